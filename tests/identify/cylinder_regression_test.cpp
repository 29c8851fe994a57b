#include "identify/cylinder_regression.h"

#include <gtest/gtest.h>

#include <cmath>

#include <limits>
#include "mauch_bench_fixture.h"

namespace swingsim {
namespace {

using namespace mauch_bench_fixture;

TEST(CylinderRegression, LeastSquaresReportsRankDeficiencyAndConditioning) {
  Eigen::MatrixXd X(5, 3);
  X << 1, 0, 2, 1, 0, 2, 1, 0, 2, 1, 0, 2, 1, 0, 2;  // column 2 = 2 x column 0, column 1 zero
  Eigen::VectorXd y = Eigen::VectorXd::Ones(5);
  const auto fit = fitLeastSquares(X, y);
  EXPECT_EQ(fit.rank, 1);
  EXPECT_TRUE(std::isinf(fit.conditionNumber));
  EXPECT_TRUE(std::isnan(fit.standardErrors[0]));
  Eigen::MatrixXd I = Eigen::MatrixXd::Identity(4, 2);
  EXPECT_NEAR(fitLeastSquares(I, Eigen::VectorXd::Ones(4)).conditionNumber, 1.0, 1e-12);
}

// Bounds in regressor order: each phase's f and k free, its damping c >= 0; a Coulomb force >= 0.
TEST(CylinderRegression, CoefficientBoundsFollowThePhysics) {
  MauchCylinderParams p = model("mauch-2phase.yaml");
  p.effects.coulombFriction = true;
  const auto bounds = coefficientBounds(p);
  ASSERT_EQ(bounds.size(), 7u);
  for (std::size_t j : {0u, 1u, 3u, 4u}) EXPECT_EQ(bounds[j].first, -1e300) << j;
  for (std::size_t j : {2u, 5u, 6u}) EXPECT_EQ(bounds[j].first, 0.0) << j;
}

// A coefficient whose unconstrained value lies outside its bound is held on the bound, gets
// a NaN standard error, and the others are refitted.
TEST(CylinderRegression, RegressionWithinBoundsHoldsAViolatingCoefficientOnItsBound) {
  const auto truth = model("mauch-4phase.yaml");
  const std::vector<BenchData> train = {makeBench(truth, 0.987, 1.0, 0.0, 3, "normal")};
  auto bounds = coefficientBounds(truth);
  const double c1 = truth.coefficients[0].c;
  bounds[2] = {c1 + 100.0, 1e300};  // phase 1 damping: above the generating value
  std::vector<bool> fixed;
  const LinearFit fit = regressWithinBounds(truth, train, bounds, fixed);
  ASSERT_EQ(fixed.size(), bounds.size());
  EXPECT_TRUE(fixed[2]);
  EXPECT_EQ(fit.coefficients[2], c1 + 100.0);
  EXPECT_TRUE(std::isnan(fit.standardErrors[2]));
  for (std::size_t j = 0; j < fixed.size(); ++j) {
    if (j != 2) {
      EXPECT_FALSE(fixed[j]) << j;
    }
  }
  // Unbounded, noise-free data give the generating damping back.
  EXPECT_NEAR(regress(truth, train).coefficients[2], c1, 1e-6 * std::max(1.0, std::abs(c1)));
}

}  // namespace
}  // namespace swingsim
