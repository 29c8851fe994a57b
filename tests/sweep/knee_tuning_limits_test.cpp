// The tuning engine (sweep/knee_tuning.h) where a hard limit is active at the result: the
// soft targets' optimum lies outside the limit, so the result must slide along the limit to
// the constrained optimum, which these closed-form "swings" give exactly (Lagrange
// conditions on a linear and on a circular limit; a narrow window no start point hits).
#include "sweep/knee_tuning.h"

#include <gtest/gtest.h>

#include <cmath>

#include "closed_form_swing.h"
#include "core/units.h"
#include "sweep/tuning_analysis.h"

namespace swingsim {
namespace {

using Fake = ClosedFormSwing;

TuningTarget softValue(TuningQuantity q, double v, double weight) {
  TuningTarget t;
  t.quantity = q;
  t.lower = t.upper = v;
  t.weight = weight;
  t.scale = tuningTargetScale(q);
  return t;
}

TuningTarget hardWindow(TuningQuantity q, double lower, double upper) {
  TuningTarget t;
  t.quantity = q;
  t.lower = lower;
  t.upper = upper;
  t.hard = true;
  t.scale = tuningTargetScale(q);
  return t;
}

const std::vector<TuningKnob> kUnitKnobs = {{"a", 0, 1, false}, {"b", 0, 1, false}};
const double kDeg = kDegToRad;

// The result meets the limit and sits on it: its margin is at most the polish's inside band
// (kHardLimitInside scale units) plus 1 % of that band for the difference steps' round-off.
void expectOnTheLimit(const TuningResult& r, std::size_t target) {
  ASSERT_TRUE(r.feasible);
  const TargetOutcome& limit = r.targets.at(target);
  EXPECT_GE(limit.margin, 0.0);
  EXPECT_LE(limit.margin, 1.01 * kHardLimitInside * limit.target.scale);
  EXPECT_TRUE(limit.binding);
}

TEST(KneeTuningLimits, ALinearLimitIsFollowedToTheConstrainedOptimum) {
  // Soft: T = 0.4 + 0.1 a toward 0.48 (a = 0.8; 10 scale units per unit of a, weight 1) and
  // P = 1 rad + 10 deg * b toward 1 rad + 8 deg (b = 0.8; 10 units per unit of b, weight 4):
  // cost 100 (a - 0.8)^2 + 400 (b - 0.8)^2. Hard: clearance 0.1 - 0.05 (a + b) >= 0.03, i.e.
  // a + b <= 1.4, which (0.8, 0.8) breaks. On the limit, 100 (a - 0.8) = 400 (b - 0.8) with
  // a + b = 1.4: a = 0.8 - 0.2 * 400 / 500 = 0.64, b = 0.8 - 0.2 * 100 / 500 = 0.76.
  const Fake f{[](double a, double) { return 0.4 + 0.1 * a; }, [](double, double b) { return 1.0 + 10 * kDeg * b; },
               [](double a, double b) { return 0.1 - 0.05 * (a + b); }};
  const std::vector<TuningTarget> targets = {softValue(TuningQuantity::kSwingTime, 0.48, 1),
                                             softValue(TuningQuantity::kPeakKneeFlexion, 1.0 + 8 * kDeg, 4),
                                             hardWindow(TuningQuantity::kMinToeClearance, 0.03, INFINITY)};
  const TuningResult r = runKneeTuning(kUnitKnobs, targets, makeEvaluator(f), {});
  expectOnTheLimit(r, 2);
  // The inside band (kHardLimitInside x 5 mm = 5e-5 m of clearance) moves a + b by 1e-3 at
  // most, and the optimum along the limit by 0.8 of that: 1e-3 on each knob.
  constexpr double kKnobTol = 1e-3;
  EXPECT_NEAR(r.best.knobs[0], 0.64, kKnobTol);
  EXPECT_NEAR(r.best.knobs[1], 0.76, kKnobTol);
  EXPECT_FALSE(r.targets[0].met);  // both soft targets give way to the limit
  EXPECT_FALSE(r.targets[1].met);
}

TEST(KneeTuningLimits, ACurvedLimitIsFollowedToTheConstrainedOptimum) {
  // Soft: a toward 0.9 and b toward 0.9 with equal costs (10 scale units per unit of each);
  // hard: clearance 0.1 - 0.05 (a^2 + b^2) >= 0.068, the disc a^2 + b^2 <= 0.64. The closest
  // point of the disc to (0.9, 0.9): its radial projection, 0.8 / sqrt(2) on each knob.
  const Fake f{[](double a, double) { return 0.4 + 0.1 * a; }, [](double, double b) { return 1.0 + 10 * kDeg * b; },
               [](double a, double b) { return 0.1 - 0.05 * (a * a + b * b); }};
  const std::vector<TuningTarget> targets = {softValue(TuningQuantity::kSwingTime, 0.49, 1),
                                             softValue(TuningQuantity::kPeakKneeFlexion, 1.0 + 9 * kDeg, 1),
                                             hardWindow(TuningQuantity::kMinToeClearance, 0.068, INFINITY)};
  const TuningResult r = runKneeTuning(kUnitKnobs, targets, makeEvaluator(f), {});
  expectOnTheLimit(r, 2);
  // The inside band (5e-5 m of clearance) shrinks the radius by 5e-5 / (0.05 * 2 * 0.8) = 6e-4.
  constexpr double kKnobTol = 1e-3;
  const double optimum = 0.8 / std::sqrt(2.0);
  EXPECT_NEAR(r.best.knobs[0], optimum, kKnobTol);
  EXPECT_NEAR(r.best.knobs[1], optimum, kKnobTol);
}

TEST(KneeTuningLimits, AWindowNoStartPointHitsIsFoundAndItsSoftOptimumTaken) {
  // Hard: peak flexion in [1 rad + 5 deg, 1 rad + 5.1 deg], i.e. b in [0.50, 0.51], which no
  // point of the 24-point start set hits (checked below). Soft: T = 0.4 + 0.1 a toward 0.47
  // (a = 0.7) and clearance 0.1 + 0.01 b toward 0.109 (b = 0.9, outside the window): the
  // constrained optimum is a = 0.7 on the window's upper edge b = 0.51.
  const Fake f{[](double a, double) { return 0.4 + 0.1 * a; }, [](double, double b) { return 1.0 + 10 * kDeg * b; },
               [](double, double b) { return 0.1 + 0.01 * b; }};
  const std::vector<TuningTarget> targets = {
      softValue(TuningQuantity::kSwingTime, 0.47, 1), softValue(TuningQuantity::kMinToeClearance, 0.109, 1),
      hardWindow(TuningQuantity::kPeakKneeFlexion, 1.0 + 5 * kDeg, 1.0 + 5.1 * kDeg)};
  const TuningResult r = runKneeTuning(kUnitKnobs, targets, makeEvaluator(f), {});
  for (const TuningPoint& p : r.startSet)
    ASSERT_FALSE(p.feasible()) << "a start point hit the window: b = " << p.knobs[1];
  expectOnTheLimit(r, 2);
  // a is free of the limit: the polish meets its target (1 % of a scale unit: 1e-3 of a).
  EXPECT_NEAR(r.best.knobs[0], 0.7, 1e-3);
  // b sits inside the upper edge by at most the inside band (0.01 deg = 1e-3 of b).
  EXPECT_LE(r.best.knobs[1], 0.51);
  EXPECT_GE(r.best.knobs[1], 0.51 - 1.01e-3);
}

TEST(KneeTuningLimits, APolishEndingPastALimitGivesTheBestPointThatMeetsIt) {
  // The linear case with a weak penalty (weight 1): the soft targets pull Ceres' solution past
  // the clearance limit, so the result must be another evaluated point, the best that meets it.
  const Fake f{[](double a, double) { return 0.4 + 0.1 * a; }, [](double, double b) { return 1.0 + 10 * kDeg * b; },
               [](double a, double b) { return 0.1 - 0.05 * (a + b); }};
  const std::vector<TuningTarget> targets = {softValue(TuningQuantity::kSwingTime, 0.48, 1),
                                             softValue(TuningQuantity::kPeakKneeFlexion, 1.0 + 8 * kDeg, 4),
                                             hardWindow(TuningQuantity::kMinToeClearance, 0.03, INFINITY)};
  TuningSettings settings;
  settings.penalty.weight = 1;
  const TuningResult r = runKneeTuning(kUnitKnobs, targets, makeEvaluator(f), settings);
  ASSERT_TRUE(r.polishEnd.ran);
  EXPECT_FALSE(r.polishEnd.feasible());
  ASSERT_TRUE(r.feasible);
  EXPECT_GE(r.targets[2].margin, 0.0);
  for (const auto* set : {&r.startSet, &r.polished})
    for (const TuningPoint& p : *set)
      if (p.feasible()) {
        EXPECT_GE(p.cost, r.best.cost);
      }
}

}  // namespace
}  // namespace swingsim
