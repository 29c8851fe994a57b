#include "knee/knee_friction.h"
#include "core/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace swingsim {
namespace {

constexpr double kDeg = kDegToRad;
constexpr double kRoundOff = 1e-12;

KneeFriction makeFriction(double tc) {
  KneeFrictionParams p;
  p.frictionMoment = tc;
  return KneeFriction(p);
}

TEST(KneeFriction, GateIsHalfAt4DegOnWellBelowAndOffWellAbove) {
  KneeFriction friction = makeFriction(10);
  // Burkett 2004: friction applies below 4 deg. The default switch width is 0.5 deg, so
  // 2 deg either side is 4 widths: tanh(4) = 0.99933.
  constexpr double kGateTol = 1e-3;
  EXPECT_NEAR(friction.calcGate(4 * kDeg), 0.5, kRoundOff);
  EXPECT_NEAR(friction.calcGate(2 * kDeg), 1.0, kGateTol);
  EXPECT_NEAR(friction.calcGate(-3 * kDeg), 1.0, kGateTol);
  EXPECT_NEAR(friction.calcGate(6 * kDeg), 0.0, kGateTol);
  EXPECT_NEAR(friction.calcGate(40 * kDeg), 0.0, kGateTol);
  // Monotone switch-off.
  double previous = 2;
  for (double a = -5; a <= 10; a += 0.25) {
    const double gate = friction.calcGate(a * kDeg);
    EXPECT_LT(gate, previous);
    previous = gate;
  }
}

TEST(KneeFriction, ResistsMotionWithMagnitudeTcBelow4Deg) {
  KneeFriction friction = makeFriction(10);
  constexpr double kSaturated = 1e-3;  // Tc (1 - gate tanh) at 1 deg and 5 rad/s
  EXPECT_NEAR(friction.calcMoment({1 * kDeg, 5.0}, nullptr), -10, 10 * kSaturated);
  EXPECT_NEAR(friction.calcMoment({1 * kDeg, -5.0}, nullptr), 10, 10 * kSaturated);
  EXPECT_EQ(friction.calcMoment({1 * kDeg, 0.0}, nullptr), 0.0);
  // Well above 4 deg it is negligible.
  EXPECT_LT(std::abs(friction.calcMoment({30 * kDeg, 5.0}, nullptr)), 1e-6);
}

TEST(KneeFriction, SmoothInVelocityNoJumpThroughZero) {
  KneeFriction friction = makeFriction(10);
  const double rateStep = 1e-6;
  const double slope =
      (friction.calcMoment({0, rateStep}, nullptr) - friction.calcMoment({0, -rateStep}, nullptr)) / (2 * rateStep);
  // tanh(rate / w): slope -Tc gate / w with gate(0 deg) = 0.5 (1 + tanh(8)).
  const double gate = friction.calcGate(0);
  EXPECT_NEAR(slope, -10 * gate / friction.params().smoothingRate, 1e-4);
}

TEST(KneeFriction, RejectsNegativeTcAndZeroWidths) {
  KneeFrictionParams p;
  p.frictionMoment = -1;
  EXPECT_THROW(KneeFriction{p}, std::invalid_argument);
  p.frictionMoment = 1;
  p.smoothingRate = 0;
  EXPECT_THROW(KneeFriction{p}, std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
