#include "knee/joint_stop.h"
#include "core/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "../independent/rk4_step.h"

namespace swingsim {
namespace {

constexpr double kDeg = kDegToRad;
constexpr double kRoundOff = 1e-9;

JointStop makeStop() {
  JointStopParams p;
  p.lower = 0;
  p.upper = 90 * kDeg;
  p.stiffness = 2.0e4;
  p.restitution = 0.4;
  return JointStop(p);
}

TEST(JointStop, FreeInsideTheRange) {
  JointStop stop = makeStop();
  for (double a : {0.0, 1e-9, 10 * kDeg, 89.9 * kDeg, 90 * kDeg})
    for (double rate : {-5.0, 0.0, 5.0}) EXPECT_EQ(stop.calcJointMoment(a, rate), 0.0);
}

TEST(JointStop, PushesBackIntoTheRangeAtRest) {
  // At rest the law sits halfway between the loading and unloading springs.
  JointStop stop = makeStop();
  const double p = 2 * kDeg;
  const double atRest = 2.0e4 * std::pow(p, 1.5) * (1 + 0.4 * 0.4) / 2;
  EXPECT_NEAR(stop.calcJointMoment(-p, 0), atRest, kRoundOff);
  EXPECT_NEAR(stop.calcJointMoment(90 * kDeg + p, 0), -atRest, kRoundOff);
}

TEST(JointStop, ContinuousAtOnsetEvenWhenHitFast) {
  // The moment grows from zero at contact whatever the speed, so there is no jump for the
  // integrator. At 1e-8 rad past the limit it is < 1e-6 N m.
  JointStop stop = makeStop();
  constexpr double kOnsetMoment = 1e-6;  // 2e4 * (1e-8)^1.5 = 2e-8
  EXPECT_LT(std::abs(stop.calcJointMoment(-1e-8, -10.0)), kOnsetMoment);
  EXPECT_LT(std::abs(stop.calcJointMoment(90 * kDeg + 1e-8, 10.0)), kOnsetMoment);
}

TEST(JointStop, LoadsWithTheFullSpringAndUnloadsWithESquaredOfIt) {
  JointStop stop = makeStop();
  const double p = 1 * kDeg, spring = 2.0e4 * std::pow(p, 1.5);
  EXPECT_NEAR(stop.calcJointMoment(-p, -2.0), spring, 1e-6 * spring);         // going in at 2 rad/s
  EXPECT_NEAR(stop.calcJointMoment(-p, 2.0), 0.16 * spring, 1e-6 * spring);   // coming out: e^2 = 0.16
  EXPECT_NEAR(stop.calcJointMoment(91 * kDeg, 2.0), -spring, 1e-6 * spring);  // the upper stop, going in
  EXPECT_NEAR(stop.calcJointMoment(91 * kDeg, -2.0), -0.16 * spring, 1e-6 * spring);
}

TEST(JointStop, NeverPullsOnRelease) {
  JointStop stop = makeStop();
  for (double rate : {3.0, 10.0, 100.0}) {
    EXPECT_GT(stop.calcJointMoment(-1 * kDeg, rate), 0.0) << "lower stop, rate " << rate;
    EXPECT_LT(stop.calcJointMoment(91 * kDeg, -rate), 0.0) << "upper stop, rate " << rate;
  }
}

// A single impact of an inertia I on the stop, integrated here by classical RK4 with a
// fixed step (independent of the simulator's integrators): exit speed / impact speed must
// be the configured restitution within 5 % over swing impact speeds (2-10 rad/s), shank
// inertias about the knee (0.05-0.3 kg m^2) and restitutions (0.1-0.9), independent of
// speed (the Hunt-Crossley law it replaced was not: docs/assumptions.md). It holds while the exit
// speed e v is at least 8 switch rates (0.4 rad/s); slower rebounds come out faster than
// e v (e = 0.1 at 1 rad/s: 0.15), and lift a shank by well under a degree.
double measureRestitution(const JointStop& stop, double inertia, double impactRate) {
  double q = 0, u = -impactRate;  // at the stop's engage angle, moving into it
  const double h = 2e-6;          // s: a few thousand steps per contact
  auto acc = [&](double qq, double uu) { return stop.calcJointMoment(qq, uu) / inertia; };
  for (int i = 0; i < 10000000; ++i) {
    testing::stepRk4(q, u, h, acc);
    if (q >= 0 && u > 0) return u / impactRate;  // left the stop
    if (q >= 0 && i > 0 && u <= 0 && std::abs(u) < 1e-12) return 0;
  }
  return -1;  // never left
}

TEST(JointStop, RestitutionOfASingleImpactIsTheConfiguredOne) {
  for (double e : {0.1, 0.2, 0.4, 0.9}) {
    JointStopParams p;
    p.restitution = e;
    const JointStop stop(p);
    for (double inertia : {0.05, 0.3}) {
      for (double v : {0.5, 1.0, 2.0, 6.0, 10.0}) {
        if (e * v < 8 * p.switchRate) continue;
        const double measured = measureRestitution(stop, inertia, v);
        EXPECT_NEAR(measured, e, 0.05 * e) << "e " << e << ", I " << inertia << " kg m^2, " << v << " rad/s";
      }
    }
  }
}

// Passivity with the stored energy (KneeLaw::isPassive, calcStoredEnergy): the stop's
// power into the joint, M angle_rate, plus the rate of its stored energy, dU/dangle
// angle_rate (dU/dangle by central differences, not by the law's formula), is never positive,
// at penetrations up to 10 deg on both stops and rates from -10 to 10 rad/s, slow turns
// near the switch rate included.
TEST(JointStop, StoredEnergyMakesItPassive) {
  for (double e : {0.0, 0.4, 0.9, 1.0}) {
    JointStopParams params = makeStop().params();
    params.restitution = e;
    const JointStop stop(params);
    EXPECT_TRUE(stop.isPassive());
    EXPECT_EQ(stop.calcJointStoredEnergy(5 * kDeg), 0.0);
    for (double edge : {params.lower, *params.upper}) {
      for (double depth = 0.01 * kDeg; depth < 10 * kDeg; depth *= 1.7) {
        const double angle = edge == params.lower ? edge - depth : edge + depth;
        const double h = 1e-7;
        const double dU = (stop.calcJointStoredEnergy(angle + h) - stop.calcJointStoredEnergy(angle - h)) / (2 * h);
        for (double rate = -10; rate <= 10; rate += 0.0137) {
          const double power = stop.calcJointMoment(angle, rate) * rate + dU * rate;
          EXPECT_LE(power, 1e-6 * std::fabs(dU * rate) + 1e-12) << "e " << e << " angle " << angle << " rate " << rate;
        }
      }
    }
  }
}

TEST(JointStop, AsKneeLawUsesFlexionAndRate) {
  JointStop stop = makeStop();
  EXPECT_EQ(stop.calcMoment({-1 * kDeg, -0.5}, nullptr), stop.calcJointMoment(-1 * kDeg, -0.5));
}

// The knee's stop has no upper side (JointStopParams::upper absent): free however far it flexes.
TEST(JointStop, NoUpperStopIsFreeAtAnyFlexion) {
  JointStopParams p;
  EXPECT_FALSE(p.upper);  // the default
  const JointStop stop(p);
  for (double a : {10 * kDeg, 179 * kDeg, 1e3})
    for (double rate : {-5.0, 0.0, 5.0}) EXPECT_EQ(stop.calcJointMoment(a, rate), 0.0) << a;
  EXPECT_EQ(stop.calcJointStoredEnergy(1e3), 0.0);
}

TEST(JointStop, RejectsBadParameters) {
  JointStopParams p;
  p.lower = 1;
  p.upper = 0;
  EXPECT_THROW(JointStop{p}, std::invalid_argument);
  p = JointStopParams{};
  p.stiffness = 0;
  EXPECT_THROW(JointStop{p}, std::invalid_argument);
  for (double e : {-0.1, 1.1}) {
    p = JointStopParams{};
    p.restitution = e;
    EXPECT_THROW(JointStop{p}, std::invalid_argument) << e;
  }
  p = JointStopParams{};
  p.switchRate = 0;
  EXPECT_THROW(JointStop{p}, std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
