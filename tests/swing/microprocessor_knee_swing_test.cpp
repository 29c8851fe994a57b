// The microprocessor knee (impedance state machine, models/microprocessor-knee-osl.yaml)
// in a whole swing: Simbody and the independent reference integrator agree, the default
// accuracy agrees with a tight one across the state transitions, the swing ends with its
// states in order, and a dissipative knee never adds energy (energy bookkeeping).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "../leg/simbody_sampling.h"
#include "core/units.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "leg/leg_model.h"
#include "reference_agreement.h"
#include "swing/knee_setup.h"
#include "swing/reference_swing.h"
#include "swing/swing_simulation.h"

namespace swingsim {
namespace {

using namespace swingsim::testing;  // the reference agreement's tolerances

Participant loadP1() { return loadParticipant(std::string(SWINGSIM_SOURCE_DIR) + "/participants/p1.yaml"); }
KneeModel loadOsl() { return loadKneeModel(std::string(SWINGSIM_SOURCE_DIR) + "/models/microprocessor-knee-osl.yaml"); }

KneeModel withMode(KneeModel model, ImpedanceMode mode) {
  std::get<ImpedanceStateMachineKnee>(model.spec.kind).stateMachine.mode = mode;
  model.law = makeKneeModelLaw(model.spec);
  return model;
}

const ImpedanceStateMachine& machineOf(const KneeLaw& law) {
  return dynamic_cast<const ImpedanceStateMachine&>(dynamic_cast<const KneeLawSum&>(law).part(0));
}

TEST(MicroprocessorKneeSwing, ReferenceIntegratorAgreesWithSimbody) {
  const Participant p = loadP1();
  const ReferenceAgreement a = compareWithReference(p, std::make_shared<const KneeLawSum>(makeKneeLaw(p, loadOsl())));
  ASSERT_TRUE(a.sim.peakKneeFlexion);
  EXPECT_LT(a.maxHipDiff, kAngleTol);
  EXPECT_LT(a.maxKneeDiff, kAngleTol);
  EXPECT_NEAR(a.end.swingTime, a.sim.swingTime, kSwingTimeTol);
  EXPECT_NEAR(a.end.peakKneeFlexion, a.sim.peakKneeFlexion->flexion, kAngleTol);
  EXPECT_NEAR(a.end.peakKneeFlexionTime, a.sim.peakKneeFlexion->time, kSwingTimeTol);
  std::printf(
      "microprocessor knee P1: max |knee diff| %.2e rad, |hip diff| %.2e rad; swing time Simbody %.9f s, "
      "reference %.9f s; peak %.4f deg\n",
      a.maxKneeDiff, a.maxHipDiff, a.sim.swingTime, a.end.swingTime, a.sim.peakKneeFlexion->flexion * kRadToDeg);
}

TEST(MicroprocessorKneeSwing, DefaultAccuracyHoldsAcrossTheTransitions) {
  // The latch (tau = 1 ms) switches the moment within a few ms; the production integrator
  // must resolve it: its swing time and peak agree with a 1e-10 run to within what the
  // sweep reports (0.1 ms, 0.01 deg).
  constexpr double kTimeTol = 1e-4;              // s
  constexpr double kPeakTol = 0.01 * kDegToRad;  // rad
  const Participant p = loadP1();
  const SwingSetup setup = makeSwingSetup(p, loadOsl(), 0.0);
  const SwingResult fast = simulateSwing(setup);
  SwingOptions tight = makeSimbodyIntegratorOptions(kSimbodyAccuracy);
  tight.eventWindow = kEventWindow;
  const SwingResult ref = simulateSwing(setup, tight);
  ASSERT_TRUE(fast.peakKneeFlexion && ref.peakKneeFlexion);
  EXPECT_NEAR(fast.swingTime, ref.swingTime, kTimeTol);
  EXPECT_NEAR(fast.peakKneeFlexion->flexion, ref.peakKneeFlexion->flexion, kPeakTol);
  std::printf("microprocessor knee P1, default accuracy vs 1e-10: swing time %.2e s, peak %.2e deg apart\n",
              fast.swingTime - ref.swingTime,
              (fast.peakKneeFlexion->flexion - ref.peakKneeFlexion->flexion) * kRadToDeg);
}

TEST(MicroprocessorKneeSwing, P1SwingEndsThroughItsStatesInOrder) {
  const Participant p = loadP1();
  const KneeLawSum law = makeKneeLaw(p, loadOsl());
  const ImpedanceStateMachine& machine = machineOf(law);
  LegModel leg(calcLegGeometry(p, 0), law, p.hipMoment, p.hipRange, 1.0);
  int lastState = 0;
  bool inOrder = true;
  double peak = 0, stateAtPeak = -1;
  swingsim::testing::integrateAndObserve(leg.getSystem(), leg.makeInitialState(p.initial), 1e-8, 0.001, 0.6,
                                         [&](const SimTK::State& s) {
                                           const int now = machine.calcCurrentState(leg.getKneeLawStates(s));
                                           inOrder = inOrder && now >= lastState;
                                           lastState = now;
                                           if (leg.getKneeFlexion(s) > peak) {
                                             peak = leg.getKneeFlexion(s);
                                             stateAtPeak = now;
                                           }
                                         });
  EXPECT_TRUE(inOrder);
  EXPECT_EQ(lastState, 2) << "the swing must reach the terminal state";
  // Flexion -> extension fires at the rate threshold (3 deg/s) just before the peak.
  EXPECT_LE(stateAtPeak, 1);
  const SwingResult r = simulateSwing(makeSwingSetup(p, loadOsl(), 0.0));
  EXPECT_TRUE(std::isfinite(r.swingTime));
  EXPECT_LT(r.swingTime, p.swingEnd.timeLimit);
  std::printf("microprocessor knee P1 at 0 m: swing time %.4f s, peak %.1f deg\n", r.swingTime,
              r.peakKneeFlexion ? r.peakKneeFlexion->flexion * kRadToDeg : NAN);
}

TEST(MicroprocessorKneeSwing, DissipativeKneeNeverAddsEnergy) {
  // Bookkeeping as tests/leg/mauch_swing_test.cpp: the latch's 1 ms time constant adds
  // round-off to the work integrals; 1e-6 J is far above the drift at 1e-9 and far below
  // the joules the knee takes.
  constexpr double kEnergyAccuracy = 1e-9;
  constexpr double kEnergyTol = 1e-6;     // J
  constexpr double kWorkRoundOff = 1e-9;  // J: the integral of M rate <= 0 may round above 0
  const Participant p = loadP1();
  const KneeModel model = withMode(loadOsl(), ImpedanceMode::kDissipative);
  const KneeLawSum law = makeKneeLaw(p, model);
  ASSERT_TRUE(law.part(0).isPassive());
  ASSERT_EQ(law.part(0).name(), "impedance state machine");
  LegModel leg(calcLegGeometry(p, 0), law, p.hipMoment, p.hipRange, 1.0);
  double b0 = NAN, maxDrift = 0, maxMachineWork = -1e9, machineWork = 0;
  int lastState = 0;
  swingsim::testing::integrateAndObserve(
      leg.getSystem(), leg.makeInitialState(p.initial), kEnergyAccuracy, 0.002, 0.8, [&](const SimTK::State& s) {
        machineWork = leg.getKneePartWork(s, 0);
        maxMachineWork = std::max(maxMachineWork, machineWork);
        lastState = machineOf(law).calcCurrentState(leg.getKneeLawStates(s));
        const double balance = leg.calcMechanicalEnergy(s) - leg.getKneeWork(s) - leg.getHipWork(s);
        if (std::isnan(b0)) b0 = balance;
        maxDrift = std::max(maxDrift, std::abs(balance - b0));
      });
  EXPECT_LE(maxMachineWork, kWorkRoundOff) << "a dissipative knee must never do positive work";
  EXPECT_LT(machineWork, -0.1) << "it must take a real amount of energy (J)";
  EXPECT_LT(maxDrift, kEnergyTol);
  EXPECT_GE(lastState, 1) << "the state machine must have left its first state";
  // The same knee powered does positive work somewhere: the check above can fail.
  const KneeLawSum powered = makeKneeLaw(p, loadOsl());
  LegModel poweredLeg(calcLegGeometry(p, 0), powered, p.hipMoment, p.hipRange, 1.0);
  double maxPoweredWork = 0;
  swingsim::testing::integrateAndObserve(
      poweredLeg.getSystem(), poweredLeg.makeInitialState(p.initial), 1e-8, 0.002, 0.8,
      [&](const SimTK::State& s) { maxPoweredWork = std::max(maxPoweredWork, poweredLeg.getKneePartWork(s, 0)); });
  EXPECT_GT(maxPoweredWork, 0.1);
  std::printf(
      "dissipative knee P1 over 0.8 s: its work max %.2e J, final %.3f J; balance drift %.2e J; "
      "powered, max work %.3f J\n",
      maxMachineWork, machineWork, maxDrift, maxPoweredWork);
}

}  // namespace
}  // namespace swingsim
