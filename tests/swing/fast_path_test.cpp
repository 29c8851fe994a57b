// Correctness guard of the fast path (docs/speed.md): swing events found between integrator
// steps on the Hermite interpolant, at the converged default accuracy, against the plain
// path (Simbody event handlers localizing every crossing) at a tight accuracy, for every
// participant and every lowering of the Burkett sweep.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "knee/joint_stop.h"
#include "study/sweep_study.h"
#include "sweep/sweep.h"
#include "swing/knee_setup.h"
#include "swing/swing_simulation.h"

namespace swingsim {
namespace {

constexpr double kConvergedTol = 1e-4;      // s: the swing time the README's convergence study converges to 0.1 ms
constexpr double kTightAccuracy = 1e-8;     // plain path: integration error far below kConvergedTol
constexpr double kTightEventWindow = 1e-9;  // s: plain path localization window

// A bundled participant with its own knee, and swing setups that point at that knee.
struct Bundled {
  Participant participant;
  std::shared_ptr<const KneeLawSum> knee;
  explicit Bundled(const char* file)
      : participant(loadParticipant(file)),
        knee(std::make_shared<const KneeLawSum>(makeKneeLaw(participant, loadKneeModel(participant.kneeModelPath)))) {}
  SwingSetup setup() const { return makeSwingSetup(participant, knee); }
};

SweepStudy burkettStudy(const SwingOptions& swing) {
  SweepStudy s = loadSweepStudy("studies/burkett2004.yaml");
  s.addedMasses = {0.0};  // the plain sweep, with Table 4's off-grid lowerings
  s.addedMassDistances.clear();
  s.swing = swing;
  s.swing.recordTrajectory = false;
  return s;
}

TEST(FastPath, SameSwingTimesAsThePlainPathForAllParticipantsAndLowerings) {
  const SweepResults fast = runSweep(burkettStudy(SwingOptions{}), 0);
  const SwingOptions plainOptions = makePlainPathOptions(kTightAccuracy, kTightEventWindow);
  const SweepResults plain = runSweep(burkettStudy(plainOptions), 0);

  ASSERT_EQ(fast.participants.size(), plain.participants.size());
  double maxDiff = 0;
  int compared = 0;
  for (std::size_t i = 0; i < fast.participants.size(); ++i) {
    const ParticipantSweep& f = fast.participants[i];
    const ParticipantSweep& p = plain.participants[i];
    ASSERT_EQ(f.points.size(), p.points.size()) << f.name;
    for (std::size_t k = 0; k < f.points.size(); ++k) {
      const SweepPoint& a = f.points[k];
      const SweepPoint& b = p.points[k];
      ASSERT_EQ(a.ok, b.ok) << f.name << " at " << a.lowering << " m: " << a.failure << b.failure;
      if (!a.ok) continue;
      const double diff = std::fabs(a.result.swingTime - b.result.swingTime);
      maxDiff = std::max(maxDiff, diff);
      ++compared;
      EXPECT_LT(diff, kConvergedTol) << f.name << " at " << a.lowering << " m";
      EXPECT_EQ(a.result.bounce, b.result.bounce) << f.name << " at " << a.lowering << " m";
      ASSERT_TRUE(a.result.peakKneeFlexion && b.result.peakKneeFlexion) << f.name << " at " << a.lowering;
      EXPECT_NEAR(a.result.peakKneeFlexion->time, b.result.peakKneeFlexion->time, kConvergedTol)
          << f.name << " at " << a.lowering;
    }
    EXPECT_EQ(f.best, p.best) << f.name;
  }
  std::printf("fast vs plain path: %d swings, largest swing time difference %.2e s (tolerance %.0e s)\n", compared,
              maxDiff, kConvergedTol);
}

// The counters say where a swing's realizations go: up to the step where the knee entered
// the zone for the last time, then the settle dwell that confirms the end.
TEST(FastPath, RealizationCountersSplitTheSwingFromTheSettleDwell) {
  const Bundled p1("participants/p1.yaml");
  SwingSetup setup = p1.setup();
  for (const SwingOptions& o : {SwingOptions{}, makeSimbodyIntegratorOptions(), makePlainPathOptions(1e-4, 1e-5)}) {
    const SwingResult r = simulateSwing(setup, o);
    EXPECT_GT(r.realizationsToEnd, 50) << integratorName(o.integrator);
    EXPECT_LT(r.realizationsToEnd, r.realizations) << integratorName(o.integrator) << ": the dwell costs some";
    EXPECT_GT(r.steps, 10);
    EXPECT_EQ(r.looseDwellRetries, 0) << "P1 does not bounce";
  }
  // No dwell at all: everything is to the end.
  setup.participant.swingEnd.settleDwell = 0;
  const SwingResult r = simulateSwing(setup);
  EXPECT_EQ(r.realizationsToEnd, r.realizations);
}

// At the same tight accuracy the two ways of finding events agree far below the tolerance:
// the Hermite crossing search is not where the fast path's error comes from.
TEST(FastPath, EventSearchAgreesWithSimbodyLocalizationAtTightAccuracy) {
  constexpr double kEventAgreement = 1e-7;  // s: both integrate to 1e-10; what is left is localization
  SweepStudy study = burkettStudy(SwingOptions{});
  study.participants.resize(1);
  study.loweringStep = 0.1;
  study.includePublishedLowerings = false;
  SwingOptions fastOptions;
  fastOptions.integrator = SwingIntegrator::kRungeKuttaMerson;  // the same integrator: only the event search differs
  fastOptions.accuracy = 1e-10;
  const SwingOptions plainOptions = makePlainPathOptions(1e-10, kTightEventWindow);
  study.swing = fastOptions;
  const SweepResults fast = runSweep(study, 0);
  study.swing = plainOptions;
  const SweepResults plain = runSweep(study, 0);
  for (std::size_t k = 0; k < fast.participants[0].points.size(); ++k) {
    const SwingResult& a = fast.participants[0].points[k].result;
    const SwingResult& b = plain.participants[0].points[k].result;
    EXPECT_NEAR(a.swingTime, b.swingTime, kEventAgreement);
    ASSERT_TRUE(a.peakKneeFlexion && b.peakKneeFlexion);
    EXPECT_NEAR(a.peakKneeFlexion->flexion, b.peakKneeFlexion->flexion, 1e-7);
  }
}

// P4 at 0.140 m with 1 kg 0.10 m below the knee: the thigh peaks 0.015 deg above its
// 20 deg target, up and back down within one integrator step. Sign changes at step ends
// alone miss that crossing (the swing then "ends" 41 ms later, at the thigh's second
// rise); the fast path checks the interpolated extremum.
TEST(FastPath, ThighGrazingItsTargetWithinOneStepIsStillFound) {
  const Bundled p4("participants/p4.yaml");
  SwingSetup setup = p4.setup();
  setup.lowering = 0.140;
  setup.added = {1.0, 0.10};
  const SwingOptions plainOptions = makePlainPathOptions(kTightAccuracy, kTightEventWindow);
  const SwingResult plain = simulateSwing(setup, plainOptions);
  // The default accuracy and tighter ones (different step placements, same crossing).
  for (double accuracy : {SwingOptions{}.accuracy, 3e-6, 1e-6}) {
    SwingOptions fastOptions;
    fastOptions.accuracy = accuracy;
    EXPECT_NEAR(simulateSwing(setup, fastOptions).swingTime, plain.swingTime, kConvergedTol) << accuracy;
  }
}

// The bounce flag, the bounce count and the settle rule are checked on knees that bounce:
// the participant's knee model without the knee friction near extension (which takes the
// rebound's energy: README "Terminal impact"), at two restitutions.
TEST(FastPath, BounceFlagAndEventsAgreeWithThePlainPathOnAKneeThatBounces) {
  for (const char* file : {"participants/p1.yaml", "participants/p3.yaml"}) {
    Participant p = loadParticipant(file);
    p.kneeFriction = 0;
    for (double restitution : {0.4, 0.6}) {
      KneeModel model = loadKneeModel(p.kneeModelPath);
      model.spec.stop.restitution = restitution;
      const SwingSetup setup =
          makeSwingSetup(p, KneeModel{model.path, model.name, makeKneeModelLaw(model.spec), model.spec});
      const SwingOptions plainOptions = makePlainPathOptions(kTightAccuracy, kTightEventWindow);
      const SwingResult fast = simulateSwing(setup);
      const SwingResult plain = simulateSwing(setup, plainOptions);
      EXPECT_TRUE(plain.bounce) << file;
      EXPECT_EQ(fast.bounce, plain.bounce) << file;
      EXPECT_EQ(fast.bounces, plain.bounces) << file;
      // The fast path began the settle dwell loosely and went back for the bounce.
      EXPECT_GE(fast.looseDwellRetries, 1) << file;
      EXPECT_NEAR(fast.swingTime, plain.swingTime, kConvergedTol) << file;
      ASSERT_EQ(fast.events.size(), plain.events.size()) << file;
      for (std::size_t i = 0; i < fast.events.size(); ++i) {
        EXPECT_EQ(fast.events[i].name, plain.events[i].name) << file;
        EXPECT_NEAR(fast.events[i].time, plain.events[i].time, kConvergedTol) << file << " " << fast.events[i].name;
      }
    }
  }
}

}  // namespace
}  // namespace swingsim
