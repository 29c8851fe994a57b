#include "numerics/rank_correlation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace swingsim {
namespace {

constexpr double kExact = 1e-12;  // closed-form cases: only rounding

TEST(RankCorrelation, TiesShareTheirAverageRank) {
  const std::vector<double> ranks = calcAverageRanks({3.0, 1.0, 3.0, 2.0});
  EXPECT_EQ(ranks, (std::vector<double>{3.5, 1.0, 3.5, 2.0}));
}

TEST(RankCorrelation, MonotoneButNonlinearIsOne) {
  std::vector<double> x, y;
  for (int i = 0; i < 20; ++i) {
    x.push_back(i);
    y.push_back(std::exp(0.3 * i));  // Pearson < 1, ranks identical
  }
  const RankCorrelation r = calcSpearman(x, y);
  EXPECT_NEAR(r.rho, 1.0, kExact);
  EXPECT_EQ(r.count, 20);
  const std::vector<double> reversed(y.rbegin(), y.rend());
  EXPECT_NEAR(calcSpearman(x, reversed).rho, -1.0, kExact);
}

TEST(RankCorrelation, MatchesTheTextbookFormulaWithoutTies) {
  // rho = 1 - 6 sum d^2 / (n (n^2 - 1)), computed by hand for this permutation.
  const std::vector<double> x = {1, 2, 3, 4, 5, 6};
  const std::vector<double> y = {2, 1, 4, 3, 6, 5};
  // d = -1, 1, -1, 1, -1, 1: sum d^2 = 6; rho = 1 - 36 / 210.
  EXPECT_NEAR(calcSpearman(x, y).rho, 1.0 - 36.0 / 210.0, kExact);
}

TEST(RankCorrelation, FisherIntervalContainsRhoAndNarrowsWithN) {
  std::vector<double> x, y;
  for (int i = 0; i < 200; ++i) {
    x.push_back(i);
    y.push_back(i + 60.0 * std::sin(1.7 * i));  // a noisy but positive relation
  }
  const std::vector<double> x30(x.begin(), x.begin() + 30), y30(y.begin(), y.begin() + 30);
  const RankCorrelation all = calcSpearman(x, y), few = calcSpearman(x30, y30);
  EXPECT_LT(all.low, all.rho);
  EXPECT_GT(all.high, all.rho);
  EXPECT_LT(all.high - all.low, few.high - few.low);
  // The half-width in z is z(0.975) sqrt(1.06 / (n - 3)).
  const double halfZ = 0.5 * (std::atanh(all.high) - std::atanh(all.low));
  EXPECT_NEAR(halfZ, 1.959963984540054 * std::sqrt(1.06 / 197.0), 1e-9);
}

TEST(RankCorrelation, SkipsNonFinitePairsAndConstantsAreUndefined) {
  const double nan = std::nan("");
  const RankCorrelation r = calcSpearman({1, 2, nan, 4, 5}, {1, 2, 3, nan, 5});
  EXPECT_EQ(r.count, 3);
  EXPECT_NEAR(r.rho, 1.0, kExact);
  EXPECT_TRUE(std::isnan(r.low));  // too few pairs for an interval
  EXPECT_TRUE(std::isnan(calcSpearman({1, 1, 1, 1, 1}, {1, 2, 3, 4, 5}).rho));
  EXPECT_THROW(calcSpearman({1, 2}, {1}), std::invalid_argument);
  EXPECT_THROW(calcSpearman({1, 2, 3}, {1, 2, 3}, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
