// The early failure (SwingOptions::earlyThighFailure): a swing whose thigh provably cannot
// reach its target any more stops there instead of at the time limit. It must change no
// swing's outcome: checked on the Burkett Monte Carlo's own variants (weak hip moments,
// stiff and soft stops, every lowering), where a third of the swings never end. The energy
// bound it rests on is checked against a brute-force scan, and the passivity of the stop
// in knee/joint_stop_test.cpp.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "core/input_error.h"
#include "core/units.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "leg/leg_model.h"
#include "study/sweep_study.h"
#include "sweep/sweep_uncertainty.h"
#include "swing/knee_setup.h"
#include "swing/swing_simulation.h"
#include "swing_outcome.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

using Outcome = testing::SwingOutcome;

Outcome run(const SwingSetup& setup, const SwingOptions& options) { return testing::runSwingCatching(setup, options); }

TEST(EarlyFailure, ChangesNoSwingOfTheMonteCarloVariants) {
  int ended = 0, failedEarly = 0, failedAtLimit = 0;
  testing::compareMonteCarloSwings(
      4, 7, [](SwingOptions& o) { o.earlyThighFailure = false; },
      [&](const PlannedSwing& planned, const Outcome& a, const Outcome& b) {
        ASSERT_TRUE(planned.knee->isPassive());
        ASSERT_EQ(a.ok, b.ok) << a.failure << " | " << b.failure;
        if (a.ok) {
          // Nothing decided early: the same swing to the last bit.
          EXPECT_EQ(a.result.swingTime, b.result.swingTime);
          EXPECT_EQ(a.result.realizations, b.result.realizations);
          ++ended;
          return;
        }
        // Both fail because the thigh never reaches its target.
        EXPECT_THAT(b.failure, HasSubstr("the thigh never reached its target flexion"));
        EXPECT_THAT(a.failure, HasSubstr("the thigh never reached its target flexion"));
        if (a.failure.find("cannot end") != std::string::npos)
          ++failedEarly;
        else
          ++failedAtLimit;
      });
  std::printf("Monte Carlo variants: %d swings ended, %d never did: %d decided early, %d at the time limit\n", ended,
              failedEarly + failedAtLimit, failedEarly, failedAtLimit);
  EXPECT_GT(ended, 100);
  EXPECT_GT(failedEarly, 20) << "the early failure must act where swings never end";
}

TEST(EarlyFailure, LeastPotentialEnergyIsTheMinimumOverKneeAngles) {
  const Participant p = loadParticipant("participants/p2.yaml");
  const KneeLawSum knee = makeKneeLaw(p, loadKneeModel(p.kneeModelPath));
  for (double lowering : {0.0, 0.1}) {
    AddedMass added;
    added.mass = lowering > 0 ? 0.5 : 0.0;
    added.distanceBelowKnee = 0.2;
    const LegModel leg(calcLegGeometry(p, lowering, added), knee, p.hipMoment, p.hipRange, 0.9, false);
    for (double hipDeg : {-20.0, 0.0, 20.0, 35.0}) {
      const double hip = hipDeg * kDegToRad;
      // Brute force: the potential at 2,000 knee angles round the circle.
      SimTK::State s = leg.makeInitialState(InitialConditions{});
      double scanned = std::numeric_limits<double>::infinity();
      for (int k = 0; k < 2000; ++k) {
        InitialConditions ic;
        ic.hipFlexion = hip;
        ic.kneeFlexion = -SimTK::Pi + 2 * SimTK::Pi * k / 2000.0;
        s = leg.makeInitialState(ic);
        scanned = std::min(scanned, leg.calcMechanicalEnergy(s));  // rates zero: all potential
      }
      const double least = leg.calcLeastPotentialEnergy(hip);
      EXPECT_LE(least, scanned + 1e-12) << hipDeg;
      // The scan's grid misses the minimum by at most 1.6e-3 rad: m g r (1.6e-3)^2 / 2, 2e-5 J.
      EXPECT_NEAR(least, scanned, 5e-5) << hipDeg;
    }
  }
}

// P1 with a hip far too weak to lift the thigh 35 deg to its target.
Participant loadWeakP1() {
  Participant p = loadParticipant("participants/p1.yaml");
  p.hipMoment.flexionAmplitude = 5;
  p.hipMoment.extensionAmplitude = 5;
  return p;
}

TEST(EarlyFailure, MessageNamesTheShortfallAndOffItRunsToTheTimeLimit) {
  const Participant p = loadWeakP1();
  const auto knee = std::make_shared<const KneeLawSum>(makeKneeLaw(p, loadKneeModel(p.kneeModelPath)));
  SwingSetup setup = makeSwingSetup(p, knee);
  const Outcome early = run(setup, SwingOptions{});
  ASSERT_FALSE(early.ok);
  EXPECT_THAT(early.failure, HasSubstr("the swing cannot end (decided at t = "));
  EXPECT_THAT(early.failure, HasSubstr("the thigh never reached its target flexion of 20 deg and cannot any more"));
  EXPECT_THAT(early.failure, HasSubstr("J short of the least the thigh at its target needs"));
  EXPECT_THAT(early.failure, HasSubstr("hip moment too small"));
  SwingOptions off;
  off.earlyThighFailure = false;
  const Outcome full = run(setup, off);
  ASSERT_FALSE(full.ok);
  EXPECT_THAT(full.failure, HasSubstr("did not end within the time limit of 1.5 s"));
  // Without requireSwingEnd it returns a NaN swing time, early as late.
  SwingOptions lenient;
  lenient.requireSwingEnd = false;
  const SwingResult r = simulateSwing(setup, lenient);
  EXPECT_TRUE(std::isnan(r.swingTime));
  EXPECT_LT(r.trajectory.time.back(), 1.0);
}

// A knee law nobody has shown to be passive (the Mauch cylinder, whose latch state may hold
// energy) never stops a swing early.
TEST(EarlyFailure, NotWithALawThatIsNotPassive) {
  const Participant p = loadWeakP1();
  const KneeModel mauch = loadKneeModel("models/mauch-2phase.yaml");
  const auto knee = std::make_shared<const KneeLawSum>(makeKneeLaw(p, mauch));
  EXPECT_FALSE(knee->isPassive());
  SwingSetup setup = makeSwingSetup(p, knee);
  const Outcome o = run(setup, SwingOptions{});
  ASSERT_FALSE(o.ok);
  EXPECT_THAT(o.failure, HasSubstr("did not end within the time limit"));
}

}  // namespace
}  // namespace swingsim
