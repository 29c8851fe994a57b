// The sweep report's shared pieces (report/sweep_report_parts.h): a failed point's cause in
// a few words, from its RunError message.
#include "report/sweep_report_parts.h"

#include <gtest/gtest.h>

namespace swingsim::sweep_report_parts {
namespace {

SweepPoint failedWith(const std::string& message) {
  SweepPoint pt;
  pt.ran = true;
  pt.failure = message;
  return pt;
}

TEST(SweepReportParts, ShortFailureNamesTheCause) {
  EXPECT_EQ(shortFailure(failedWith("P1 at lowering 0 m: ... the thigh never reached its target")),
            "no end: thigh short of target");
  EXPECT_EQ(shortFailure(failedWith("P1 at lowering 0 m: ... the knee never came back inside the zone")),
            "no end: knee stays flexed");
  EXPECT_EQ(shortFailure(failedWith("P1 at lowering 0 m: the knee flexion passed 180 deg at 0.0454 s, ...")),
            "failed: knee past 180 deg");
  EXPECT_EQ(shortFailure(failedWith("P1: the integrator failed")), "failed");
  EXPECT_EQ(shortFailure(SweepPoint{}), "not run (interrupted)");
}

}  // namespace
}  // namespace swingsim::sweep_report_parts
