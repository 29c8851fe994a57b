#include "knee/knee_geometry.h"
#include "core/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace swingsim {
namespace {

constexpr double kDeg = kPi / 180.0;
// Central-difference step and the truncation error it allows (h^2 times a bounded third
// derivative of a length of order 0.16 m).
constexpr double kFdStep = 1e-5;
constexpr double kFdTol = 1e-9;
// Round-off on lengths of order 0.1 m.
constexpr double kLengthTol = 1e-14;

TEST(KneeGeometry, CylinderLengthMatchesEquationOneAtHandPoints) {
  const KneeGeometry g;  // ab = 0.1603 m, ac = 0.0247 m (Chien 2014 Eq. 1)
  // theta = 0: alpha = 90 deg, bc = sqrt(ab^2 + ac^2).
  EXPECT_NEAR(g.calcCylinderLength(0.0), std::hypot(0.1603, 0.0247), kLengthTol);
  // theta = 90 deg: alpha = 0, bc = ab - ac.
  EXPECT_NEAR(g.calcCylinderLength(90 * kDeg), 0.1603 - 0.0247, kLengthTol);
  // theta = 30 deg: law of cosines with alpha = 60 deg.
  const double bc30 = std::sqrt(0.1603 * 0.1603 + 0.0247 * 0.0247 - 2 * 0.1603 * 0.0247 * std::cos(60 * kDeg));
  EXPECT_NEAR(g.calcCylinderLength(30 * kDeg), bc30, kLengthTol);
}

TEST(KneeGeometry, PistonPositionFollowsDesignConvention) {
  const KneeGeometry g;
  EXPECT_EQ(g.calcPistonPosition(0.0), 0.0);
  EXPECT_GT(g.calcPistonPosition(10 * kDeg), 0.0);  // flexion
  EXPECT_LT(g.calcPistonPosition(-3 * kDeg), 0.0);  // hyperextension
  EXPECT_GT(g.calcPistonPosition(60 * kDeg), g.calcPistonPosition(30 * kDeg));
  EXPECT_GT(g.calcPistonVelocity(20 * kDeg, 2.0), 0.0);  // flexing
  EXPECT_LT(g.calcPistonVelocity(20 * kDeg, -2.0), 0.0);
}

TEST(KneeGeometry, MomentArmIsTheDerivativeOfPistonPosition) {
  const KneeGeometry g;
  for (double deg = -10; deg <= 80; deg += 7.5) {
    const double th = deg * kDeg;
    const double fd = (g.calcPistonPosition(th + kFdStep) - g.calcPistonPosition(th - kFdStep)) / (2 * kFdStep);
    EXPECT_NEAR(g.calcMomentArm(th), fd, kFdTol) << deg << " deg";
    const double fdLength = (g.calcCylinderLength(th + kFdStep) - g.calcCylinderLength(th - kFdStep)) / (2 * kFdStep);
    EXPECT_NEAR(g.calcLengthDerivative(th), fdLength, kFdTol) << deg << " deg";
  }
}

TEST(KneeGeometry, KneeMomentDoesTheSameVirtualWorkAsTheCylinderForce) {
  // Power balance: M * thetadot = -F * xd (the cylinder's force F resists compression).
  const KneeGeometry g;
  for (double deg : {-4.0, 0.0, 15.0, 45.0, 70.0}) {
    for (double rate : {-5.0, 0.3, 6.0}) {
      const double th = deg * kDeg, force = 321.0;
      const double power = g.calcKneeMoment(th, force) * rate;
      const double xd = g.calcPistonVelocity(th, rate);
      EXPECT_NEAR(power, -force * xd, 1e-12 * std::fabs(force * xd) + 1e-15);
    }
  }
  // A force resisting compression resists knee flexion: flexion moment is negative.
  EXPECT_LT(g.calcKneeMoment(20 * kDeg, 100.0), 0.0);
  EXPECT_NEAR(g.calcKneeMoment(20 * kDeg, 100.0), 100.0 * g.calcLengthDerivative(20 * kDeg), kLengthTol);
}

TEST(KneeGeometry, FlexionInvertsPistonPosition) {
  const KneeGeometry g;
  for (double deg = -20; deg <= 85; deg += 5) {
    EXPECT_NEAR(g.calcFlexion(g.calcPistonPosition(deg * kDeg)), deg * kDeg, 1e-10);
  }
  EXPECT_THROW(g.calcFlexion(1.0), std::domain_error);
}

TEST(KneeGeometry, RejectsImpossibleLengths) {
  EXPECT_THROW(KneeGeometry({-0.1, 0.02}), std::invalid_argument);
  EXPECT_THROW(KneeGeometry({0.1, 0.0}), std::invalid_argument);
  EXPECT_THROW(KneeGeometry({0.1, 0.1}), std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
