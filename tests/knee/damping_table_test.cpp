#include "knee/damping_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace swingsim {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
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

TEST(DampingTable, InterpolatesLinearlyAndHoldsOutsideTheTable) {
  DampingTable table(makeParams(DampingSpeedRule::kLinear));
  EXPECT_NEAR(table.calcTableMoment(15 * kDeg), 1.3, kRoundOff);
  EXPECT_NEAR(table.calcTableMoment(50 * kDeg), 1.6 + 0.5 * 2.9, kRoundOff);
  EXPECT_NEAR(table.calcTableMoment(-5 * kDeg), 1.0, kRoundOff);
  EXPECT_NEAR(table.calcTableMoment(90 * kDeg), 4.5, kRoundOff);
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
