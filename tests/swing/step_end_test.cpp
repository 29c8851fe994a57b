// What is read between two step ends (swing/step_end.h): the cubic Hermite interpolant is
// exact on cubics, findRoot finds a root known in closed form, and findKneeRisingAbove finds
// a knee passing a level at the step end or only inside the step.
#include <gtest/gtest.h>

#include <cmath>

#include "core/units.h"
#include "swing/step_end.h"

namespace swingsim {
namespace {

constexpr double kRoundOff = 1e-12;  // a cubic reproduced exactly, to round-off

TEST(StepEnd, HermiteIsExactOnACubic) {
  auto y = [](double t) { return 1 + 2 * t - 3 * t * t + 0.5 * t * t * t; };
  auto dy = [](double t) { return 2 - 6 * t + 1.5 * t * t; };
  const double t0 = 0.2, h = 0.3;
  for (double s : {0.0, 0.25, 0.5, 0.9, 1.0})
    EXPECT_NEAR(calcHermite(y(t0), dy(t0), y(t0 + h), dy(t0 + h), h, s), y(t0 + s * h), kRoundOff) << s;
}

TEST(StepEnd, FindRootFindsTheRootToTheTimeResolution) {
  const double h = 0.01;  // s
  // cos(pi s / 1.4) - 0.5 = 0 at s = 1.4 / 3.
  const double s = findRoot([](double x) { return std::cos(M_PI * x / 1.4) - 0.5; }, h);
  EXPECT_NEAR(s * h, 1.4 / 3 * h, 10 * kCrossingTimeTol);
}

// A step end with the knee at `knee` (rad) moving at `rate` (rad/s), accelerating at `acc`.
StepEnd kneeAt(double t, double knee, double rate, double acc) {
  StepEnd e{};
  e.t = t;
  e.knee = knee;
  e.kneeRate = rate;
  e.kneeAcc = acc;
  return e;
}

TEST(StepEnd, KneeRisingAboveALevelIsFoundWhereItCrosses) {
  // knee(t) = 3 + 10 (t - 0.1) on [0.1, 0.2]: a line, reproduced exactly; crosses pi at
  // t = 0.1 + (pi - 3) / 10.
  const auto crossing = findKneeRisingAbove(kneeAt(0.1, 3.0, 10, 0), kneeAt(0.2, 4.0, 10, 0), kPi);
  ASSERT_TRUE(crossing);
  EXPECT_NEAR(*crossing, 0.1 + (kPi - 3) / 10, 10 * kCrossingTimeTol);
}

TEST(StepEnd, KneeAboveALevelOnlyInsideTheStepIsFound) {
  // knee(t) = 3.2 - 10 (t - 0.15)^2 on [0.1, 0.2]: 3.175 at both ends, top 3.2 at 0.15;
  // above 3.19 from 0.15 - sqrt(0.001).
  auto knee = [](double t) { return 3.2 - 10 * (t - 0.15) * (t - 0.15); };
  auto rate = [](double t) { return -20 * (t - 0.15); };
  const StepEnd a = kneeAt(0.1, knee(0.1), rate(0.1), -20), b = kneeAt(0.2, knee(0.2), rate(0.2), -20);
  const auto crossing = findKneeRisingAbove(a, b, 3.19);
  ASSERT_TRUE(crossing);
  EXPECT_NEAR(*crossing, 0.15 - std::sqrt(0.001), 10 * kCrossingTimeTol);
  EXPECT_FALSE(findKneeRisingAbove(a, b, 3.21));  // its top stays below
}

TEST(StepEnd, KneeBelowALevelHasNoCrossing) {
  EXPECT_FALSE(findKneeRisingAbove(kneeAt(0.1, 1.0, 5, 0), kneeAt(0.2, 1.5, 5, 0), kPi));
  EXPECT_FALSE(findKneeRisingAbove(kneeAt(0.1, 1.5, -5, 0), kneeAt(0.2, 1.0, -5, 0), kPi));
}

}  // namespace
}  // namespace swingsim
