// What is read between two step ends (swing/step_end.h): the cubic Hermite interpolant is
// exact on cubics, and findRoot finds a root known in closed form.
#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace swingsim
