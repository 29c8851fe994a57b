// The chance of a tuned setting meeting its hard limits over the sweep's assumption ranges
// (sweep/tuning_chance.h): the Wilson interval against its published values, the nominal draw
// against a plain simulate of the same leg, and the counts against the samples' own swings.
#include "sweep/tuning_chance.h"

#include <gtest/gtest.h>

#include <cmath>

#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "swing/knee_setup.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;

TunedLeg p1At(double lowering) {
  TunedLeg leg;
  leg.participant = loadParticipant(kRoot + "/participants/p1.yaml");
  leg.knee = loadKneeModel(leg.participant.kneeModelPath);
  leg.lowering = lowering;
  leg.options.recordTrajectory = false;
  return leg;
}

TuningTarget swingTimeWithin(double lower, double upper) {
  return {TuningQuantity::kSwingTime, lower, upper, true, 1, tuningTargetScale(TuningQuantity::kSwingTime)};
}

// The Wilson score interval's ends in closed form at the edges: 0 of n reaches
// z^2 / (n + z^2) (0.2775 for n = 10), n of n starts at n / (n + z^2) (0.8830 for n = 29);
// 5 of 10 is 0.2366-0.7634 (as tabulated by Newcombe 1998, Stat Med 17:857).
TEST(TuningChance, WilsonIntervalMatchesPublishedValues) {
  const auto [l0, h0] = calcWilsonInterval(0, 10);
  EXPECT_NEAR(l0, 0, 1e-12);
  EXPECT_NEAR(h0, 0.2775, 5e-5);
  const auto [l5, h5] = calcWilsonInterval(5, 10);
  EXPECT_NEAR(l5, 0.2366, 5e-5);
  EXPECT_NEAR(h5, 0.7634, 5e-5);
  const auto [l29, h29] = calcWilsonInterval(29, 29);
  EXPECT_NEAR(l29, 0.8830, 5e-5);
  EXPECT_NEAR(h29, 1, 1e-12);
}

// The nominal draw is the tuned swing itself; a window around the nominal time that every
// sample meets gives 100 %, one that none meets 0 % with every sample counted as a miss, and a
// window cut at the nominal time splits the samples as their own swing times do.
TEST(TuningChance, CountsTheSamplesThatMeetEveryHardLimit) {
  const TunedLeg leg = p1At(0.02);
  const double nominal =
      simulateSwing(makeSwingSetup(leg.participant, leg.knee, leg.lowering, leg.added), leg.options).swingTime;
  const TuningChanceOptions options{12, 7};
  const TuningChance wide = calcTuningChance(leg, {swingTimeWithin(0.1, 2.0)}, options, 2);
  ASSERT_TRUE(wide.ran);
  EXPECT_NEAR(wide.nominalSwingTime, nominal, 1e-12);
  EXPECT_EQ(wide.met + wide.failed, 12);
  EXPECT_EQ(wide.misses.at(0), 0);
  EXPECT_NE(wide.verdict.find("of 12 samples"), std::string::npos) << wide.verdict;

  const TuningChance none = calcTuningChance(leg, {swingTimeWithin(5.0, 6.0)}, options, 2);
  ASSERT_TRUE(none.ran);
  EXPECT_EQ(none.met, 0);
  EXPECT_EQ(none.misses.at(0), 12 - none.failed);
  EXPECT_NE(none.verdict.find("missed most: swing_time_s"), std::string::npos) << none.verdict;

  // Below the nominal time: the samples that swing faster than the tuned leg.
  const TuningChance below = calcTuningChance(leg, {swingTimeWithin(0.1, nominal)}, options, 1);
  ASSERT_TRUE(below.ran);
  EXPECT_GT(below.met, 0) << below.verdict;  // the assumptions move the time both ways
  EXPECT_LT(below.met, 12) << below.verdict;
  EXPECT_EQ(below.met + below.misses.at(0) + below.failed, 12);
  EXPECT_LE(below.low, below.chance());
  EXPECT_GE(below.high, below.chance());
}

}  // namespace
}  // namespace swingsim
