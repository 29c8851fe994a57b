#include "numerics/monotone_cubic.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace swingsim {
namespace {

// Arithmetic round-off of a few operations on O(1) values.
constexpr double kRoundOff = 1e-12;

TEST(MonotoneCubic, PassesThroughTheSamplesAndHoldsTheEnds) {
  const std::vector<double> x = {0, 1, 2.5, 4}, y = {1, 3, 2, 5};
  for (auto ends : {MonotoneCubicEnds::kSecant, MonotoneCubicEnds::kFlat}) {
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(interpolateMonotoneCubic(x, y, x[i], ends), y[i], kRoundOff);
    EXPECT_EQ(interpolateMonotoneCubic(x, y, -3.0, ends), 1.0);
    EXPECT_EQ(interpolateMonotoneCubic(x, y, 9.0, ends), 5.0);
  }
}

TEST(MonotoneCubic, ReproducesAStraightLine) {
  // Every secant is 2: the harmonic-mean slopes are 2 and the cubic is the line itself.
  const std::vector<double> x = {0, 0.5, 2, 3}, y = {1, 2, 5, 7};
  for (double t = 0; t <= 3; t += 0.125)
    EXPECT_NEAR(interpolateMonotoneCubic(x, y, t, MonotoneCubicEnds::kSecant), 1 + 2 * t, kRoundOff) << "t=" << t;
}

TEST(MonotoneCubic, NeverOvershootsMonotoneData) {
  // A step-like rise, where an ordinary cubic spline overshoots above 10 and below 0.
  const std::vector<double> x = {0, 1, 2, 3, 4, 5}, y = {0, 0, 0.1, 9.9, 10, 10};
  for (auto ends : {MonotoneCubicEnds::kSecant, MonotoneCubicEnds::kFlat}) {
    double previous = -1;
    for (double t = 0; t <= 5; t += 0.01) {
      const double v = interpolateMonotoneCubic(x, y, t, ends);
      EXPECT_GE(v, -kRoundOff);
      EXPECT_LE(v, 10.0 + kRoundOff);
      EXPECT_GE(v, previous - kRoundOff) << "falls at t=" << t;
      previous = v;
    }
  }
}

TEST(MonotoneCubic, FlatEndsHaveZeroSlopeSecantEndsDoNot) {
  const std::vector<double> x = {0, 1, 2}, y = {0, 1, 4};
  constexpr double kStep = 1e-6;  // one-sided difference near the first sample
  const double flat = (interpolateMonotoneCubic(x, y, kStep, MonotoneCubicEnds::kFlat) - 0) / kStep;
  const double secant = (interpolateMonotoneCubic(x, y, kStep, MonotoneCubicEnds::kSecant) - 0) / kStep;
  constexpr double kSlopeTol = 1e-4;  // the difference quotient's error, O(kStep x curvature)
  EXPECT_NEAR(flat, 0.0, kSlopeTol);
  EXPECT_NEAR(secant, 1.0, kSlopeTol);  // the first secant, (1 - 0) / (1 - 0)
}

}  // namespace
}  // namespace swingsim
