#include "knee/damping_table.h"
#include "core/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace swingsim {
namespace {

constexpr double kDeg = kDegToRad;
// Interpolation and the speed rule are a few floating-point operations.
constexpr double kRoundOff = 1e-12;

DampingTableParams makeParams(DampingSpeedRule rule) {
  DampingTableParams p;
  p.flexion = {0, 30 * kDeg, 70 * kDeg};
  p.moment = {1.0, 1.6, 4.5};
  p.referenceRate = 150 * kDeg;
  p.speedRule = rule;
  return p;
}

TEST(DampingTable, PassesThroughTheSamplesAndHoldsOutsideTheTable) {
  DampingTable table(makeParams(DampingSpeedRule::kLinear));
  EXPECT_NEAR(table.calcTableMoment(0), 1.0, kRoundOff);
  EXPECT_NEAR(table.calcTableMoment(30 * kDeg), 1.6, kRoundOff);
  EXPECT_NEAR(table.calcTableMoment(70 * kDeg), 4.5, kRoundOff);
  EXPECT_NEAR(table.calcTableMoment(-5 * kDeg), 1.0, kRoundOff);
  EXPECT_NEAR(table.calcTableMoment(90 * kDeg), 4.5, kRoundOff);
  // Between samples, worked by hand. The slope at 30 deg is PCHIP's (Fritsch & Butland
  // 1984): secants 0.02 and 0.0725 N m/deg over intervals of 30 and 40 deg, weights
  // w1 = 2*40 + 30 = 110 and w2 = 40 + 2*30 = 100, slope 210 / (110/0.02 + 100/0.0725)
  // = 29/950 N m/deg (0.0305); the ends are flat. At an interval's midpoint the cubic
  // Hermite is (y0 + y1)/2 + h (m0 - m1)/8.
  constexpr double m30 = 29.0 / 950;                                              // N m per deg
  EXPECT_NEAR(table.calcTableMoment(15 * kDeg), 1.3 - 30 * m30 / 8, kRoundOff);   // 1.18553
  EXPECT_NEAR(table.calcTableMoment(50 * kDeg), 3.05 + 40 * m30 / 8, kRoundOff);  // 3.20263
}

TEST(DampingTable, IsMonotoneBetweenMonotoneSamplesAndHasNoKinks) {
  DampingTable table(makeParams(DampingSpeedRule::kLinear));
  constexpr double kStep = 0.01 * kDeg;
  double previous = table.calcTableMoment(-1 * kDeg);
  for (double x = -1 * kDeg; x <= 71 * kDeg; x += kStep) {
    const double m = table.calcTableMoment(x);
    EXPECT_GE(m, previous - kRoundOff) << x / kDeg;  // rising data, rising curve: no overshoot
    previous = m;
  }
  // C1 at every sample (and into the held ends): one-sided slopes agree. A linear table
  // has slope jumps of 0.05 N m/deg here.
  constexpr double kH = 1e-6;                // rad
  constexpr double kSlopeTol = 1e-3 / kDeg;  // N m/rad, vs jumps of order 3 N m/rad
  for (double knot : {0.0, 30 * kDeg, 70 * kDeg}) {
    const double left = (table.calcTableMoment(knot) - table.calcTableMoment(knot - kH)) / kH;
    const double right = (table.calcTableMoment(knot + kH) - table.calcTableMoment(knot)) / kH;
    EXPECT_NEAR(left, right, kSlopeTol) << knot / kDeg;
  }
}

TEST(DampingTable, ResistsMotionInBothDirections) {
  for (auto rule : {DampingSpeedRule::kLinear, DampingSpeedRule::kConstant}) {
    DampingTable table(makeParams(rule));
    for (double flexion : {-2 * kDeg, 10 * kDeg, 45 * kDeg, 80 * kDeg}) {
      EXPECT_LT(table.calcMoment({flexion, 2.0}, nullptr), 0) << "flexing must be resisted";
      EXPECT_GT(table.calcMoment({flexion, -2.0}, nullptr), 0) << "extending must be resisted";
      EXPECT_EQ(table.calcMoment({flexion, 0.0}, nullptr), 0) << "no moment at rest";
    }
  }
}

TEST(DampingTable, LinearSpeedRuleScalesWithRateAndMatchesTheTableAtTheReferenceSpeed) {
  DampingTable table(makeParams(DampingSpeedRule::kLinear));
  const double rate = 150 * kDeg;
  EXPECT_NEAR(table.calcMoment({30 * kDeg, rate}, nullptr), -1.6, kRoundOff);
  EXPECT_NEAR(table.calcMoment({30 * kDeg, 0.5 * rate}, nullptr), -0.8, kRoundOff);
  EXPECT_NEAR(table.calcMoment({30 * kDeg, 3 * rate}, nullptr), -4.8, kRoundOff);
}

TEST(DampingTable, ConstantSpeedRuleSaturatesAndIsSmoothThroughZero) {
  DampingTableParams p = makeParams(DampingSpeedRule::kConstant);
  p.smoothingRate = 0.5;
  DampingTable table(p);
  // Far above the smoothing rate the magnitude is the table value, whatever the speed.
  constexpr double kSaturated = 1e-6;  // 1 - tanh(20 / 0.5)
  EXPECT_NEAR(table.calcMoment({30 * kDeg, 20.0}, nullptr), -1.6, kSaturated);
  EXPECT_NEAR(table.calcMoment({30 * kDeg, 40.0}, nullptr), -1.6, kSaturated);
  // Smooth: tanh slope at zero = table / smoothingRate.
  const double dr = 1e-6;
  EXPECT_NEAR(table.calcMoment({30 * kDeg, dr}, nullptr) / dr, -1.6 / 0.5, 1e-5);
}

TEST(DampingTable, ExtensionFactorScalesOnlyExtension) {
  DampingTableParams p = makeParams(DampingSpeedRule::kLinear);
  p.extensionFactor = 0.5;
  DampingTable table(p);
  const double rate = 150 * kDeg;
  EXPECT_NEAR(table.calcMoment({30 * kDeg, rate}, nullptr), -1.6, kRoundOff);
  EXPECT_NEAR(table.calcMoment({30 * kDeg, -rate}, nullptr), 0.8, kRoundOff);
}

TEST(DampingTable, RejectsBadParameters) {
  DampingTableParams p = makeParams(DampingSpeedRule::kLinear);
  p.flexion = {0, 0, 1};
  EXPECT_THROW(DampingTable{p}, std::invalid_argument);
  p = makeParams(DampingSpeedRule::kLinear);
  p.moment[1] = -1;
  EXPECT_THROW(DampingTable{p}, std::invalid_argument);
  p = makeParams(DampingSpeedRule::kLinear);
  p.moment.pop_back();
  EXPECT_THROW(DampingTable{p}, std::invalid_argument);
  p = makeParams(DampingSpeedRule::kLinear);
  p.referenceRate = 0;
  EXPECT_THROW(DampingTable{p}, std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
