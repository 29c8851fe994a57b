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

// The lags scale with the record: at most one per kWhitenessLagDivisor samples of the
// shortest segment. A 15-sample record asked for 20 lags (Q was NaN there, read as white)
// gets 3 and a finite test; a strong AR(1) misfit of 60 samples still fails with its 12.
TEST(ResidualAnalysis, WhitenessLagsScaleWithTheShortestRecord) {
  std::mt19937_64 rng(12);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> shortRecord, ar1;
  double last = 0;
  for (int i = 0; i < 60; ++i) {
    if (i < 15) shortRecord.push_back(noise(rng));
    last = 0.95 * last + noise(rng);
    ar1.push_back(last);
  }
  const WhitenessTest t = calcWhitenessTest({shortRecord}, 20);
  EXPECT_EQ(t.lags, 15 / kWhitenessLagDivisor);
  EXPECT_EQ(t.requestedLags, 20);
  EXPECT_TRUE(t.computed) << t.note;
  EXPECT_TRUE(std::isfinite(t.q));
  EXPECT_NE(t.note.find("3 of the 20 lags"), std::string::npos) << t.note;
  const WhitenessTest misfit = calcWhitenessTest({ar1, ar1}, 20);
  EXPECT_EQ(misfit.lags, 60 / kWhitenessLagDivisor);
  EXPECT_EQ(judgeWhiteness(misfit, 0.01), Whiteness::kNotWhite) << misfit.pValue;
  // The shortest segment sets the lags.
  EXPECT_EQ(calcWhitenessLags({ar1, shortRecord}, 20), 3);
  EXPECT_EQ(calcWhitenessLags({ar1}, 4), 4);
}

// A test that cannot be computed is "cannot tell", never white: too short a record, a NaN
// in the residual, a constant residual; a NaN statistic has a NaN tail probability.
TEST(ResidualAnalysis, AWhitenessTestThatCannotBeComputedIsNeverAPass) {
  const std::vector<double> nine{0.3, -1.2, 0.8, 0.1, -0.5, 1.4, -0.9, 0.2, 0.6};
  const WhitenessTest tooShort = calcWhitenessTest({nine}, 20);
  EXPECT_FALSE(tooShort.computed);
  EXPECT_EQ(judgeWhiteness(tooShort, 0.01), Whiteness::kCannotTell);
  EXPECT_NE(tooShort.note.find("9 samples"), std::string::npos) << tooShort.note;
  std::vector<double> withNan(100, 0.0);
  for (std::size_t i = 0; i < withNan.size(); ++i) withNan[i] = std::sin(0.7 * static_cast<double>(i * i));
  withNan[50] = std::nan("");
  const WhitenessTest nan = calcWhitenessTest({withNan}, 20);
  EXPECT_EQ(judgeWhiteness(nan, 0.01), Whiteness::kCannotTell);
  EXPECT_NE(nan.note.find("non-finite"), std::string::npos) << nan.note;
  const WhitenessTest constant = calcWhitenessTest({std::vector<double>(100, 0.25)}, 20);
  EXPECT_EQ(judgeWhiteness(constant, 0.01), Whiteness::kCannotTell);
  EXPECT_NE(constant.note.find("constant"), std::string::npos) << constant.note;
  EXPECT_TRUE(std::isnan(calcChiSquaredSurvival(std::nan(""), 20)));
  EXPECT_DOUBLE_EQ(calcChiSquaredSurvival(INFINITY, 20), 0.0);
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

// A short record (a 60 Hz swing of 24 samples) asked for 12 bins gets 4 bins of 6, never a
// 2-sample bin whose spread (and band) can collapse; fewer than kMinBinSamples: no bins.
TEST(ResidualAnalysis, SparseBinsAreMergedToTheMinimumCount) {
  std::vector<double> variable, residual;
  for (int i = 0; i < 24; ++i) {
    variable.push_back(i);
    residual.push_back(std::sin(0.3 * i) + 1e-3 * (i % 2));  // smooth: neighbours nearly equal
  }
  const BinnedResidual b = calcBinnedResidual(variable, residual, 12, 0.2);
  ASSERT_EQ(b.center.size(), 24 / kMinBinSamples);
  for (std::size_t k = 0; k < b.center.size(); ++k) {
    EXPECT_GE(b.upper[k] - b.lower[k] + 1, static_cast<double>(kMinBinSamples));  // integer variable: count
    EXPECT_GT(b.halfWidth[k], 0);
  }
  const std::vector<double> few(kMinBinSamples - 1, 1.0);
  EXPECT_TRUE(calcBinnedResidual(few, few, 12, 1.0).center.empty());
}

// Two bins equally far from zero (mirror images): the lowest bin is named, every time; a bin
// of constant residual (zero spread) has no band and is not named although its mean is largest.
TEST(ResidualAnalysis, BinnedTiesGoToTheLowestBinAndZeroSpreadBinsAreLeftOut) {
  std::vector<double> variable, residual;
  const std::vector<std::vector<double>> bins = {
      {1, 2, 3, 4, 5}, {1, -1, 1, -1, 0}, {9, 9, 9, 9, 9}, {-1, -2, -3, -4, -5}};
  for (std::size_t k = 0; k < bins.size(); ++k)
    for (double r : bins[k]) {
      variable.push_back(static_cast<double>(variable.size()));
      residual.push_back(r);
    }
  const BinnedResidual b = calcBinnedResidual(variable, residual, 4, 1.0);
  ASSERT_EQ(b.center.size(), 4u);
  EXPECT_EQ(b.halfWidth[2], 0);
  EXPECT_EQ(b.maxBin, 0u);
  EXPECT_GT(b.maxSignificance, 1);
  // Equal variable values: the bins follow the sample order, so the same input gives the same bins.
  const std::vector<double> flat(20, 0.0);
  const BinnedResidual f1 = calcBinnedResidual(flat, residual, 4, 1.0), f2 = calcBinnedResidual(flat, residual, 4, 1.0);
  EXPECT_EQ(f1.mean, f2.mean);
  EXPECT_EQ(f1.maxBin, 0u);
}

// Closed form for one degree of freedom: chi'^2(1, lambda) is (Z + sqrt(lambda))^2, so the
// power at level alpha is Phi(sqrt(lambda) - z) + Phi(-sqrt(lambda) - z), z = z_{1-alpha/2}.
// Table value: lambda = (1.96 + 0.8416)^2 = 7.849 gives 80 % power at alpha 0.05 (Cohen 1988).
TEST(ResidualAnalysis, NoncentralChiSquaredPowerMatchesTheClosedFormAndTheTable) {
  const auto phi = [](double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); };
  for (double alpha : {0.05, 0.01, 0.001})
    for (double lambda : {0.5, 3.0, 7.849, 20.0}) {
      const double z = calcNormalQuantile(1 - alpha / 2), r = std::sqrt(lambda);
      EXPECT_NEAR(calcChiSquaredPower(lambda, 1, alpha), phi(r - z) + phi(-r - z), kTableTolerance);
    }
  constexpr double kTableDigits = 1e-4;  // the table's four digits
  EXPECT_NEAR(calcChiSquaredPower(7.849, 1, 0.05), 0.80, kTableDigits);
  EXPECT_NEAR(calcChiSquaredPower(1e-9, 3, 0.01), 0.01, 1e-8);  // lambda -> 0: power -> alpha
  // lambda 1 per record: 7 records give 0.754, 8 give 0.807 (closed form above).
  EXPECT_EQ(calcRecordsForPower(1.0, 1, 0.05, 0.8), 8);
  EXPECT_EQ(calcRecordsForPower(8.0, 1, 0.05, 0.8), 1);
  EXPECT_EQ(calcRecordsForPower(0.0, 1, 0.05, 0.8), 0);
  EXPECT_EQ(calcRecordsForPower(1e-9, 1, 0.05, 0.8, 1000), 0);
}

}  // namespace
}  // namespace swingsim
