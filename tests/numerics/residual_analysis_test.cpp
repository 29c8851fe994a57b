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

// A residual that is nonzero only above 55 (of a variable spread over 0..80): the run of
// significant bins starts near 55 and reaches the top; below it the means are noise.
TEST(ResidualAnalysis, BinnedRunFindsWhereInTheRangeTheResidualSits) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> noise(0.0, 0.5);
  std::uniform_real_distribution<double> spread(0.0, 80.0);
  std::vector<double> variable, residual;
  for (int i = 0; i < 4000; ++i) {
    const double x = spread(rng);
    variable.push_back(x);
    residual.push_back((x > 55 ? -1.0 : 0.0) + noise(rng));
  }
  const BinnedResidual b = calcBinnedResidual(variable, residual, 16, 1.0);
  ASSERT_GT(b.maxSignificance, 1);
  EXPECT_LT(b.mean[b.maxBin], 0);
  EXPECT_EQ(b.runLast, b.center.size() - 1);
  EXPECT_NEAR(b.lower[b.runFirst], 55, 5.0 + 1e-9);  // a bin is 5 wide
  for (std::size_t k = 0; k < b.center.size(); ++k) {
    EXPECT_LE(b.lower[k], b.center[k]);
    EXPECT_GE(b.upper[k], b.center[k]);
  }
}

}  // namespace
}  // namespace swingsim
