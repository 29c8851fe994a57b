// KneeClimb (the settle dwell's early end): how high the knee can climb out of its stop as
// one degree of freedom. Checked against closed forms and against the knee's climb
// integrated in time here (small fixed-step RK4 of q'' = -f h + mu f M(q, q'), written in
// this file), never against KneeClimb's own integration in the knee angle.
#include "swing/knee_climb.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "../independent/rk4_step.h"
#include "core/units.h"
#include "knee/joint_stop.h"
#include "knee/knee_added_effects.h"
#include "knee/knee_friction.h"

namespace swingsim {
namespace {

constexpr double kDeg = kDegToRad;
constexpr double kMu = 4.0;     // 1/(kg m^2): a shank and foot of 0.25 kg m^2
constexpr double kHold = 20.0;  // rad/s^2
constexpr double kEdge = 5.5 * kDeg;

JointStopParams stopParams() {
  JointStopParams p;
  p.lower = 0;
  p.stiffness = 2.0e4;
  p.restitution = 0.4;
  return p;
}

// The top of the knee's climb from (q0, w0 > 0) above the stop, integrated in time: the knee
// decelerated by `trusted` of the hold and of the resisting moment (a moment pushing it up
// counts whole), as KneeClimb states it.
double climbInTime(const KneeLaw& others, double q0, double w0, double trusted) {
  auto acc = [&](double q, double w) {
    const double m = others.calcMoment({q, w}, nullptr);
    return -trusted * kHold + kMu * (trusted * std::min(m, 0.0) + std::max(m, 0.0));
  };
  double q = q0, w = w0;
  const double h = 1e-6;      // s
  while (w > 0 && q < 1.0) {  // 1 rad: far past any edge
    testing::stepRk4(q, w, h, acc);
  }
  return q;
}

TEST(KneeClimb, StopAloneGivesBackItsStoredEnergyAgainstTheTrustedHold) {
  const JointStop stop(stopParams());
  const KneeClimb climb(stop);
  ASSERT_EQ(climb.getStop(), &stop);
  // On the stop at -1.5 deg, rising at 0.8 rad/s: per unit inertia it has w^2/2 + mu U.
  const double q = -1.5 * kDeg, w = 0.8;
  const double energy = 0.5 * w * w + kMu * stop.calcJointStoredEnergy(q);
  for (double f : {0.5, 1.0}) {
    const double reach = energy / (f * kHold);  // rad it can climb
    EXPECT_TRUE(climb.canReach(q, w, q + 0.99 * reach, kMu, kHold, f)) << f;
    EXPECT_FALSE(climb.canReach(q, w, q + 1.01 * reach, kMu, kHold, f)) << f;
  }
  EXPECT_TRUE(climb.canReach(kEdge, 0.0, kEdge, kMu, kHold, 0.5)) << "at the edge it is there";
}

TEST(KneeClimb, ConstantFrictionAddsItsMomentOverInertiaToTheHold) {
  KneeLawSum law;
  law.add(std::make_unique<JointStop>(stopParams()));
  KneeAddedEffectsParams coulomb;
  coulomb.coulombMoment = 6.0;          // N m
  coulomb.coulombSmoothingRate = 1e-4;  // rad/s: a step, so the friction is constant
  law.add(std::make_unique<KneeAddedEffects>(coulomb));
  const KneeClimb climb(law);
  ASSERT_NE(climb.getStop(), nullptr);
  const double q = 1 * kDeg, w = 1.5, f = 0.5;
  const double reach = 0.5 * w * w / (f * (kHold + kMu * 6.0));
  EXPECT_TRUE(climb.canReach(q, w, q + 0.99 * reach, kMu, kHold, f));
  EXPECT_FALSE(climb.canReach(q, w, q + 1.01 * reach, kMu, kHold, f));
  // Without the friction the same knee climbs (20 + 24) / 20 = 2.2 times as high.
  const KneeClimb bare(law.part(0));
  EXPECT_TRUE(bare.canReach(q, w, q + 2 * reach, kMu, kHold, f));
}

TEST(KneeClimb, AgreesWithTheClimbIntegratedInTimeUnderFrictionNearExtensionAndDamping) {
  // Burkett's knee friction near extension (tanh in the rate, gated off above 4 deg) plus a
  // viscous damping: the climb crosses the gate.
  KneeLawSum others;
  KneeFrictionParams friction;
  friction.frictionMoment = 10.0;  // N m, Burkett Table 2's order
  others.add(std::make_unique<KneeFriction>(friction));
  KneeAddedEffectsParams damping;
  damping.viscousDamping = 0.3;  // N m s/rad
  others.add(std::make_unique<KneeAddedEffects>(damping));
  KneeLawSum law = others;
  law.add(std::make_unique<JointStop>(stopParams()));
  const KneeClimb climb(law);
  for (double w0 : {0.5, 1.5, 3.0}) {
    for (double q0 : {0.2 * kDeg, 2.0 * kDeg}) {
      const double top = climbInTime(others, q0, w0, 0.5);
      const double height = top - q0;
      ASSERT_GT(height, 0.0);
      EXPECT_TRUE(climb.canReach(q0, w0, q0 + 0.98 * height, kMu, kHold, 0.5)) << w0 << " rad/s from " << q0 / kDeg;
      EXPECT_FALSE(climb.canReach(q0, w0, q0 + 1.02 * height, kMu, kHold, 0.5)) << w0 << " rad/s from " << q0 / kDeg;
    }
  }
}

TEST(KneeClimb, APartPushingTheKneeUpCountsWhole) {
  // An "assist" spring of negative stiffness pushes the knee into flexion (not passive): the
  // cheap answer (energy against the hold alone) would say no; the climb says yes.
  KneeAddedEffectsParams push;
  push.assistStiffness = -400.0;  // N m/rad: +400 q N m at q > 0
  KneeLawSum others;
  others.add(std::make_unique<KneeAddedEffects>(push));
  KneeLawSum law = others;
  law.add(std::make_unique<JointStop>(stopParams()));
  const KneeClimb climb(law);
  const double q0 = 1 * kDeg, w0 = 0.3;
  ASSERT_LT(0.5 * w0 * w0, 0.5 * kHold * (kEdge - q0)) << "the hold alone would stop it";
  const double top = climbInTime(others, q0, w0, 0.5);
  ASSERT_GT(top, kEdge) << "the spring lifts it past the edge";
  EXPECT_TRUE(climb.canReach(q0, w0, kEdge, kMu, kHold, 0.5));
}

// A law with a state of its own (as the Mauch cylinder's latch) that would stop any climb.
class StatefulBrake final : public KneeLaw {
 public:
  std::string name() const override { return "stateful brake"; }
  int numStates() const override { return 1; }
  double calcMoment(const KneeKinematics& knee, const double*) const override { return -1e6 * knee.flexionRate; }
  std::unique_ptr<KneeLaw> clone() const override { return std::make_unique<StatefulBrake>(*this); }
};

TEST(KneeClimb, PartsWithStatesAreLeftOut) {
  KneeLawSum law;
  law.add(std::make_unique<StatefulBrake>());
  law.add(std::make_unique<JointStop>(stopParams()));
  const KneeClimb climb(law);
  const KneeClimb bare(law.part(1));
  for (double w : {0.3, 1.0, 2.0})
    EXPECT_EQ(climb.canReach(0.5 * kDeg, w, kEdge, kMu, kHold, 0.5),
              bare.canReach(0.5 * kDeg, w, kEdge, kMu, kHold, 0.5))
        << w;
}

TEST(KneeClimb, NoStopWithoutAJointStop) {
  KneeAddedEffectsParams damping;
  damping.viscousDamping = 1.0;
  const KneeAddedEffects law(damping);
  EXPECT_EQ(KneeClimb(law).getStop(), nullptr);
}

}  // namespace
}  // namespace swingsim
