#include "knee/joint_stop.h"
#include "core/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace swingsim {
namespace {

constexpr double kDeg = kDegToRad;
constexpr double kRoundOff = 1e-9;

JointStop makeStop() {
  JointStopParams p;
  p.lower = 0;
  p.upper = 90 * kDeg;
  p.stiffness = 2.0e4;
  p.dissipation = 0.3;
  return JointStop(p);
}

TEST(JointStop, FreeInsideTheRange) {
  JointStop stop = makeStop();
  for (double a : {0.0, 1e-9, 10 * kDeg, 89.9 * kDeg, 90 * kDeg})
    for (double rate : {-5.0, 0.0, 5.0}) EXPECT_EQ(stop.calcJointMoment(a, rate), 0.0);
}

TEST(JointStop, PushesBackIntoTheRangeAtRest) {
  JointStop stop = makeStop();
  const double p = 2 * kDeg;
  EXPECT_NEAR(stop.calcJointMoment(-p, 0), 2.0e4 * std::pow(p, 1.5), kRoundOff);
  EXPECT_NEAR(stop.calcJointMoment(90 * kDeg + p, 0), -2.0e4 * std::pow(p, 1.5), kRoundOff);
}

TEST(JointStop, ContinuousAtOnsetEvenWhenHitFast) {
  // Hunt-Crossley: the moment grows from zero at contact whatever the speed, so there is
  // no jump for the integrator. At 1e-8 rad past the limit at 10 rad/s it is < 1e-6 N m.
  JointStop stop = makeStop();
  constexpr double kOnsetMoment = 1e-6;  // 2e4 * (1e-8)^1.5 * (1 + 0.45 * 10) = 1.1e-7
  EXPECT_LT(std::abs(stop.calcJointMoment(-1e-8, -10.0)), kOnsetMoment);
  EXPECT_LT(std::abs(stop.calcJointMoment(90 * kDeg + 1e-8, 10.0)), kOnsetMoment);
}

TEST(JointStop, DissipatesMoreGoingInThanComingOut) {
  JointStop stop = makeStop();
  const double p = 1 * kDeg;
  const double entering = stop.calcJointMoment(-p, -1.0);  // moving deeper into the stop
  const double leaving = stop.calcJointMoment(-p, 1.0);
  EXPECT_GT(entering, stop.calcJointMoment(-p, 0));
  EXPECT_LT(leaving, stop.calcJointMoment(-p, 0));
  EXPECT_NEAR(entering, 2.0e4 * std::pow(p, 1.5) * (1 + 1.5 * 0.3 * 1.0), kRoundOff);
}

TEST(JointStop, NeverPullsOnRelease) {
  // Leaving fast (1.5 c pdot < -1), a Hunt-Crossley term would turn negative and glue the
  // joint to the stop; the law clips it at zero.
  JointStop stop = makeStop();
  for (double rate : {3.0, 10.0, 100.0}) {
    EXPECT_GE(stop.calcJointMoment(-1 * kDeg, rate), 0.0) << "lower stop, rate " << rate;
    EXPECT_LE(stop.calcJointMoment(91 * kDeg, -rate), 0.0) << "upper stop, rate " << rate;
  }
  EXPECT_EQ(stop.calcJointMoment(-1 * kDeg, 10.0), 0.0);
}

TEST(JointStop, AsKneeLawUsesFlexionAndRate) {
  JointStop stop = makeStop();
  EXPECT_EQ(stop.calcMoment({-1 * kDeg, -0.5}, nullptr), stop.calcJointMoment(-1 * kDeg, -0.5));
}

TEST(JointStop, RejectsBadParameters) {
  JointStopParams p;
  p.lower = 1;
  p.upper = 0;
  EXPECT_THROW(JointStop{p}, std::invalid_argument);
  p = JointStopParams{};
  p.stiffness = 0;
  EXPECT_THROW(JointStop{p}, std::invalid_argument);
  p = JointStopParams{};
  p.dissipation = -0.1;
  EXPECT_THROW(JointStop{p}, std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
