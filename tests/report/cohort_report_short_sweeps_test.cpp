// The cohort report says whose lowering sweep stopped before the grid's end (the leg ran out:
// the knee unit's COM would pass the ankle, or the shank its least length), and where; a
// cohort whose every sweep reaches the grid's end says nothing of it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "report/cohort_report.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// Two participants on a grid to 50 mm: A swept to its end, B stopped at 25 mm.
struct TwoParticipants {
  Cohort cohort;
  std::vector<CohortParticipantResult> results;
  CohortSummary summary;

  TwoParticipants() {
    cohort.study.name = "tiny";
    cohort.study.loweringStep = 0.025;
    cohort.study.loweringMax = 0.05;
    cohort.templatePath = "participants/p1.yaml";
    cohort.count = 2;
    for (std::size_t k = 0; k < cohortProperties().size(); ++k) {
      CohortDistribution d;
      d.min = 1;
      d.max = 2;
      d.source = "source";
      cohort.distributions.push_back(d);
    }
    for (const char* name : {"A", "B"}) {
      Participant p;
      p.name = name;
      p.bodyMass = 70;
      cohort.study.participants.push_back(p);
      cohort.values.push_back(std::vector<double>(cohortProperties().size(), 1.25));
      CohortParticipantResult r;
      r.ran = r.calibrated = true;
      r.timeScale = 1.1;
      r.sweep.lowerings = {0, 0.025, 0.05};
      r.sweep.swingTimes = {0.45, 0.44, 0.43};
      r.sweep.best = 2;
      results.push_back(r);
    }
    summary.participants = summary.calibrated = 2;
    summary.fastestLowering = {0.05, 0.025};
    summary.timeGained = {0.02, 0.01};
  }
  std::string reportMd() const {
    for (const auto& [name, text] : makeCohortReport(cohort, results, summary))
      if (name == "report.md") return text;
    return "";
  }
};

TEST(CohortReportShortSweeps, ASweepThatStopsBeforeTheGridsEndIsNamedWithWhere) {
  TwoParticipants t;
  EXPECT_THAT(t.reportMd(), Not(HasSubstr("sweeps stop before")));
  t.results[1].sweep.lowerings = {0, 0.025};
  t.results[1].sweep.swingTimes = {0.45, 0.44};
  t.results[1].sweep.best = 1;
  EXPECT_THAT(t.reportMd(), HasSubstr("1 participant's sweep stops before 50 mm, where their leg runs out (the knee "
                                      "unit's centre of mass would pass the ankle, or the shank its least length): B "
                                      "at 25 mm.\n"));
  t.results[0].sweep.lowerings = {0};
  t.results[0].sweep.swingTimes = {0.45};
  t.results[0].sweep.best = 0;
  EXPECT_THAT(t.reportMd(),
              HasSubstr("2 participants' sweeps stop before 50 mm, where their leg runs out (the knee "
                        "unit's centre of mass would pass the ankle, or the shank its least length): A at "
                        "0 mm, B at 25 mm.\n"));
}

}  // namespace
}  // namespace swingsim
