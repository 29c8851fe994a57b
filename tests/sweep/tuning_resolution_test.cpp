// Tuned settings at the knobs' resolution (sweep/tuning_resolution.h), on a hand-written swing
// whose peak flexion and swing time are planes in the knobs: the rounding neighbours of an
// optimum on a hard limit's edge, the move one step inside, the "cannot", a jump inside the
// cell, and the tolerance bands, each worked out by hand.
#include "sweep/tuning_resolution.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/units.h"

namespace swingsim {
namespace {

// Knob 0: a lowering (m, step 1 mm); knob 1: an equilibrium angle (deg, step 1 deg).
std::vector<TuningKnob> knobs() {
  return {{"lowering_m", 0.0, 0.05, false, 0.001}, {"equilibrium_deg", 30, 80, false, 1.0}};
}

// Peak flexion 40 deg + 1000 deg/m x lowering + 1 x equilibrium; swing time 0.5 s - 2 s/m x
// lowering - 0.001 s/deg x equilibrium.
SwingResult plane(const std::vector<double>& x) {
  SwingResult r;
  r.peakKneeFlexion = KneePeak{(40 + 1000 * x[0] + x[1]) * kDegToRad, 0.2};
  r.swingTime = 0.5 - 2 * x[0] - 0.001 * x[1];
  r.minToeClearance = 0.1;
  return r;
}

TuningTarget peakAtMost90() {
  return {TuningQuantity::kPeakKneeFlexion,
          60 * kDegToRad,
          90 * kDegToRad,
          true,
          1,
          tuningTargetScale(TuningQuantity::kPeakKneeFlexion)};
}

TuningPoint pointAt(const std::vector<double>& x, const std::vector<TuningTarget>& targets) {
  TuningPoint p;
  p.knobs = x;
  scoreTuningPoint(p, plane(x), targets);
  return p;
}

TEST(TuningResolution, DefaultsFollowTheKeysUnit) {
  EXPECT_DOUBLE_EQ(*findDefaultKnobResolution("lowering_m"), 0.001);
  EXPECT_DOUBLE_EQ(*findDefaultKnobResolution("impedance_state_machine.states[0].equilibrium_deg"), 1.0);
  EXPECT_DOUBLE_EQ(*findDefaultKnobResolution("impedance_state_machine.states[0].stiffness_Nm_per_rad"), 1.0);
  EXPECT_DOUBLE_EQ(*findDefaultKnobResolution("impedance_state_machine.states[1].damping_Nm_s_per_rad"), 0.1);
  EXPECT_DOUBLE_EQ(*findDefaultKnobResolution("knee_effects.model_scale"), 0.01);
  EXPECT_DOUBLE_EQ(*findDefaultKnobResolution("added_mass_kg"), 0.01);
  // A rate per metre is not a length; a list entry's unit is not told by its key.
  EXPECT_FALSE(findDefaultKnobResolution("settings[0].coefficients[1].c_Ns_per_m"));
  EXPECT_FALSE(findDefaultKnobResolution("damping_table.moment_Nm[3]"));
}

TEST(TuningResolution, RoundingStaysOnTheGridInsideTheRange) {
  const TuningKnob k{"x_deg", 30.4, 80, false, 1.0};
  EXPECT_DOUBLE_EQ(roundToKnobGrid(k, 30.45), 31.0);  // 30 lies outside the range
  EXPECT_DOUBLE_EQ(roundToKnobGrid(k, 41.6), 42.0);
  EXPECT_DOUBLE_EQ(roundToKnobGrid({"lowering_m", 0, 0.15, false, 0.001}, 0.021748686179741055), 0.022);
}

TEST(TuningResolution, AnOptimumInsideTheLimitsHoldsAtEveryRoundingNeighbour) {
  const std::vector<TuningTarget> targets = {peakAtMost90()};
  // Peak 40 + 10.4 + 35.3 = 85.7 deg; the corners of its cell (0.010-0.011 m x 35-36 deg) peak
  // at 85 to 87 deg.
  const TuningPoint optimum = pointAt({0.0104, 35.3}, targets);
  const ResolutionCheck c = checkTuningResolution(knobs(), targets, plane, optimum, 0.010, 1);
  ASSERT_TRUE(c.ran);
  EXPECT_TRUE(c.holds) << c.verdict;
  EXPECT_EQ(c.corners.size(), 4u);
  EXPECT_EQ(c.cellsTried, 1);
  for (const TuningPoint& p : c.corners) EXPECT_TRUE(p.feasible());
  // On the grid.
  EXPECT_NEAR(c.result.knobs[0] * 1000, std::round(c.result.knobs[0] * 1000), 1e-9);
  EXPECT_NEAR(c.result.knobs[1], std::round(c.result.knobs[1]), 1e-12);
}

TEST(TuningResolution, AnOptimumOnALimitsEdgeMovesOneStepInside) {
  const std::vector<TuningTarget> targets = {peakAtMost90()};
  // Peak 40 + 11.7 + 38.29 = 89.99 deg, as P1's microprocessor tune. The corners of its cell
  // (0.011-0.012 m x 38-39 deg) peak at 89, 90, 90 and 91 deg: (0.012, 39) breaks the limit.
  const TuningPoint optimum = pointAt({0.0117, 38.29}, targets);
  ASSERT_TRUE(optimum.feasible());
  const ResolutionCheck c = checkTuningResolution(knobs(), targets, plane, optimum, 0.010, 1);
  ASSERT_TRUE(c.ran);
  EXPECT_TRUE(c.holds) << c.verdict;
  EXPECT_NE(c.verdict.find("moved 1 step inside"), std::string::npos) << c.verdict;
  EXPECT_NE(c.verdict.find("peak_knee_flexion_deg 91"), std::string::npos) << c.verdict;
  for (const TuningPoint& p : c.corners) EXPECT_TRUE(p.feasible()) << p.peakKneeFlexion * kRadToDeg;
  EXPECT_TRUE(c.result.feasible());
}

TEST(TuningResolution, NoCellThatHoldsIsSaid) {
  // A window 1 deg wide around 89.99 deg: no cell of 1 mm x 1 deg (corners 2 deg apart) fits.
  TuningTarget narrow = peakAtMost90();
  narrow.lower = 89.5 * kDegToRad;
  const std::vector<TuningTarget> targets = {narrow};
  const ResolutionCheck c = checkTuningResolution(knobs(), targets, plane, pointAt({0.0117, 38.29}, targets), 0.010, 1);
  ASSERT_TRUE(c.ran);
  EXPECT_FALSE(c.holds);
  EXPECT_EQ(c.verdict.rfind("cannot", 0), 0u) << c.verdict;
  EXPECT_TRUE(c.bands.empty());
}

TEST(TuningResolution, ACellWithAJumpInsideIsNotAResult) {
  const std::vector<TuningTarget> targets = {peakAtMost90()};
  // The knee rebounds past the zone for lowerings from 11 mm: the swing is 0.1 s longer there.
  const TuningEvaluator jumping = [](const std::vector<double>& x) {
    SwingResult r = plane(x);
    if (x[0] > 0.0105) {
      r.bounces = 1;
      r.swingTime += 0.1;
    }
    return r;
  };
  TuningPoint optimum;
  optimum.knobs = {0.0104, 35.3};
  scoreTuningPoint(optimum, jumping(optimum.knobs), targets);
  const ResolutionCheck c = checkTuningResolution(knobs(), targets, jumping, optimum, 0.010, 1);
  EXPECT_TRUE(c.holds) << c.verdict;
  EXPECT_NE(c.verdict.find("jumps inside it"), std::string::npos) << c.verdict;
  for (const TuningPoint& p : c.corners) EXPECT_EQ(p.bounces, c.corners.front().bounces);
}

TEST(TuningResolution, TheBandsStopAtTheLimitTheWindowAndTheRangeEnd) {
  const std::vector<TuningTarget> targets = {peakAtMost90()};
  // A window of 11 ms (not 10: a step that lands on the window's edge would hang on round-off).
  const ResolutionCheck c = checkTuningResolution(knobs(), targets, plane, pointAt({0.0104, 35.3}, targets), 0.011, 1);
  ASSERT_TRUE(c.holds);
  // Every corner costs 0 (no soft target): the first, (0.010 m, 35 deg), peak 85 deg.
  ASSERT_DOUBLE_EQ(c.result.knobs[0], 0.010);
  ASSERT_DOUBLE_EQ(c.result.knobs[1], 35.0);
  ASSERT_EQ(c.bands.size(), 2u);
  // Lowering: 2 ms and 1 deg per mm. Down: 5 mm (10 ms; 6 mm would be 12 ms). Up: 5 mm to 90
  // deg (6 mm would be 91 deg).
  EXPECT_DOUBLE_EQ(c.bands[0].low, 0.005);
  EXPECT_EQ(c.bands[0].lowStop, "swing time +12 ms");
  EXPECT_DOUBLE_EQ(c.bands[0].high, 0.015);
  EXPECT_EQ(c.bands[0].highStop.rfind("peak_knee_flexion_deg 91", 0), 0u) << c.bands[0].highStop;
  // Equilibrium: 1 ms and 1 deg per deg. Down: the range end at 30 deg first. Up: 5 deg to 90.
  EXPECT_DOUBLE_EQ(c.bands[1].low, 30.0);
  EXPECT_EQ(c.bands[1].lowStop, "range end");
  EXPECT_DOUBLE_EQ(c.bands[1].high, 40.0);
}

TEST(TuningResolution, KnobsWithoutAResolutionAreLeftAsTheyAre) {
  std::vector<TuningKnob> continuous = knobs();
  for (TuningKnob& k : continuous) k.resolution = 0;
  const std::vector<TuningTarget> targets = {peakAtMost90()};
  EXPECT_FALSE(checkTuningResolution(continuous, targets, plane, pointAt({0.0104, 35.3}, targets), 0.010, 1).ran);
}

}  // namespace
}  // namespace swingsim
