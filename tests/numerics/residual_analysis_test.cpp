#include "numerics/residual_analysis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace swingsim {
namespace {

// Textbook values (Abramowitz & Stegun Tables 26.1 and 26.8) to their printed digits.
constexpr double kTableTolerance = 1e-9;

TEST(ResidualAnalysis, DistributionTailsAndQuantilesMatchTheTables) {
  EXPECT_NEAR(calcChiSquaredSurvival(3.841458820694124, 1), 0.05, kTableTolerance);
  EXPECT_NEAR(calcChiSquaredSurvival(37.56623478662507, 20), 0.01, kTableTolerance);
  EXPECT_NEAR(calcChiSquaredSurvival(2.0, 2), std::exp(-1.0), kTableTolerance);  // chi^2(2) tail is exp(-x/2)
  EXPECT_DOUBLE_EQ(calcChiSquaredSurvival(0.0, 3), 1.0);
  EXPECT_NEAR(calcNormalQuantile(0.975), 1.959963984540054, kTableTolerance);
  EXPECT_NEAR(calcNormalQuantile(0.995), 2.5758293035489004, kTableTolerance);
  EXPECT_NEAR(calcChiSquaredQuantile(0.95, 1), 3.841458820694124, kTableTolerance);
}

// White noise passes Ljung-Box at 1 %, and its effective sample size is about n; a smooth
// misfit (AR(1) with rho 0.9) fails and has about n (1 - 0.9) / (1 + 0.9) effective samples.
TEST(ResidualAnalysis, WhiteNoisePassesAndAStrongAr1MisfitFails) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> white, ar1;
  double last = 0;
  for (int i = 0; i < 4000; ++i) {
    white.push_back(noise(rng));
    last = 0.9 * last + noise(rng);
    ar1.push_back(last);
  }
  EXPECT_GT(calcWhitenessTest({white}, 20).pValue, 0.01);
  EXPECT_LT(calcWhitenessTest({ar1}, 20).pValue, 1e-6);
  EXPECT_NEAR(calcEffectiveSampleSize({white}), 4000, 400);
  EXPECT_NEAR(calcEffectiveSampleSize({ar1}), 4000 * 0.1 / 1.9, 60);
}

}  // namespace
}  // namespace swingsim
