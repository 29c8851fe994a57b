// The Simbody adapters of the knee law and the hip drive (leg/knee_force_element.h) on one
// pin joint without gravity: the moment they apply is the law's, it accelerates the joint
// by moment / inertia, the work they book is the kinetic energy they take, and a law's own
// states are integrated beside the mechanics.
#include "leg/knee_force_element.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>

#include "knee/joint_stop.h"
#include "knee/knee_law.h"
#include "model/hip_moment_profile.h"
#include "simbody_sampling.h"

namespace swingsim {
namespace {

using namespace SimTK;

constexpr double kInertia = 0.2;     // kg m^2 about the pin (a shank about the knee)
constexpr double kRoundOff = 1e-12;  // one division and Simbody's articulated-body solve
constexpr double kAccuracy = 1e-9;   // RK-Merson accuracy of the integrated tests
constexpr double kEnergyTol = 1e-6;  // J: drift the integrator allows at kAccuracy

// A viscous damper, M = -c u: resists every motion, its work is -integral c u^2 dt.
class TestDamper final : public KneeLaw {
 public:
  explicit TestDamper(double c) : c_(c) {}
  std::string name() const override { return "test damper"; }
  double calcMoment(const KneeKinematics& knee, const double*) const override { return -c_ * knee.flexionRate; }
  std::unique_ptr<KneeLaw> clone() const override { return std::make_unique<TestDamper>(*this); }

 private:
  double c_;
};

// A law with one state z (initially 0.7, dz/dt = the flexion rate) and the moment -z: the
// adapter must integrate z and hand it to calcMoment.
class TestStateLaw final : public KneeLaw {
 public:
  std::string name() const override { return "test state"; }
  int numStates() const override { return 1; }
  void initialStates(double* z) const override { z[0] = 0.7; }
  double calcMoment(const KneeKinematics&, const double* z) const override { return -z[0]; }
  void calcStateDerivatives(const KneeKinematics& knee, const double*, double* zdot) const override {
    zdot[0] = knee.flexionRate;
  }
  std::unique_ptr<KneeLaw> clone() const override { return std::make_unique<TestStateLaw>(*this); }
};

// One body on a pin to ground (q about z), no gravity, with a knee element on the pin.
struct PinRig {
  MultibodySystem system;
  SimbodyMatterSubsystem matter{system};
  GeneralForceSubsystem forces{system};
  MobilizedBody::Pin pin{matter.Ground(), Transform(),
                         Body::Rigid(MassProperties(1.0, Vec3(0), Inertia(1.0, 1.0, kInertia))), Transform()};
  KneeForceElement* knee = nullptr;

  PinRig(const KneeLaw& law, bool trackWork) {
    knee = new KneeForceElement(forces, matter, pin, law, trackWork);
    Force::Custom(forces, knee);  // owns knee
    system.realizeTopology();
  }
  // A copied State keeps its values but not its cache: realize it again before reading energy.
  State realized(State s) const {
    system.realize(s, Stage::Acceleration);
    return s;
  }
  State stateAt(double flexion, double rate) const {
    State s = system.getDefaultState();
    pin.setOneQ(s, 0, flexion);
    pin.setOneU(s, 0, rate);
    system.realize(s, Stage::Acceleration);
    return s;
  }
};

KneeLawSum damperAndStop() {
  KneeLawSum sum;
  sum.add(std::make_unique<TestDamper>(0.5));
  sum.add(std::make_unique<JointStop>(JointStopParams{}));
  return sum;
}

TEST(KneeForceElement, AppliesTheLawsMomentAndItAcceleratesTheKneeByMomentOverInertia) {
  const KneeLawSum law = damperAndStop();
  const PinRig rig(law, false);
  for (const KneeKinematics k : {KneeKinematics{0.3, -2.0}, KneeKinematics{1.1, 4.0}, KneeKinematics{-0.01, -1.5}}) {
    const State s = rig.stateAt(k.flexion, k.flexionRate);
    const double expected = law.calcMoment(k, nullptr);
    EXPECT_NEAR(rig.knee->calcKneeMoment(s), expected, kRoundOff) << "flexion " << k.flexion;
    EXPECT_NEAR(rig.pin.getOneUDot(s, 0), expected / kInertia, kRoundOff) << "+ moment = + flexion acceleration";
  }
  EXPECT_NEAR(rig.knee->calcKneeMoment(rig.stateAt(0.3, -2.0)), 1.0, kRoundOff) << "the damper alone above extension";
}

TEST(KneeForceElement, HyperextensionStopEngagesOnlyBeyondFullExtension) {
  const JointStopParams stop;  // engages at 0 rad
  const PinRig rig(JointStop(stop), false);
  EXPECT_EQ(rig.knee->calcKneeMoment(rig.stateAt(0.05, -1.0)), 0.0) << "flexed: the stop is not touched";
  EXPECT_EQ(rig.pin.getOneUDot(rig.stateAt(0.05, -1.0), 0), 0.0);
  // 0.02 rad into the stop and going deeper: the loading spring k p^1.5 (tanh(1/0.05) = 1
  // to 1e-17), pushing back towards flexion.
  const State in = rig.stateAt(-0.02, -1.0);
  const double loading = stop.stiffness * std::pow(0.02, 1.5);
  EXPECT_NEAR(rig.knee->calcKneeMoment(in), loading, 1e-9 * loading);
  EXPECT_GT(rig.pin.getOneUDot(in, 0), 0.0);
  // Coming out at the same depth: the unloading spring, e^2 of it.
  const double unloading = stop.restitution * stop.restitution * loading;
  EXPECT_NEAR(rig.knee->calcKneeMoment(rig.stateAt(-0.02, 1.0)), unloading, 1e-9 * loading);
}

TEST(KneeForceElement, WorkOfEachPartAddsUpToTheKineticEnergyTaken) {
  const PinRig rig(damperAndStop(), true);
  ASSERT_EQ(rig.knee->numWorkParts(), 2);
  EXPECT_EQ(rig.knee->getWorkPartName(0), "test damper");
  EXPECT_EQ(rig.knee->getWorkPartName(1), "hyperextension stop");
  // Falling into the stop at 3 rad/s, bouncing out: no potential energy without gravity, so
  // the work booked is the change of kinetic energy (work-energy theorem).
  const State start = rig.stateAt(0.1, -3.0);
  const double kinetic0 = rig.system.calcKineticEnergy(start);
  bool touchedStop = false;
  State end;
  testing::integrateAndObserve(rig.system, start, kAccuracy, 0.01, 0.4, [&](const State& s) {
    touchedStop = touchedStop || rig.pin.getOneQ(s, 0) < 0;
    end = rig.realized(s);
  });
  ASSERT_TRUE(touchedStop);
  const double work = rig.knee->getWork(end);
  EXPECT_NEAR(work, rig.system.calcKineticEnergy(end) - kinetic0, kEnergyTol);
  EXPECT_NEAR(rig.knee->getPartWork(end, 0) + rig.knee->getPartWork(end, 1), work, kRoundOff);
  EXPECT_LT(rig.knee->getPartWork(end, 0), -0.1) << "the damper dissipates";
  // Out of the stop again, the stop has given back e^2 of what it took: it dissipated.
  ASSERT_GT(rig.pin.getOneQ(end, 0), 0.0);
  EXPECT_LT(rig.knee->getPartWork(end, 1), 0.0);
}

TEST(KneeForceElement, WithoutWorkTrackingNoStateIsAddedAndWorkIsRefused) {
  const PinRig rig(TestDamper(1.0), false);
  const State s = rig.stateAt(0.2, 1.0);
  EXPECT_EQ(s.getNZ(), 0);
  EXPECT_EQ(rig.knee->numWorkParts(), 1);
  EXPECT_EQ(rig.knee->getWorkPartName(0), "test damper");
  EXPECT_EQ(rig.knee->getLawStates(s), nullptr);
  EXPECT_THROW(rig.knee->getWork(s), std::logic_error);
  EXPECT_THROW(rig.knee->getPartWork(s, 0), std::logic_error);
}

TEST(KneeForceElement, LawStatesStartAtTheLawsValuesAndAreIntegrated) {
  const PinRig rig(TestStateLaw(), true);
  const State start = rig.stateAt(0.4, 2.0);
  EXPECT_EQ(start.getNZ(), 2) << "the law's state, then the work";
  ASSERT_NE(rig.knee->getLawStates(start), nullptr);
  EXPECT_EQ(rig.knee->getLawStates(start)[0], 0.7);
  EXPECT_EQ(rig.knee->calcKneeMoment(start), -0.7) << "the moment reads the law's state";
  State end;
  testing::integrateAndObserve(rig.system, start, kAccuracy, 0.05, 0.2, [&](const State& s) { end = rig.realized(s); });
  // dz/dt = dq/dt, so z moves with q.
  const double z = rig.knee->getLawStates(end)[0];
  EXPECT_NEAR(z - 0.7, rig.pin.getOneQ(end, 0) - 0.4, 1e-7);
  EXPECT_NEAR(rig.knee->calcKneeMoment(end), -z, kRoundOff);
  EXPECT_NEAR(rig.knee->getWork(end), rig.system.calcKineticEnergy(end) - rig.system.calcKineticEnergy(start),
              kEnergyTol);
}

TEST(HipDriveElement, AppliesTheProfileAtTheStatesTimePlusTheRangeStop) {
  MultibodySystem system;
  SimbodyMatterSubsystem matter(system);
  GeneralForceSubsystem forces(system);
  MobilizedBody::Pin thigh(matter.Ground(), Transform(),
                           Body::Rigid(MassProperties(1.0, Vec3(0), Inertia(1.0, 1.0, kInertia))), Transform());
  HipMomentProfile profile;  // 30 N m flexion half-sine over 0.2 s, then 15 N m extension
  JointStopParams range;
  range.lower = -0.3;
  range.upper = 1.2;
  auto* hip = new HipDriveElement(forces, matter, thigh, profile, range, true);
  Force::Custom(forces, hip);
  system.realizeTopology();
  State s = system.getDefaultState();
  s.setTime(0.1);
  thigh.setOneQ(s, 0, 0.5);
  thigh.setOneU(s, 0, 1.0);
  system.realize(s, Stage::Acceleration);
  EXPECT_NEAR(hip->calcHipMoment(s), 30.0, 1e-9) << "the flexion half-sine's peak, within the range";
  EXPECT_NEAR(thigh.getOneUDot(s, 0), 30.0 / kInertia, 1e-9);
  EXPECT_EQ(hip->getWork(s), 0.0) << "nothing done at the start";
  // Past the upper end, moving on: the stop pushes back (a negative moment) on top of the profile.
  thigh.setOneQ(s, 0, 1.25);
  system.realize(s, Stage::Acceleration);
  const double expected = profile.calcMoment(0.1) + JointStop(range).calcJointMoment(1.25, 1.0);
  EXPECT_NEAR(hip->calcHipMoment(s), expected, 1e-9);
  EXPECT_LT(expected, 30.0 - 10.0);
}

}  // namespace
}  // namespace swingsim
