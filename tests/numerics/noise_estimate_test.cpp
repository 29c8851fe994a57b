#include "numerics/noise_estimate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace swingsim {
namespace {

// A standard error of the MAD-based sigma from n pseudo-residuals is about 1.2 sigma /
// sqrt(n) (normal data); with n ~ 2000 that is 2.7 %: 8 % is three of them.
constexpr double kRelativeTolerance = 0.08;

// A smooth signal like a bench force (500 N at the stride frequency and its harmonics),
// sampled unevenly around 361 Hz, with white noise of known size and a fixed seed.
TEST(NoiseEstimate, RecoversTheNoiseOfASmoothSignalWithinEightPercent) {
  for (double sigma : {5.0, 15.0, 40.0}) {
    std::mt19937_64 rng(42);
    std::normal_distribution<double> noise(0.0, sigma);
    std::uniform_real_distribution<double> jitter(-0.2, 0.2);
    std::vector<double> t, y;
    for (int i = 0; i < 2000; ++i) {
      const double ti = (i + jitter(rng)) / 361.4;
      t.push_back(ti);
      y.push_back(500 * std::sin(2 * M_PI * ti) + 150 * std::sin(2 * M_PI * 3 * ti) + noise(rng));
    }
    const NoiseEstimate e = estimateNoise(t, y);
    EXPECT_NEAR(e.sigma, sigma, kRelativeTolerance * sigma) << sigma;
    EXPECT_EQ(e.samples, 1998u);
  }
}

// Sharp corners (a valve switch every 0.2 s: a jump of 300 N) touch few samples: the robust
// scale ignores them, where a plain RMS of the pseudo-residuals would not.
TEST(NoiseEstimate, IsNotInflatedByRareJumpsInTheSignal) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 10.0);
  std::vector<double> t, y;
  for (int i = 0; i < 3000; ++i) {
    t.push_back(i / 361.4);
    y.push_back((static_cast<int>(t.back() / 0.2) % 2 ? 300.0 : 0.0) + noise(rng));
  }
  EXPECT_NEAR(estimateNoise(t, y).sigma, 10.0, kRelativeTolerance * 10.0);
}

TEST(NoiseEstimate, NoiselessStraightLineGivesZeroAndPoolingWeighsBySamples) {
  EXPECT_DOUBLE_EQ(estimateNoise({0, 1, 2, 3}, {1, 3, 5, 7}).sigma, 0.0);
  const NoiseEstimate pooled = poolNoise({{1.0, 100}, {2.0, 300}});
  EXPECT_NEAR(pooled.sigma, std::sqrt((100 * 1.0 + 300 * 4.0) / 400), 1e-12);
  EXPECT_THROW(estimateNoise({0, 1}, {1, 2}), std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
