// The symmetry lowering (sweep/sweep_symmetry.h): a crossing interpolated between grid
// points, the closest point with its gap when there is none, and its interval over the
// uncertainty samples; each answer worked out by hand from the synthetic curve.
#include "sweep/sweep_symmetry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "study/sweep_study.h"
#include "sweep/sweep.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;
const double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kRounding = 1e-12;  // s or m: the hand answers are exact up to double rounding

const std::vector<double> kGrid = {0.00, 0.01, 0.02, 0.03};
const std::vector<double> kTimes = {0.50, 0.46, 0.42, 0.40};  // s, falling with the lowering

TEST(SweepSymmetry, CrossingIsInterpolatedBetweenTheGridPointsAroundIt) {
  // 0.43 s lies between 0.46 s (0.01 m, gap +0.03) and 0.42 s (0.02 m, gap -0.01):
  // 0.01 + 0.01 * 0.03 / 0.04 = 0.0175 m.
  const SymmetryLowering s = calcSymmetryLowering(kGrid, kTimes, 0.43);
  ASSERT_TRUE(s.given && s.found);
  EXPECT_TRUE(s.reached);
  EXPECT_NEAR(s.lowering, 0.0175, kRounding);
  EXPECT_DOUBLE_EQ(s.prostheticTime, 0.43);
  EXPECT_DOUBLE_EQ(s.gap, 0.0);
  EXPECT_DOUBLE_EQ(s.calcRatio(), 1.0);
}

TEST(SweepSymmetry, NoCrossingIsInterpolatedAcrossAJumpBetweenPieces) {
  // The same curve with a jump between 0.01 m and 0.02 m (pieces 0 and 1): 0.43 s lies in the
  // jump, so no lowering gives it; the closest point is 0.02 m (0.42 s, 10 ms faster).
  const SymmetryLowering s = calcSymmetryLowering(kGrid, kTimes, 0.43, {0, 0, 1, 1});
  ASSERT_TRUE(s.given && s.found);
  EXPECT_FALSE(s.reached);
  EXPECT_TRUE(s.acrossJump);
  EXPECT_DOUBLE_EQ(s.jumpFrom, 0.01);
  EXPECT_DOUBLE_EQ(s.jumpTo, 0.02);
  EXPECT_DOUBLE_EQ(s.lowering, 0.02);
  EXPECT_NEAR(s.gap, -0.01, kRounding);
}

TEST(SweepSymmetry, ACrossingInsideAPieceBeyondAJumpIsStillReached) {
  // Times 0.50, 0.46 | 0.38, 0.48 with the jump between 0.01 and 0.02 m: 0.43 s is jumped over
  // first, then crossed inside the second piece at 0.02 + 0.01 * 0.05 / 0.10 = 0.025 m.
  const SymmetryLowering s = calcSymmetryLowering(kGrid, {0.50, 0.46, 0.38, 0.48}, 0.43, {0, 0, 1, 1});
  EXPECT_TRUE(s.reached);
  EXPECT_NEAR(s.lowering, 0.025, kRounding);
  EXPECT_TRUE(s.acrossJump);
  EXPECT_DOUBLE_EQ(s.jumpFrom, 0.01);
}

TEST(SweepSymmetry, ExactGridHitIsThatLowering) {
  const SymmetryLowering s = calcSymmetryLowering(kGrid, kTimes, 0.42);
  EXPECT_TRUE(s.reached);
  EXPECT_DOUBLE_EQ(s.lowering, 0.02);
}

TEST(SweepSymmetry, SoundLimbFasterThanEveryLoweringIsTheClosestPointNotReached) {
  // Every lowering is slower than 0.30 s; the closest is the fastest, 0.40 s at 0.03 m.
  const SymmetryLowering s = calcSymmetryLowering(kGrid, kTimes, 0.30);
  ASSERT_TRUE(s.found);
  EXPECT_FALSE(s.reached);
  EXPECT_DOUBLE_EQ(s.lowering, 0.03);
  EXPECT_DOUBLE_EQ(s.prostheticTime, 0.40);
  EXPECT_NEAR(s.gap, 0.10, kRounding);
  EXPECT_NEAR(s.calcRatio(), 0.40 / 0.30, kRounding);
}

TEST(SweepSymmetry, SoundLimbSlowerThanEveryLoweringGivesANegativeGap) {
  const SymmetryLowering s = calcSymmetryLowering(kGrid, kTimes, 0.60);
  EXPECT_FALSE(s.reached);
  EXPECT_DOUBLE_EQ(s.lowering, 0.00);
  EXPECT_NEAR(s.gap, -0.10, kRounding);
}

TEST(SweepSymmetry, FirstCrossingFromTheStandardLocation) {
  // Down, up, down: three crossings of 0.45 s; the first is halfway to 0.01 m.
  const SymmetryLowering s = calcSymmetryLowering(kGrid, {0.50, 0.40, 0.50, 0.40}, 0.45);
  EXPECT_TRUE(s.reached);
  EXPECT_NEAR(s.lowering, 0.005, kRounding);
}

TEST(SweepSymmetry, NoCrossingOverAPointWithoutASwingEnd) {
  // 0.50 s and 0.40 s straddle 0.46 s, but the point between them did not end a swing:
  // no crossing is claimed, the closest ended point (0 m, +0.04 s) is given.
  const SymmetryLowering s = calcSymmetryLowering({0.00, 0.01, 0.02}, {0.50, kNaN, 0.40}, 0.46);
  ASSERT_TRUE(s.found);
  EXPECT_FALSE(s.reached);
  EXPECT_DOUBLE_EQ(s.lowering, 0.00);
}

TEST(SweepSymmetry, WithoutASoundLimbTimeOrASwingEndNothingIsFound) {
  EXPECT_FALSE(calcSymmetryLowering(kGrid, kTimes, 0).given);
  EXPECT_FALSE(calcSymmetryLowering(kGrid, kTimes, kNaN).given);
  const SymmetryLowering none = calcSymmetryLowering(kGrid, {kNaN, kNaN, kNaN, kNaN}, 0.45);
  EXPECT_TRUE(none.given);
  EXPECT_FALSE(none.found);
}

// P1 of the shipped study on a 50 mm grid: runSweep gives the symmetry lowering of its own
// grid points against P1's sound_limb_swing_time_s.
TEST(SweepSymmetry, SweepUsesTheParticipantsSoundLimbTime) {
  SweepStudy study = loadSweepStudy(kRoot + "/studies/burkett2004.yaml");
  study.participants.resize(1);
  study.loweringStep = 0.05;
  study.includePublishedLowerings = false;
  ASSERT_TRUE(study.participants[0].soundLimbSwingTime.has_value());
  const SweepResults r = runSweep(study, 1);
  const ParticipantSweep& ps = r.participants[0];
  std::vector<double> lowerings, times;
  for (const auto& pt : ps.points) {
    lowerings.push_back(pt.lowering);
    times.push_back(pt.ok ? pt.result.swingTime : kNaN);
  }
  const SymmetryLowering expected = calcSymmetryLowering(lowerings, times, *study.participants[0].soundLimbSwingTime);
  ASSERT_TRUE(ps.symmetry.given && ps.symmetry.found);
  EXPECT_DOUBLE_EQ(ps.symmetry.soundTime, 0.499);  // Burkett Table 4, P1 anatomical at 0 m
  EXPECT_EQ(ps.symmetry.reached, expected.reached);
  EXPECT_DOUBLE_EQ(ps.symmetry.lowering, expected.lowering);

  study.participants[0].soundLimbSwingTime.reset();
  EXPECT_FALSE(runSweep(study, 1).participants[0].symmetry.given);
}

// The uncertainty analysis on made-up swing times (no swing is simulated): every run's
// curve is t = 0.50 - 0.4 d + offset (s, d in m), crossing 0.45 s at d = (0.05 + offset) / 0.4.
TEST(SweepSymmetry, UncertaintyIntervalContainsTheNominalAndCountsSamplesNotReaching) {
  SweepStudy study = loadSweepStudy(kRoot + "/studies/burkett2004.yaml");
  study.participants.resize(1);
  study.loweringStep = 0.05;
  study.includePublishedLowerings = false;
  study.participants[0].soundLimbSwingTime = 0.45;
  UncertaintyOptions options;
  options.samples = 10;
  options.sensitivity = false;
  const UncertaintyPlan plan = planSweepUncertainty(study, options);
  UncertaintySwingTimes times = UncertaintySwingTimes::makeEmpty(plan.swingCount);
  for (const auto& run : plan.runs) {
    ASSERT_GE(run.lowerings.back(), 0.15) << "the crossings need the grid to reach 0.15 m";
    // Samples 0-6 shift the curve by -12 .. +12 ms; 7 and 8 lift it 200 ms (never reaches
    // 0.45 s); 9 ends no swing.
    double offset = 0;
    if (run.kind == UncertaintyRun::Kind::kSample)
      offset = run.sample < 7 ? -0.012 + 0.004 * static_cast<double>(run.sample) : 0.2;
    const bool noEnd = run.kind == UncertaintyRun::Kind::kSample && run.sample == 9;
    for (std::size_t k = 0; k < run.lowerings.size(); ++k) {
      times.swingTimes[run.firstSwing + k] = noEnd ? kNaN : 0.50 - 0.4 * run.lowerings[k] + offset;
      times.finished[run.firstSwing + k] = 1;
    }
  }
  const ParticipantUncertainty pu = assembleUncertaintyResults(study, plan, times).participants[0];
  ASSERT_TRUE(pu.symmetry.reached);
  EXPECT_NEAR(pu.symmetry.lowering, 0.125, kRounding);
  EXPECT_EQ(pu.samplesWithoutSwingEnd, 1);
  EXPECT_EQ(pu.symmetryLowering.count, 9);  // the sample without a swing end is left out
  EXPECT_EQ(pu.symmetryNotReached, 2);
  EXPECT_LE(pu.symmetryLowering.p05, pu.symmetry.lowering);
  EXPECT_GE(pu.symmetryLowering.p95, pu.symmetry.lowering);
  // The median of 7 crossings 0.095 .. 0.155 m and two closest points at the grid's end.
  EXPECT_NEAR(pu.symmetryLowering.median, (0.05 + 0.004) / 0.4, kRounding);

  study.participants[0].soundLimbSwingTime.reset();
  const ParticipantUncertainty without = assembleUncertaintyResults(study, plan, times).participants[0];
  EXPECT_FALSE(without.symmetry.given);
  EXPECT_EQ(without.symmetryLowering.count, 0);
}

}  // namespace
}  // namespace swingsim
