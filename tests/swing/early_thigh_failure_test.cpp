// The early thigh failure (swing/early_thigh_failure.h) as a unit: a leg at rest below a
// target its constant hip moment cannot lift it to, and the same leg thrown upwards fast;
// and when the rule applies. That it changes no swing is tests/swing/early_failure_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "core/units.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "leg/leg_model.h"
#include "swing/early_thigh_failure.h"
#include "swing/knee_setup.h"
#include "swing/step_end.h"

namespace swingsim {
namespace {

// P1 with a hip far too weak to lift the thigh to its target.
SwingSetup weakP1() {
  Participant p = loadParticipant("participants/p1.yaml");
  p.hipMoment.flexionAmplitude = 5;
  p.hipMoment.extensionAmplitude = 5;
  return makeSwingSetup(p, loadKneeModel(p.kneeModelPath));
}

// The check at a state with the thigh at `hip` (rad) rising at `hipRate` (rad/s), knee
// straight and still, after the hip moment's last breakpoint.
bool cannotEndFrom(const SwingSetup& setup, double hip, double hipRate) {
  const Participant& p = setup.participant;
  const LegModel leg(calcLegGeometry(p, setup.lowering, setup.added), *setup.knee, p.hipMoment, p.hipRange,
                     calcHipHeight(p), false);
  EarlyThighFailure failure(setup, SwingOptions{}, true);
  InitialConditions at;
  at.hipFlexion = hip;
  at.kneeFlexion = 0;
  at.hipFlexionRate = hipRate;
  at.kneeFlexionRate = 0;
  SimTK::State s = leg.makeInitialState(at);
  s.updTime() = failure.getConstantFrom() + 0.1;
  const StepEnd now = readStepEnd(leg, s, false);
  failure.check(now, s, leg, false);
  return failure.cannotEnd();
}

TEST(EarlyThighFailure, AThighAtRestUnderAWeakHipCannotReachItsTargetAThrownOneCan) {
  const SwingSetup setup = weakP1();
  EXPECT_TRUE(cannotEndFrom(setup, 0.0, 0.0));
  // 10 rad/s at the hip gives the leg about 1/2 I w^2 = tens of J, far more than the few J
  // lifting it 20 deg takes.
  EXPECT_FALSE(cannotEndFrom(setup, 0.0, 10.0));
}

TEST(EarlyThighFailure, OnlyOnTheFastPathWithAPassiveKneeUnderAHipMoment) {
  const SwingSetup setup = weakP1();
  EXPECT_TRUE(EarlyThighFailure(setup, SwingOptions{}, true).isAllowed());
  EXPECT_FALSE(EarlyThighFailure(setup, SwingOptions{}, false).isAllowed());
  SwingOptions off;
  off.earlyThighFailure = false;
  EXPECT_FALSE(EarlyThighFailure(setup, off, true).isAllowed());
  const SwingSetup mauch = makeSwingSetup(setup.participant, loadKneeModel("models/mauch-2phase.yaml"));
  EXPECT_FALSE(EarlyThighFailure(mauch, SwingOptions{}, true).isAllowed());
  SwingSetup measured = setup;
  measured.participant.drive = SwingDrive::kThighKinematics;
  EXPECT_FALSE(EarlyThighFailure(measured, SwingOptions{}, true).isAllowed());
  // A sagging socket can go below the least potential energy taken at zero deflection.
  SwingSetup socket = setup;
  socket.participant.socket = SocketCompliance{};
  EXPECT_FALSE(EarlyThighFailure(socket, SwingOptions{}, true).isAllowed());
}

}  // namespace
}  // namespace swingsim
