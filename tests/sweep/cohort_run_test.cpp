// The cohort summary on results made up here: a gain that grows with one property puts that
// property first with rho = 1; the time gained is the standard-location time minus the
// fastest; participants not calibrated are left out of the intervals and correlations.
#include "sweep/cohort_run.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace swingsim {
namespace {

constexpr double kRound = 1e-12;  // differences of given numbers: rounding only

Cohort makeCohort(int count) {
  Cohort c;
  c.count = count;
  c.seed = 11;
  for (const auto& p : cohortProperties()) {
    CohortDistribution d;
    d.min = p.physicalMin + 0.3 * (p.physicalMax - p.physicalMin);
    d.max = p.physicalMin + 0.4 * (p.physicalMax - p.physicalMin);
    d.source = "test";
    c.distributions.push_back(d);
  }
  Participant templ;
  templ.name = "template";
  drawCohortParticipants(c, templ);
  return c;
}

TEST(CohortRun, GainFollowingOnePropertyRanksItFirstWithRhoOne) {
  const Cohort c = makeCohort(30);
  const std::size_t residual = findCohortProperty("residual_limb_fraction");
  std::vector<CohortParticipantResult> results(30);
  for (std::size_t i = 0; i < results.size(); ++i) {
    auto& r = results[i];
    r.ran = r.calibrated = true;
    r.timeScale = 1.0;
    r.sweep.lowerings = {0.0, 0.01, 0.02};
    // Fastest at 0.01 m, faster by 0.02 x the residual-limb fraction (a strictly increasing gain).
    const double gain = 0.02 * c.values[i][residual];
    r.sweep.swingTimes = {0.45, 0.45 - gain, 0.45 - 0.5 * gain};
    pickBest(r.sweep);
  }
  results[3].calibrated = false;  // left out: no sweep
  results[3].sweep = {};
  results[3].timeScale = std::nan("");

  const CohortSummary s = summarizeCohort(c, results);
  EXPECT_EQ(s.participants, 30);
  EXPECT_EQ(s.calibrated, 29);
  EXPECT_NEAR(s.timeGained[0], 0.02 * c.values[0][residual], kRound);
  EXPECT_TRUE(std::isnan(s.timeGained[3]));
  EXPECT_EQ(s.fastestLoweringInterval.count, 29);
  EXPECT_NEAR(s.fastestLoweringInterval.median, 0.01, kRound);
  ASSERT_FALSE(s.predictors.empty());
  EXPECT_EQ(s.predictors.front().key, "residual_limb_fraction");
  EXPECT_NEAR(s.predictors.front().withGain.rho, 1.0, kRound);
  EXPECT_EQ(s.predictors.front().withGain.count, 29);
  // Every drawn property and the six derived ones are there, each once.
  EXPECT_EQ(s.predictors.size(), cohortProperties().size() + 6);
}

TEST(CohortRun, TargetIsTheDrawnSwingTime) {
  const Cohort c = makeCohort(5);
  const std::size_t k = findCohortProperty("swing_time_s");
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(c.targetSwingTime(i), c.values[i][k]);
  EXPECT_EQ(c.study.participants[4].name, "C005");
}

}  // namespace
}  // namespace swingsim
