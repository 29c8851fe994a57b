#include "numerics/metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace swingsim {
namespace {

TEST(Median, OddEvenAndEmpty) {
  EXPECT_EQ(calcMedian({3, 1, 2}), 2);
  EXPECT_EQ(calcMedian({4, 1, 3, 2}), 3);  // the upper of the two middle values
  EXPECT_TRUE(std::isnan(calcMedian({})));
}

TEST(ErrorMetrics, MatchHandComputedValues) {
  // measured mean 2.5, SS_tot = 5; residuals 0, 1, -1, 2: SS_res = 6.
  const auto m = calcErrorMetrics({1, 2, 3, 4}, {1, 1, 4, 2});
  EXPECT_EQ(m.count, 4u);
  EXPECT_DOUBLE_EQ(m.maxError, 2.0);
  EXPECT_EQ(m.maxErrorIndex, 3u);
  EXPECT_DOUBLE_EQ(m.rmse, std::sqrt(6.0 / 4.0));
  EXPECT_DOUBLE_EQ(m.r2, 1.0 - 6.0 / 5.0);
  EXPECT_DOUBLE_EQ(m.bias, 0.5);
}

TEST(ErrorMetrics, PerfectPredictionAndMasks) {
  const auto m = calcErrorMetrics({1, 5, 2}, {1, 5, 2});
  EXPECT_EQ(m.rmse, 0.0);
  EXPECT_EQ(m.r2, 1.0);
  const auto masked = calcErrorMetrics({1, 5, 2, 9}, {1, 0, 2, 9}, {true, false, true, true});
  EXPECT_EQ(masked.count, 3u);
  EXPECT_EQ(masked.maxError, 0.0);
  const auto none = calcErrorMetrics({1, 2}, {1, 2}, {false, false});
  EXPECT_EQ(none.count, 0u);
  EXPECT_TRUE(std::isnan(none.rmse));
  EXPECT_TRUE(std::isnan(calcErrorMetrics({3, 3}, {3, 2}).r2));  // constant measurement
  EXPECT_THROW(calcErrorMetrics({1, 2}, {1}), std::invalid_argument);
  EXPECT_THROW(calcErrorMetrics({}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
