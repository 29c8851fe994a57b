// The jumps of the swing time along the lowering (sweep/swing_time_jumps.h), on a
// hand-written piecewise function of the lowering whose jumps are known exactly: a jump is
// narrowed to its lowering, named by its cause, and a change of bounce count without a jump
// in the swing time is no jump.
#include "sweep/swing_time_jumps.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/units.h"
#include "sweep/sweep_symmetry.h"

namespace swingsim {
namespace {

constexpr double kZone = 6 * kDegToRad;
constexpr double kJumpAt = 0.1655;  // m, where the hand-written knee stops rebounding past the zone

// A knee that rebounds past the zone below kJumpAt (one bounce, a whole 130 ms excursion more)
// and stays inside above it; the rest of the swing time falls by 0.5 s/m with the lowering.
std::optional<PieceSample> reboundingKnee(double lowering) {
  PieceSample s;
  s.lowering = lowering;
  s.firstZoneEntry = 0.40 - 0.5 * lowering;
  s.bounces = lowering < kJumpAt ? 1 : 0;
  s.swingTime = *s.firstZoneEntry + (s.bounces ? 0.13 : 0.0);
  if (s.bounces) s.bounceHeight = kZone + (kJumpAt - lowering) * 10 * kDegToRad;  // 0.1 deg past at 10 mm
  return s;
}

std::vector<PieceSample> grid(const PieceSampler& f) {
  std::vector<PieceSample> out;
  for (int k = 0; k <= 20; ++k) out.push_back(*f(0.01 * k));
  return out;
}

TEST(SwingTimeJumps, AJumpIsNarrowedToItsLoweringAndNamedByItsCause) {
  int swings = 0;
  const PieceSampler counted = [&](double d) {
    ++swings;
    return reboundingKnee(d);
  };
  const std::vector<SwingTimeJump> jumps = findSwingTimeJumps(grid(reboundingKnee), counted, kZone);
  ASSERT_EQ(jumps.size(), 1u);
  const SwingTimeJump& j = jumps[0];
  EXPECT_LE(j.above.lowering - j.below.lowering, kJumpBracket);
  EXPECT_LT(j.below.lowering, kJumpAt);
  EXPECT_GE(j.above.lowering, kJumpAt);
  EXPECT_NEAR(j.calcLowering(), kJumpAt, kJumpBracket);
  EXPECT_NEAR(j.below.swingTime - j.above.swingTime, 0.13, 0.001);
  // The continuous companion barely moves across the bracket.
  EXPECT_NEAR(*j.below.firstZoneEntry, *j.above.firstZoneEntry, kJumpBracket);
  // At the narrowed edge the rebound passes the zone by at most 10 deg/m x 0.1 mm = 0.001 deg.
  double past = 0;
  ASSERT_EQ(std::sscanf(j.describeCause().c_str(), "a rebound %lf deg past the zone", &past), 1) << j.describeCause();
  EXPECT_GT(past, 0);
  EXPECT_LE(past, 0.001);
  EXPECT_NE(j.describe().find("the swing jumps from 0.447 s to 0.317 s at 0.165"), std::string::npos) << j.describe();
  // 10 mm down to 0.1 mm: 7 halvings.
  EXPECT_EQ(swings, 7);
}

TEST(SwingTimeJumps, ABounceCountChangeWithoutAJumpInTheSwingTimeIsNoJump) {
  // A bounce before the thigh reaches its target does not move the swing end.
  const PieceSampler f = [](double d) {
    std::optional<PieceSample> s = reboundingKnee(d);
    s->swingTime = *s->firstZoneEntry;
    return s;
  };
  EXPECT_TRUE(findSwingTimeJumps(grid(f), f, kZone).empty());
}

TEST(SwingTimeJumps, OneMoreBounceIsNamedSo) {
  const PieceSampler f = [](double d) {
    std::optional<PieceSample> s = reboundingKnee(d);
    s->bounces += 1;
    return s;
  };
  const std::vector<SwingTimeJump> jumps = findSwingTimeJumps(grid(f), f, kZone);
  ASSERT_EQ(jumps.size(), 1u);
  EXPECT_EQ(jumps[0].describeCause(), "one more bounce (2 against 1)");
}

TEST(SwingTimeJumps, ASwingThatDoesNotEndStopsTheBisectionWhereItIs) {
  const PieceSampler failing = [](double) { return std::optional<PieceSample>(); };
  const std::vector<SwingTimeJump> jumps = findSwingTimeJumps(grid(reboundingKnee), failing, kZone);
  ASSERT_EQ(jumps.size(), 1u);
  EXPECT_DOUBLE_EQ(jumps[0].below.lowering, 0.16);
  EXPECT_DOUBLE_EQ(jumps[0].above.lowering, 0.17);
}

TEST(SwingTimeJumps, PiecesCountTheJumpsBelowALowering) {
  const std::vector<SwingTimeJump> jumps = findSwingTimeJumps(grid(reboundingKnee), reboundingKnee, kZone);
  EXPECT_EQ(calcPieceIndex(jumps, 0.10), 0);
  EXPECT_EQ(calcPieceIndex(jumps, 0.17), 1);
  EXPECT_NE(findJumpBetween(jumps, 0.17, 0.16), nullptr);
  EXPECT_EQ(findJumpBetween(jumps, 0.15, 0.16), nullptr);
}

}  // namespace
}  // namespace swingsim

namespace swingsim {
namespace {

// The thigh's half of the swing-end rule: above kThighJumpAt the thigh's flexion peaks just
// short of its target and reaches it 0.1 s later; the bounce count is the same throughout.
constexpr double kThighJumpAt = 0.1829;

std::optional<PieceSample> grazingThigh(double lowering) {
  PieceSample s;
  s.lowering = lowering;
  s.firstZoneEntry = 0.38 - 0.05 * lowering;
  s.thighAtTarget = lowering < kThighJumpAt ? 0.32 : 0.42;
  s.swingTime = std::max(*s.firstZoneEntry, *s.thighAtTarget + 0.02);
  return s;
}

TEST(SwingTimeJumps, AJumpThatKeepsTheBounceCountIsFoundByItsSizeAndNamedByTheThigh) {
  std::vector<PieceSample> grid;
  for (int k = 0; k <= 20; ++k) grid.push_back(*grazingThigh(0.01 * k));
  const std::vector<SwingTimeJump> jumps = findSwingTimeJumps(grid, grazingThigh, kZone);
  ASSERT_EQ(jumps.size(), 1u);
  EXPECT_NEAR(jumps[0].calcLowering(), kThighJumpAt, kJumpBracket);
  EXPECT_EQ(jumps[0].describeCause(),
            "the thigh's flexion grazing its target: it reaches it 0.100 s later on one side");
}

TEST(SwingTimeJumps, ASteepButContinuousStepIsNoJump) {
  // 30 ms over one 10 mm step (ten times the others), linear inside it: bisected, then dropped.
  const PieceSampler steep = [](double d) {
    PieceSample s;
    s.lowering = d;
    s.swingTime = 0.5 - 0.3 * d - (d > 0.10 ? 3.0 * (std::min(d, 0.11) - 0.10) : 0.0);
    return std::optional<PieceSample>(s);
  };
  std::vector<PieceSample> grid;
  for (int k = 0; k <= 20; ++k) grid.push_back(*steep(0.01 * k));
  EXPECT_TRUE(findSwingTimeJumps(grid, steep, kZone).empty());
}

// A curve known only on its grid (an uncertainty sample): a step beyond 3x the median step
// (at least 5 ms) starts a new piece; a swing that did not end (NaN) splits nothing; and the
// symmetry lowering of such a sample is not read across that step.
TEST(SwingTimeJumps, ScreenedPiecesSplitAGridCurveAtAStepBeyondTheScreen) {
  const double nan = std::nan("");
  EXPECT_EQ(calcScreenedPieces({0.50, 0.49, 0.48, 0.40, 0.39}), (std::vector<int>{0, 0, 0, 1, 1}));
  EXPECT_EQ(calcScreenedPieces({0.50, 0.496, 0.492, 0.488}), (std::vector<int>{0, 0, 0, 0}));  // below the 5 ms floor
  EXPECT_EQ(calcScreenedPieces({0.50, nan, 0.48, 0.47, 0.46}), (std::vector<int>{0, 0, 0, 0, 0}));
  const std::vector<double> lowerings{0, 0.01, 0.02, 0.03, 0.04};
  const std::vector<double> times{0.50, 0.49, 0.48, 0.40, 0.39};
  const SymmetryLowering across = calcSymmetryLowering(lowerings, times, 0.45, calcScreenedPieces(times));
  EXPECT_FALSE(across.reached);
  EXPECT_TRUE(across.acrossJump);
  EXPECT_DOUBLE_EQ(across.jumpFrom, 0.02);
  const SymmetryLowering inside = calcSymmetryLowering(lowerings, times, 0.485, calcScreenedPieces(times));
  EXPECT_TRUE(inside.reached);
  EXPECT_NEAR(inside.lowering, 0.015, 1e-12);
}

}  // namespace
}  // namespace swingsim
