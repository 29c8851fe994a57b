#include "numerics/sample_derivative.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace swingsim {

namespace {

// Round-off of a difference quotient of O(1) values over steps of ~0.1.
constexpr double kRoundOff = 1e-12;

TEST(SampleDerivative, ExactForAQuadraticOnAnUnevenGridInside) {
  // The three-point formula on an uneven grid is exact for any quadratic:
  // x = 3 t^2 - 2 t + 1, x' = 6 t - 2.
  const std::vector<double> t = {0.0, 0.1, 0.25, 0.3, 0.6, 0.65, 1.0};
  std::vector<double> x;
  for (double s : t) x.push_back(3 * s * s - 2 * s + 1);
  const auto v = estimatePistonVelocity(t, x);
  ASSERT_EQ(v.size(), t.size());
  for (std::size_t i = 1; i + 1 < t.size(); ++i) EXPECT_NEAR(v[i], 6 * t[i] - 2, kRoundOff) << "i=" << i;
}

TEST(SampleDerivative, EndsAreOneSidedSecants) {
  const std::vector<double> t = {0.0, 0.1, 0.25, 0.3};
  const std::vector<double> x = {1.0, 2.0, 2.5, 4.0};
  const auto v = estimatePistonVelocity(t, x);
  EXPECT_NEAR(v.front(), (2.0 - 1.0) / 0.1, kRoundOff);
  EXPECT_NEAR(v.back(), (4.0 - 2.5) / 0.05, kRoundOff);
}

TEST(SampleDerivative, SecondOrderOnASine) {
  // The error of the central difference falls as h^2: halving the step quarters it.
  auto maxError = [](int n) {
    std::vector<double> t, x;
    for (int i = 0; i <= n; ++i) {
      t.push_back(static_cast<double>(i) / n);
      x.push_back(std::sin(3 * t.back()));
    }
    const auto v = estimatePistonVelocity(t, x);
    double e = 0;
    for (int i = 1; i < n; ++i)
      e = std::max(e, std::fabs(v[static_cast<std::size_t>(i)] - 3 * std::cos(3 * t[static_cast<std::size_t>(i)])));
    return e;
  };
  const double ratio = maxError(50) / maxError(100);
  constexpr double kSecondOrderLow = 3.5, kSecondOrderHigh = 4.5;  // 4 for an h^2 error, first order would give 2
  EXPECT_GT(ratio, kSecondOrderLow);
  EXPECT_LT(ratio, kSecondOrderHigh);
}

TEST(SampleDerivative, TooFewSamplesGiveZeros) {
  EXPECT_TRUE(estimatePistonVelocity({}, {}).empty());
  EXPECT_EQ(estimatePistonVelocity({0.5}, {2.0}), std::vector<double>{0.0});
}

}  // namespace
}  // namespace swingsim
