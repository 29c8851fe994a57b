#include "numerics/local_polynomial.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace swingsim {
namespace {

// A cubic is its own local cubic: value, rate and acceleration exact on an uneven grid; NaN
// where the window leaves the record.
TEST(LocalPolynomial, ACubicIsReproducedExactly) {
  std::vector<double> t, y;
  for (int i = 0; i < 200; ++i) {
    const double ti = 0.002 * i + 0.0005 * std::sin(i);  // uneven
    t.push_back(ti);
    y.push_back(1.0 - 2.0 * ti + 3.0 * ti * ti - 4.0 * ti * ti * ti);
  }
  const LocalPolynomialFit f = fitLocalPolynomial(t, y, 0.03);
  EXPECT_TRUE(std::isnan(f.acceleration.front()));
  EXPECT_TRUE(std::isnan(f.acceleration.back()));
  for (std::size_t i = 20; i < 180; ++i) {
    EXPECT_NEAR(f.value[i], y[i], 1e-9);
    EXPECT_NEAR(f.rate[i], -2.0 + 6.0 * t[i] - 12.0 * t[i] * t[i], 1e-7);
    EXPECT_NEAR(f.acceleration[i], 6.0 - 24.0 * t[i], 1e-5);
  }
}

// The gains are the noise's standard deviation per unit of the samples' noise, and the weights
// are the filter: checked against 2000 noisy copies.
TEST(LocalPolynomial, GainsAndWeightsAreTheNoisesPath) {
  std::vector<double> t;
  for (int i = 0; i < 100; ++i) t.push_back(0.002 * i);
  std::mt19937_64 e(5);
  std::normal_distribution<double> noise(0.0, 1.0);
  const std::size_t at = 50;
  double sum = 0, sumSq = 0;
  constexpr int kCopies = 2000;
  LocalPolynomialFit f;
  std::vector<double> y(t.size());
  for (int c = 0; c < kCopies; ++c) {
    for (double& v : y) v = noise(e);
    f = fitLocalPolynomial(t, y, 0.02);
    sum += f.acceleration[at];
    sumSq += f.acceleration[at] * f.acceleration[at];
  }
  const double sd = std::sqrt(sumSq / kCopies - (sum / kCopies) * (sum / kCopies));
  EXPECT_NEAR(sd, f.accelerationGain[at], 0.05 * f.accelerationGain[at]);
  double fromWeights = 0;
  for (std::size_t k = 0; k < f.accelerationWeights[at].size(); ++k)
    fromWeights += f.accelerationWeights[at][k] * y[f.windowStart[at] + k];
  EXPECT_NEAR(fromWeights, f.acceleration[at], 1e-9 * std::abs(f.acceleration[at]) + 1e-9);
}

TEST(LocalPolynomial, RefusesWhatItCannotFitAndLeavesSparseWindowsOpen) {
  EXPECT_THROW(fitLocalPolynomial({0, 1, 2}, {0, 1}, 0.5), std::invalid_argument);
  EXPECT_THROW(fitLocalPolynomial({0, 1, 2, 3, 4}, {0, 1, 2, 3, 4}, 1.0, 1), std::invalid_argument);
  // 3 samples in each window: too few for a cubic and its noise; no estimate, no error.
  const LocalPolynomialFit f = fitLocalPolynomial({0, 1, 2, 3, 4}, {0, 1, 2, 3, 4}, 1.0, 3);
  for (double a : f.acceleration) EXPECT_TRUE(std::isnan(a));
}

}  // namespace
}  // namespace swingsim
