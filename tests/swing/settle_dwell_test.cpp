// The settle dwell's early end (SwingOptions::earlySettleEnd): ending the dwell once the
// knee can no longer leave the zone must give the swing the full dwell gives, on every
// lowering of the four Burkett participants, with their knees and with bouncy ones.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "study/sweep_study.h"
#include "sweep/sweep.h"
#include "sweep/sweep_uncertainty.h"
#include "swing/knee_setup.h"
#include "swing/swing_simulation.h"
#include "swing_outcome.h"

namespace swingsim {
namespace {

// A knee variant of the sweep: the participant's knee model with a stop restitution and
// with or without the knee friction near extension (which takes a rebound's energy).
struct KneeVariant {
  const char* name;
  double restitution;  // < 0: the model's own
  bool friction;
};

using Outcome = testing::SwingOutcome;

Outcome run(const SwingSetup& setup, const SwingOptions& options) { return testing::runSwingCatching(setup, options); }

TEST(SettleDwell, EarlyEndGivesTheFullDwellsSwingForEveryLoweringAndBouncyKnees) {
  const SweepStudy study = loadSweepStudy("studies/burkett2004.yaml");
  const KneeVariant variants[] = {{"as published", -1, true},
                                  {"restitution 0.9, no friction", 0.9, false},
                                  {"restitution 0.6, no friction", 0.6, false}};
  SwingOptions early;
  early.recordTrajectory = false;
  SwingOptions full = early;
  full.earlySettleEnd = false;
  int compared = 0, bouncing = 0;
  for (const KneeVariant& v : variants) {
    int swings = 0, endedEarly = 0;
    long realizationsEarly = 0, realizationsFull = 0;
    for (const Participant& base : study.participants) {
      Participant p = base;
      if (!v.friction) p.kneeFriction = 0;
      const KneeModel& published = findStudyKneeModel(study, base);
      KneeModelSpec spec = published.spec;
      if (v.restitution >= 0) spec.stop.restitution = v.restitution;
      const auto knee = std::make_shared<const KneeLawSum>(
          makeKneeLaw(p, KneeModel{published.path, published.name, makeKneeModelLaw(spec), spec}));
      for (double lowering : sweepLowerings(study, p)) {
        SCOPED_TRACE(p.name + " at " + std::to_string(lowering) + " m, " + v.name);
        const SwingSetup setup = makeSwingSetup(p, knee, lowering);
        const Outcome a = run(setup, early), b = run(setup, full);
        ASSERT_EQ(a.ok, b.ok) << a.failure << b.failure;
        if (!a.ok) continue;
        const SwingResult &x = a.result, &y = b.result;
        ++compared;
        ++swings;
        endedEarly += x.endDecidedTime < y.endDecidedTime;
        bouncing += y.bounces > 0;
        realizationsEarly += x.realizations;
        realizationsFull += y.realizations;
        // The same swing, exactly: the early end only stops integrating after the decision.
        EXPECT_EQ(x.swingTime, y.swingTime);
        EXPECT_EQ(x.bounces, y.bounces);
        EXPECT_EQ(x.bounce, y.bounce);
        EXPECT_EQ(x.bounceHeight, y.bounceHeight);
        ASSERT_TRUE(x.peakKneeFlexion && y.peakKneeFlexion);
        EXPECT_EQ(x.peakKneeFlexion->flexion, y.peakKneeFlexion->flexion);
        EXPECT_EQ(x.peakKneeFlexion->time, y.peakKneeFlexion->time);
        EXPECT_EQ(x.minToeClearance, y.minToeClearance);
        EXPECT_EQ(x.looseDwellRetries, y.looseDwellRetries);
        ASSERT_EQ(x.events.size(), y.events.size());
        for (std::size_t i = 0; i < x.events.size(); ++i) {
          EXPECT_EQ(x.events[i].name, y.events[i].name);
          EXPECT_EQ(x.events[i].time, y.events[i].time) << x.events[i].name;
        }
        // The first stop contact after the last entry: its impact is decided before the
        // early end. Its deepest point may not be: the early end may come while the hip
        // moment still changes (HipMomentProfile::calcRangeFrom), and a knee resting on its
        // stop can then be pressed a little deeper later in the same contact (P4 at 0.19 m:
        // 3.358 against 3.368 mrad). simulate and the terminal impact check, which report
        // the penetration, integrate the whole dwell.
        ASSERT_EQ(x.impacts.empty(), y.impacts.empty());
        if (!x.impacts.empty()) {
          EXPECT_EQ(x.impacts.front().impactRate, y.impacts.front().impactRate);
          EXPECT_LE(x.impacts.front().maxPenetration, y.impacts.front().maxPenetration);
          EXPECT_GT(x.impacts.front().maxPenetration, 0.99 * y.impacts.front().maxPenetration);
        }
        EXPECT_LE(x.endDecidedTime, y.endDecidedTime);
        EXPECT_LE(x.realizations, y.realizations);
      }
    }
    std::printf("early settle end, knee %s: %d swings, %d ended early; realizations %ld -> %ld\n", v.name, swings,
                endedEarly, realizationsFull, realizationsEarly);
    // And it is a lever where the knee comes to rest on its stop: on the published knees
    // (no bounce) most swings end early (not asserting a speed, only that it acts).
    if (v.restitution < 0) {
      EXPECT_GT(endedEarly, swings / 2) << v.name;
    }
  }
  EXPECT_GT(bouncing, 10) << "the bouncy variants must bounce";
}

// The same on the Monte Carlo's own variants (sweep_uncertainty.h): hip half-sines of
// 0.15-0.25 s, so the early end is often decided while the extension moment still acts
// (HipMomentProfile::calcRangeFrom), stops 1.25e4-5e4 N m/rad^1.5 with restitution 0.3-0.5,
// friction 5-15 N m, dwells of 0.10-0.20 s, every lowering.
TEST(SettleDwell, EarlyEndGivesTheFullDwellsSwingOnTheMonteCarloVariants) {
  int compared = 0, endedEarly = 0, beforeHipConstant = 0;
  testing::compareMonteCarloSwings(
      4, 11, [](SwingOptions& o) { o.earlySettleEnd = false; },
      [&](const PlannedSwing& planned, const Outcome& a, const Outcome& b) {
        ASSERT_EQ(a.ok, b.ok) << a.failure << " | " << b.failure;
        if (!a.ok) return;
        ++compared;
        const SwingResult &x = a.result, &y = b.result;
        if (x.endDecidedTime < y.endDecidedTime) {
          ++endedEarly;
          const std::vector<double> kinks = planned.participant.hipMoment.calcBreakpoints();
          beforeHipConstant += !kinks.empty() && x.endDecidedTime < kinks.back();
        }
        EXPECT_EQ(x.swingTime, y.swingTime);
        EXPECT_EQ(x.bounces, y.bounces);
        EXPECT_EQ(x.bounceHeight, y.bounceHeight);
        ASSERT_EQ(x.events.size(), y.events.size());
        for (std::size_t i = 0; i < x.events.size(); ++i)
          EXPECT_EQ(x.events[i].time, y.events[i].time) << x.events[i].name;
      });
  std::printf("Monte Carlo variants: %d swings ended, %d ended early, %d of them before the hip moment was constant\n",
              compared, endedEarly, beforeHipConstant);
  EXPECT_GT(compared, 100);
  EXPECT_GT(endedEarly, compared / 2);
  EXPECT_GT(beforeHipConstant, 0);
}

// Off (the full dwell) the end is decided at the swing end plus the dwell, as before.
TEST(SettleDwell, FullDwellIsDecidedOneDwellAfterTheSwingEnd) {
  const Participant p = loadParticipant("participants/p1.yaml");
  const auto knee = std::make_shared<const KneeLawSum>(makeKneeLaw(p, loadKneeModel(p.kneeModelPath)));
  SwingSetup setup = makeSwingSetup(p, knee);
  SwingOptions full;
  full.earlySettleEnd = false;
  const SwingResult r = simulateSwing(setup, full);
  EXPECT_GE(r.endDecidedTime, r.swingTime + p.swingEnd.settleDwell);
  const SwingResult e = simulateSwing(setup);
  EXPECT_LT(e.endDecidedTime, r.endDecidedTime) << "P1 at the standard location rests on its stop well before";
  EXPECT_GT(e.endDecidedTime, e.swingTime);
}

}  // namespace
}  // namespace swingsim
