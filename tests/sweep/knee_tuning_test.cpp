// The tuning engine (sweep/knee_tuning.h) on swings made by closed-form functions of the
// knobs: what it must recover, report as missed or as a ridge is then known exactly.
#include "sweep/knee_tuning.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "closed_form_swing.h"
#include "sweep/tuning_analysis.h"

namespace swingsim {
namespace {

using Fake = ClosedFormSwing;

TuningTarget valueTarget(TuningQuantity q, double v) {
  TuningTarget t;
  t.quantity = q;
  t.lower = t.upper = v;
  t.scale = tuningTargetScale(q);
  return t;
}

const std::vector<TuningKnob> kKnobs = {{"a", 0, 1, false}, {"b", 0.5, 4, true}};
// Recovered to 1e-4 of each range: the polish converges to ~1e-9 in cost on these smooth functions.
constexpr double kRecoveryTol = 1e-4;

TEST(KneeTuning, RecoversTheSettingsThatMadeTheTargets) {
  const Fake f{[](double a, double b) { return 0.4 + 0.1 * a + 0.03 * b; },
               [](double a, double b) { return 1.0 + 0.3 * a - 0.05 * b; },
               {}};
  const double a = 0.7, b = 2.5;  // truth, away from the range middles
  const auto r = runKneeTuning(kKnobs,
                               {valueTarget(TuningQuantity::kSwingTime, f.time(a, b)),
                                valueTarget(TuningQuantity::kPeakKneeFlexion, f.peak(a, b))},
                               makeEvaluator(f), {});
  ASSERT_TRUE(r.feasible);
  EXPECT_NEAR(r.best.knobs[0], a, kRecoveryTol * 1);
  EXPECT_NEAR(r.best.knobs[1], b, kRecoveryTol * 3.5);
  EXPECT_TRUE(r.identifiable) << r.identifiability;
  for (const auto& o : r.targets) EXPECT_TRUE(o.met);
  // The sensitivity is the functions' own gradient (linear: exact up to round-off).
  EXPECT_NEAR(r.sensitivity(0, 0), 0.1, 1e-6);
  EXPECT_NEAR(r.sensitivity(1, 1), -0.05, 1e-6);
}

TEST(KneeTuning, TwoKnobsOneTargetIsReportedAsARidge) {
  const std::vector<TuningKnob> knobs = {{"a", 0, 1, false}, {"b", 0, 1, false}};
  const Fake f{[](double a, double b) { return 0.4 + 0.1 * (a + b); }, [](double, double) { return 1.0; }, {}};
  const auto r = runKneeTuning(knobs, {valueTarget(TuningQuantity::kSwingTime, 0.5)}, makeEvaluator(f), {});
  ASSERT_TRUE(r.targets.at(0).met);
  EXPECT_NEAR(r.best.knobs[0] + r.best.knobs[1], 1.0, kRecoveryTol);
  EXPECT_FALSE(r.identifiable);
  EXPECT_NE(r.identifiability.find("ridge"), std::string::npos) << r.identifiability;
  // The ridge is a + b = const: direction (1, -1) / sqrt(2) up to its sign.
  ASSERT_EQ(r.ridge.size(), 2u);
  EXPECT_NEAR(r.ridge[0] + r.ridge[1], 0.0, 1e-6);
  EXPECT_NEAR(std::abs(r.ridge[0]), std::sqrt(0.5), 1e-6);
}

TEST(KneeTuning, AHardLimitNoSettingMeetsIsReportedWithItsMiss) {
  // Peak flexion at most 1.3 rad (a = 1); the limit asks for 2 rad: missed by 0.7 rad.
  const Fake f{
      [](double a, double b) { return 0.4 + 0.1 * a + 0.03 * b; }, [](double a, double) { return 1.0 + 0.3 * a; }, {}};
  TuningTarget limit;
  limit.quantity = TuningQuantity::kPeakKneeFlexion;
  limit.lower = 2.0;
  limit.hard = true;
  limit.scale = tuningTargetScale(limit.quantity);
  const auto r = runKneeTuning(kKnobs, {valueTarget(TuningQuantity::kSwingTime, 0.5), limit}, makeEvaluator(f), {});
  EXPECT_FALSE(r.feasible);
  ASSERT_EQ(r.targets.size(), 2u);
  EXPECT_FALSE(r.targets[1].met);
  // The polish stops within kAtBoundFraction of a's range end: 1e-4 x 0.3 rad of peak flexion.
  EXPECT_NEAR(r.targets[1].margin, -0.7, kAtBoundFraction * 0.3 * 1.01);
  EXPECT_TRUE(r.knobAtBound[0]);  // a at its upper end is what stops it
  EXPECT_NEAR(r.best.knobs[0], 1.0, kRecoveryTol);
}

TEST(KneeTuning, ASoftTargetOutOfReachIsMissedAtTheRangeEnds) {
  // Swing time at least 0.4 + 0.03 * 0.5 = 0.415 s (a = 0, b = 0.5); asked 0.3 s.
  const Fake f{[](double a, double b) { return 0.4 + 0.1 * a + 0.03 * b; }, [](double, double) { return 1.0; }, {}};
  const auto r = runKneeTuning(kKnobs, {valueTarget(TuningQuantity::kSwingTime, 0.3)}, makeEvaluator(f), {});
  ASSERT_TRUE(r.feasible);
  EXPECT_FALSE(r.targets[0].met);
  EXPECT_NEAR(r.targets[0].margin, -(0.415 - 0.3), 1e-6);
  EXPECT_TRUE(r.knobAtBound[0]);
  EXPECT_TRUE(r.knobAtBound[1]);
}

TEST(KneeTuning, AHardLimitBindsWhereTheSoftOptimumBreaksIt) {
  // Alone, the swing-time target wants a = 1 (T = 0.5 at b = 0.5... 4); the clearance limit
  // 0.1 - 0.08 a >= 0.05 stops a at 0.625: the limit binds there.
  const Fake f{[](double a, double) { return 0.4 + 0.1 * a; }, [](double, double) { return 1.0; },
               [](double a, double) { return 0.1 - 0.08 * a; }};
  TuningTarget limit;
  limit.quantity = TuningQuantity::kMinToeClearance;
  limit.lower = 0.05;
  limit.hard = true;
  limit.scale = tuningTargetScale(limit.quantity);
  const auto r = runKneeTuning(kKnobs, {valueTarget(TuningQuantity::kSwingTime, 0.5), limit}, makeEvaluator(f), {});
  ASSERT_TRUE(r.feasible);
  EXPECT_GE(r.targets[1].margin, 0.0);  // never a result that breaks a hard limit
  // On the limit: at most the polish's inside margin (kHardLimitInside scale units, 50 um,
  // a = 0.6244) from the edge, and 1 % of that for round-off.
  EXPECT_LE(r.targets[1].margin, 1.01 * kHardLimitInside * limit.scale);
  EXPECT_GE(r.best.knobs[0], 0.625 - 1.01 * kHardLimitInside * limit.scale / 0.08);
  EXPECT_TRUE(r.targets[1].binding);
  EXPECT_FALSE(r.targets[0].met);
}

TEST(KneeTuning, AgreesWithAFineGridSearchOnTwoKnobs) {
  // A curved valley with its minimum inside the box: cost (T - 0.45)^2 / 0.01^2 + (P - 1.1)^2 / (1 deg)^2.
  const std::vector<TuningKnob> knobs = {{"a", 0, 1, false}, {"b", 0, 1, false}};
  const Fake f{[](double a, double b) { return 0.4 + 0.08 * a * a + 0.05 * b; },
               [](double a, double b) { return 1.0 + 0.2 * a - 0.1 * b * b + 0.1 * a * b; },
               {}};
  const std::vector<TuningTarget> targets = {valueTarget(TuningQuantity::kSwingTime, 0.45),
                                             valueTarget(TuningQuantity::kPeakKneeFlexion, 1.1)};
  const auto r = runKneeTuning(knobs, targets, makeEvaluator(f), {});
  const int n = 400;
  const double step = 1.0 / n;
  double bestCost = 1e300, ga = 0, gb = 0;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      TuningPoint p;
      p.knobs = {i * step, j * step};
      scoreTuningPoint(p, makeEvaluator(f)(p.knobs), targets);
      if (p.cost < bestCost) bestCost = p.cost, ga = p.knobs[0], gb = p.knobs[1];
    }
  EXPECT_NEAR(r.best.knobs[0], ga, step);
  EXPECT_NEAR(r.best.knobs[1], gb, step);
  EXPECT_LE(r.best.cost, bestCost + 1e-9);  // the polish is at least as good as the grid
}

TEST(KneeTuning, TheSameSeedGivesTheSameResultOnAnyThreadCount) {
  const Fake f{[](double a, double b) { return 0.4 + 0.1 * a + 0.03 * b; },
               [](double a, double b) { return 1.0 + 0.3 * a - 0.05 * b; },
               {}};
  const std::vector<TuningTarget> targets = {valueTarget(TuningQuantity::kSwingTime, 0.5)};
  TuningSettings one, two;
  one.jobs = 1;
  two.jobs = 2;
  const auto r1 = runKneeTuning(kKnobs, targets, makeEvaluator(f), one);
  const auto r2 = runKneeTuning(kKnobs, targets, makeEvaluator(f), two);
  ASSERT_EQ(r1.startSet.size(), r2.startSet.size());
  for (std::size_t i = 0; i < r1.startSet.size(); ++i) EXPECT_EQ(r1.startSet[i].knobs, r2.startSet[i].knobs);
  EXPECT_EQ(r1.best.knobs, r2.best.knobs);
}

TEST(KneeTuning, TheStopFlagEndsTheRunWithTheBestPointSoFar) {
  volatile bool stop = false;
  std::atomic<int> calls{0};
  const Fake f{[](double a, double b) { return 0.4 + 0.1 * a + 0.03 * b; }, [](double, double) { return 1.0; }, {}};
  const TuningEvaluator inner = makeEvaluator(f);
  const TuningEvaluator evaluate = [&](const std::vector<double>& x) {
    if (++calls >= 5) stop = true;
    return inner(x);
  };
  TuningSettings s;
  s.jobs = 1;
  const auto r = runKneeTuning(kKnobs, {valueTarget(TuningQuantity::kSwingTime, 0.5)}, evaluate, s, {}, &stop);
  EXPECT_TRUE(r.interrupted);
  EXPECT_LT(r.startSet.size(), 24u);
  EXPECT_TRUE(r.polished.empty());
  EXPECT_TRUE(r.best.ran);
  EXPECT_TRUE(r.targets.empty());  // no analysis of an interrupted run
}

}  // namespace
}  // namespace swingsim

namespace swingsim {
namespace {

// A measured record that ends inside the settle dwell (the knee resting in the zone with the
// thigh at its target) still gives a swing time: the entry into the zone, flagged; one that
// ends with the knee still flexed is a failed point that says why.
TEST(KneeTuning, ARecordEndingInsideTheSettleDwellGivesTheEntryAsTheSwingEnd) {
  const std::vector<TuningTarget> targets = {{TuningQuantity::kSwingTime, 0.4, 0.4, false, 1, 0.01}};
  SwingResult swing;
  swing.swingTime = std::numeric_limits<double>::quiet_NaN();
  swing.trialEnd = TrialEnd{"settle_dwell", 0.386, 0.05, 0.3, 0.5, 0.35, 0.1, 0.040, 0.15};
  TuningPoint p;
  scoreTuningPoint(p, swing, targets);
  EXPECT_TRUE(p.ran);
  EXPECT_TRUE(p.dwellCutByRecord);
  EXPECT_NEAR(p.swingTime, 0.386 - 0.040, 1e-12);

  swing.trialEnd = TrialEnd{"knee_zone", 0.386, 0.4, 0.3, 0.5, 0.35, 0.1, std::nullopt, 0.15};
  TuningPoint q;
  scoreTuningPoint(q, swing, targets);
  EXPECT_FALSE(q.ran);
  EXPECT_FALSE(q.dwellCutByRecord);
  EXPECT_NE(q.failure.find("the swing has no swing_time_s (the measured trial ended at 0.386 s"), std::string::npos)
      << q.failure;
}

}  // namespace
}  // namespace swingsim
