// The steppers under the swing loop (swing/swing_stepper.h) on one pin joint with a known
// solution: a linear spring (q = q0 cos 2 pi t, period 1 s) and a constant moment (q a
// parabola). Each stepper reaches the time limit and agrees with the solution; Dormand-Prince
// ends steps on breakpoints and on the knee's levels, goes back to a checkpoint and on with
// the loose dwell.
#include "swing/swing_stepper.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace swingsim {
namespace {

using namespace SimTK;

constexpr double kAccuracy = 1e-8;
constexpr double kSolutionTol = 1e-5;  // rad: global error of a 1 s run at kAccuracy, with margin
constexpr double kRoundOff = 1e-12;    // s or rad: a step end placed on a time or a level

// One body on a pin (q about z, inertia 1 kg m^2) with either a spring or a constant moment.
struct Rig {
  MultibodySystem system;
  SimbodyMatterSubsystem matter{system};
  GeneralForceSubsystem forces{system};
  MobilizedBody::Pin pin{matter.Ground(), Transform(), Body::Rigid(MassProperties(1.0, Vec3(0), Inertia(1.0))),
                         Transform()};

  State start(double q, double u) {
    system.realizeTopology();
    State s = system.getDefaultState();
    pin.setOneQ(s, 0, q);
    pin.setOneU(s, 0, u);
    system.realize(s, Stage::Acceleration);
    return s;
  }
};

// A spring of stiffness (2 pi)^2 N m/rad: period 1 s, q = 0.5 cos(2 pi t) from q = 0.5 at rest.
struct Oscillator : Rig {
  Oscillator() { Force::MobilityLinearSpring(forces, pin, MobilizerQIndex(0), 4 * Pi * Pi, 0.0); }
  static double calcAngle(double t) { return 0.5 * std::cos(2 * Pi * t); }
};

SwingOptions simbodyOptions(SwingIntegrator kind, bool events) {
  SwingOptions o;
  o.integrator = kind;
  o.accuracy = kAccuracy;
  o.simbodyEvents = events;
  return o;
}

TEST(SwingStepper, MakeIntegratorGivesSimbodysOwnAndRefusesDormandPrince) {
  Oscillator rig;
  rig.system.realizeTopology();
  EXPECT_EQ(std::string(makeIntegrator(SwingIntegrator::kRungeKuttaMerson, rig.system)->getMethodName()),
            "RungeKuttaMerson");
  EXPECT_EQ(std::string(makeIntegrator(SwingIntegrator::kRungeKuttaFeldberg, rig.system)->getMethodName()),
            "RungeKuttaFeldberg");
  EXPECT_EQ(std::string(makeIntegrator(SwingIntegrator::kRungeKutta3, rig.system)->getMethodName()), "RungeKutta3");
  EXPECT_EQ(std::string(makeIntegrator(SwingIntegrator::kVerlet, rig.system)->getMethodName()), "Verlet");
  EXPECT_EQ(std::string(makeIntegrator(SwingIntegrator::kCPodes, rig.system)->getMethodName()), "CPodesBDF");
  EXPECT_THROW(makeIntegrator(SwingIntegrator::kDormandPrince, rig.system), std::invalid_argument);
}

TEST(SwingStepper, SimbodyStepperTakesOneStepACallUpToTheLimit) {
  for (const bool events : {false, true}) {
    Oscillator rig;
    const State initial = rig.start(0.5, 0.0);
    constexpr double kLimit = 1.0;
    SimbodyStepper stepper(rig.system, initial, simbodyOptions(SwingIntegrator::kRungeKuttaMerson, events), kLimit);
    int advanced = 0;  // calls that moved time on (the time stepper first reports the start)
    double last = 0;
    while (stepper.step(kLimit)) {
      const State& s = stepper.getState();
      EXPECT_GE(s.getTime(), last);
      advanced += s.getTime() > last;
      last = s.getTime();
      EXPECT_GE(s.getSystemStage(), Stage::Acceleration);
    }
    const State& end = stepper.getState();
    EXPECT_NEAR(end.getTime(), kLimit, kRoundOff) << "events " << events;
    EXPECT_NEAR(rig.pin.getOneQ(end, 0), Oscillator::calcAngle(kLimit), kSolutionTol);
    EXPECT_GT(advanced, 10) << "a step a call, not one call to the end";
    EXPECT_GE(stepper.getNumSteps(), advanced);
    EXPECT_GE(stepper.getNumRealizations(), 4 * stepper.getNumSteps()) << "RK-Merson: 5 stages a step";
  }
}

TEST(SwingStepper, DormandPrinceMatchesTheSolutionAndEndsStepsOnBreakpoints) {
  Oscillator rig;
  const State initial = rig.start(0.5, 0.0);
  DormandPrinceStepper stepper(rig.system, initial, kAccuracy, {0.123, 0.377, 2.0});
  std::vector<double> ends;
  constexpr double kLimit = 1.0;
  while (stepper.step(kLimit)) ends.push_back(stepper.getState().getTime());
  ends.push_back(stepper.getState().getTime());
  for (double b : {0.123, 0.377}) {
    bool hit = false;
    for (double t : ends) hit = hit || std::fabs(t - b) < kRoundOff;
    EXPECT_TRUE(hit) << "a step ends on the breakpoint " << b;
  }
  EXPECT_NEAR(ends.back(), kLimit, kRoundOff);
  EXPECT_NEAR(rig.pin.getOneQ(stepper.getState(), 0), Oscillator::calcAngle(kLimit), kSolutionTol);
  EXPECT_EQ(stepper.getNumSteps(), static_cast<int>(ends.size()));
  // First same as last: six realizations a step, one to start, and few rejected steps.
  EXPECT_GE(stepper.getNumRealizations(), 6 * stepper.getNumSteps());
  EXPECT_LE(stepper.getNumRealizations(), 8 * stepper.getNumSteps());
  EXPECT_FALSE(stepper.step(kLimit)) << "nothing past the limit";
}

TEST(SwingStepper, DormandPrinceEndsAStepWhereTheFallingKneeReachesEachLevel) {
  // A constant extending moment of 10 N m: q = 1 - t - 5 t^2, a parabola the prediction
  // follows exactly, so the steps end on the levels to round-off.
  Rig rig;
  Force::MobilityConstantForce(rig.forces, rig.pin, -10.0);
  const State initial = rig.start(1.0, -1.0);
  DormandPrinceStepper stepper(rig.system, initial, kAccuracy, {});
  stepper.setKneeLevels(0, {0.5, 0.2, -0.3});
  std::vector<double> angles;
  while (stepper.step(0.5)) angles.push_back(rig.pin.getOneQ(stepper.getState(), 0));
  for (double level : {0.5, 0.2, -0.3}) {
    bool hit = false;
    for (double q : angles) hit = hit || std::fabs(q - level) < 1e-9;
    EXPECT_TRUE(hit) << "a step ends at the level " << level;
  }
  const double t = stepper.getState().getTime();
  EXPECT_NEAR(rig.pin.getOneQ(stepper.getState(), 0), 1 - t - 5 * t * t, 1e-9);
}

TEST(SwingStepper, DormandPrinceGoesBackToItsCheckpointAndOnWithTheLooseDwell) {
  Oscillator rig;
  const State initial = rig.start(0.5, 0.0);
  DormandPrinceStepper stepper(rig.system, initial, kAccuracy, {0.25});
  while (stepper.getState().getTime() < 0.25) stepper.step(1.0);
  stepper.saveCheckpoint();
  const double checkpointAngle = rig.pin.getOneQ(stepper.getState(), 0);
  stepper.loosen(100 * kAccuracy);
  for (int i = 0; i < 3; ++i) stepper.step(1.0);
  const double later = stepper.getState().getTime();
  EXPECT_GT(later, 0.25);
  const int stepsBefore = stepper.getNumSteps();
  // Back to the checkpoint: the same time and angle, and the steps taken still counted.
  stepper.restoreCheckpoint(kAccuracy);
  EXPECT_NEAR(stepper.getState().getTime(), 0.25, kRoundOff);
  EXPECT_EQ(rig.pin.getOneQ(stepper.getState(), 0), checkpointAngle);
  EXPECT_EQ(stepper.getNumSteps(), stepsBefore);
  // The loose dwell to the end: Bogacki-Shampine at the looser accuracy still follows the spring.
  stepper.loosen(100 * kAccuracy);
  while (stepper.step(1.0)) {
  }
  EXPECT_NEAR(stepper.getState().getTime(), 1.0, kRoundOff);
  EXPECT_NEAR(rig.pin.getOneQ(stepper.getState(), 0), Oscillator::calcAngle(1.0), 100 * kSolutionTol);
  EXPECT_GT(stepper.getNumSteps(), stepsBefore);
}

}  // namespace
}  // namespace swingsim
