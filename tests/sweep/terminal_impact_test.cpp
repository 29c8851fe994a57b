// Burkett's terminal-impact findings checked on a sweep: what the check reports must be what
// the sweeps it ran show, and the JSON carries it under the documented keys.
#include "sweep/terminal_impact.h"

#include <gtest/gtest.h>

#include <cmath>

#include "io/json_file.h"
#include "report/sweep_report.h"
#include "study/sweep_study.h"

namespace swingsim {
namespace {

SweepStudy coarseStudy() {
  SweepStudy s = loadSweepStudy("studies/burkett2004.yaml");
  s.participants = {s.participants[0], s.participants[2]};  // P1 (Tc 10 N m), P3 (Tc 5 N m)
  s.loweringStep = 0.05;
  s.addedMasses = {0.0};
  s.includePublishedLowerings = false;
  return s;
}

bool contains(const std::vector<double>& v, double x) {
  for (double d : v)
    if (std::fabs(d - x) < 1e-9) return true;
  return false;
}

TEST(TerminalImpact, FindingsAreWhatTheSweepsShow) {
  const SweepStudy study = coarseStudy();
  SweepResults results = runSweep(study, 0);
  checkTerminalImpact(study, results, 0);
  ASSERT_EQ(results.terminalImpact.size(), 2u);

  // The friction-free sweep, run here independently of the check.
  SweepStudy frictionFree = study;
  for (Participant& p : frictionFree.participants) p.kneeFriction = 0;
  const SweepResults withoutFriction = runSweep(frictionFree, 0);

  for (std::size_t i = 0; i < 2; ++i) {
    const TerminalImpactCheck& c = results.terminalImpact[i];
    EXPECT_EQ(c.participant, study.participants[i].name);
    EXPECT_EQ(c.frictionMoment, study.participants[i].kneeFriction);
    for (const auto& pt : results.participants[i].points)
      EXPECT_EQ(contains(c.bounceLowerings, pt.lowering), pt.ok && pt.result.bounce)
          << c.participant << " " << pt.lowering;
    for (const auto& pt : withoutFriction.participants[i].points)
      EXPECT_EQ(contains(c.bounceLoweringsWithoutFriction, pt.lowering), pt.ok && pt.result.bounce)
          << c.participant << " " << pt.lowering << " without friction";
    // The standard location and the largest lowering, each with its first impact booked by cause.
    ASSERT_EQ(c.tracked.size(), 2u);
    EXPECT_EQ(c.tracked[0].lowering, 0.0);
    EXPECT_EQ(c.tracked[1].lowering, results.participants[i].loweringCap);
    ASSERT_TRUE(c.tracked[0].ok) << c.tracked[0].failure;
    ASSERT_FALSE(c.tracked[0].result.impacts.empty());
    const StopImpact& im = c.tracked[0].result.impacts.front();
    EXPECT_GT(im.impactRate, 1.0);  // rad/s: a swing ends by meeting its stop
    bool stopBooked = false, frictionBooked = false;
    for (const auto& w : im.work) {
      stopBooked = stopBooked || (w.cause == "hyperextension stop" && w.work < 0);
      frictionBooked = frictionBooked || (w.cause == "knee friction" && w.work < 0);
    }
    EXPECT_TRUE(stopBooked && frictionBooked) << c.participant;
    EXPECT_FALSE(c.findings.empty());
  }
  // P1 and P3 bounce once their friction is gone (measured: at the standard location), and
  // the findings name the friction as what stops it.
  for (const auto& c : results.terminalImpact) {
    if (!c.bounceLowerings.empty()) continue;
    EXPECT_FALSE(c.bounceLoweringsWithoutFriction.empty()) << c.participant;
    bool named = false;
    for (const auto& f : c.findings)
      named = named || f.find("What stops the bounce: the knee friction") != std::string::npos;
    EXPECT_TRUE(named) << c.participant;
  }

  const Json j = Json::parse(formatSweepJson(results));
  for (const auto& p : j["participants"]) {
    ASSERT_TRUE(p.contains("terminal_impact")) << p["name"];
    const Json& t = p["terminal_impact"];
    for (const char* key :
         {"knee_friction_Nm", "bounce_lowerings_m", "interior_optimum", "without_friction", "impacts", "findings"})
      EXPECT_TRUE(t.contains(key)) << key;
    EXPECT_TRUE(t["impacts"][0]["first_stop_impact"].contains("restitution"));
    EXPECT_TRUE(p["bounces"].is_array());
  }
}

}  // namespace
}  // namespace swingsim
