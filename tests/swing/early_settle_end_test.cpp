// The early settle end (swing/early_settle_end.h) as a unit: the decision against the
// closed form of a knee climbing under a constant hold, and when the rule applies at all.
// That it changes no swing is tests/swing/settle_dwell_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "core/units.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "knee/joint_stop.h"
#include "swing/early_settle_end.h"
#include "swing/knee_climb.h"
#include "swing/knee_setup.h"

namespace swingsim {
namespace {

// A knee above its stop (no stop force on the way up) and no other law part: decelerated at
// kHoldFraction x hold, it climbs v^2 / (2 kHoldFraction hold) and reaches the edge iff that
// is at least the gap. The climb is stepped (KneeClimb::kClimbStep), so rates within this
// fraction of the critical one are not asked about.
constexpr double kRateMargin = 0.05;

TEST(EarlySettleEnd, DecidesAsTheClosedFormClimbUnderAConstantHold) {
  JointStopParams stop;
  stop.lower = 0;
  KneeLawSum law;
  law.add(std::make_unique<JointStop>(stop));
  const KneeClimb climb(law);
  const double edge = 5.5 * kDegToRad, knee = 2 * kDegToRad, mu = 5.0;  // mu: 1/(kg m^2), any
  const double freeAcceleration = -80;                                  // rad/s^2
  const double critical = std::sqrt(2 * kHoldFraction * -freeAcceleration * (edge - knee));
  StepEnd e{};
  e.knee = knee;
  e.kneeRate = critical * (1 - kRateMargin);
  EXPECT_TRUE(isSettled(e, climb, edge, mu, freeAcceleration));
  e.kneeRate = critical * (1 + kRateMargin);
  EXPECT_FALSE(isSettled(e, climb, edge, mu, freeAcceleration));
  // Falling (decided only where the knee rises or rests), above the edge, or not held down.
  e.kneeRate = -0.1;
  EXPECT_FALSE(isSettled(e, climb, edge, mu, freeAcceleration));
  e.kneeRate = 0;
  EXPECT_TRUE(isSettled(e, climb, edge, mu, freeAcceleration));
  EXPECT_FALSE(isSettled(e, climb, edge, mu, 1.0));
  e.knee = edge + 0.01;
  EXPECT_FALSE(isSettled(e, climb, edge, mu, freeAcceleration));
}

TEST(EarlySettleEnd, OnlyOnTheFastPathUnderAHipMomentWithoutEnergyBookkeeping) {
  const Participant p = loadParticipant("participants/p1.yaml");
  const SwingSetup setup = makeSwingSetup(p, loadKneeModel(p.kneeModelPath));
  const KneeClimb climb(*setup.knee);
  constexpr int kMobilities = 2;  // thigh and shank
  const SwingOptions defaults;
  EXPECT_TRUE(EarlySettleEnd(setup, defaults, climb, true, kMobilities).isAllowed());
  EXPECT_FALSE(EarlySettleEnd(setup, defaults, climb, false, kMobilities).isAllowed());
  SwingOptions off;
  off.earlySettleEnd = false;
  EXPECT_FALSE(EarlySettleEnd(setup, off, climb, true, kMobilities).isAllowed());
  SwingOptions energy;
  energy.trackImpactEnergy = true;
  EXPECT_FALSE(EarlySettleEnd(setup, energy, climb, true, kMobilities).isAllowed());
  SwingSetup measured = setup;
  measured.participant.drive = SwingDrive::kThighKinematics;
  EXPECT_FALSE(EarlySettleEnd(measured, defaults, climb, true, kMobilities).isAllowed());
  // A compliant socket adds two mobilities the bound does not know (docs/socket.md).
  SwingSetup socket = setup;
  socket.participant.socket = SocketCompliance{};
  EXPECT_FALSE(EarlySettleEnd(socket, defaults, climb, true, kMobilities + 2).isAllowed());
}

}  // namespace
}  // namespace swingsim
