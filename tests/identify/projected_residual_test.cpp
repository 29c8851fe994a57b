#include "identify/projected_residual.h"

#include <gtest/gtest.h>

#include <cmath>
#include "mauch_bench_fixture.h"

namespace swingsim {
namespace {

using namespace mauch_bench_fixture;

TEST(CylinderProjectedResidual, JacobianMatchesFiniteDifferences) {
  // Central differences at a relative step of 1e-5 are accurate to about step^2 (1e-10)
  // relative plus round-off 1e-16 / 1e-5 of the residual's size: far below this bound.
  constexpr double kJacobianTol = 1e-6;
  constexpr double kRelativeStep = 1e-5;
  // Round-off of one residual evaluation relative to its size (a QR of ~1800 rows is good to
  // ~1e-13): divided by the step it bounds the differences' round-off error, generously.
  constexpr double kResidualRoundOff = 1e-9;
  const auto truth = model("mauch-4phase.yaml");
  const auto data = makeBench(truth, 0.987, 1.0, kNoise, 5, "normal");
  for (const char* file : {"mauch-4phase.yaml", "mauch-2phase.yaml"}) {
    auto params = model(file);
    params.switches.velocityWidth *= 3.0;
    params.switches.positionWidth *= 0.5;
    params.switches.hyperextensionPosition += 2e-4;
    params.switches.latchRate = 300.0;
    Eigen::MatrixXd jacobian;
    const Eigen::VectorXd r = calcProjectedResidual(params, {data}, &jacobian);
    ASSERT_EQ(jacobian.rows(), r.size());
    ASSERT_EQ(jacobian.cols(), 4);
    EXPECT_EQ(r, calcProjectedResidual(params, {data}));  // the same residual with or without it
    double* constants[] = {&params.switches.velocityWidth, &params.switches.positionWidth,
                           &params.switches.hyperextensionPosition, &params.switches.latchRate};
    for (int k = 0; k < 4; ++k) {
      const double v = *constants[k], h = kRelativeStep * std::max(std::fabs(v), 1e-3);
      *constants[k] = v + h;
      const Eigen::VectorXd up = calcProjectedResidual(params, {data});
      *constants[k] = v - h;
      const Eigen::VectorXd down = calcProjectedResidual(params, {data});
      *constants[k] = v;
      const Eigen::VectorXd numeric = (up - down) / (2 * h);
      ASSERT_GT(numeric.norm(), 0.0) << file << " constant " << k;
      EXPECT_LT((jacobian.col(k) - numeric).norm(), kJacobianTol * numeric.norm() + kResidualRoundOff * r.norm() / h)
          << file << " constant " << k << ": analytic " << jacobian.col(k).norm() << ", numeric " << numeric.norm();
    }
  }
}

// The switch constants as bounded parameters and back, in one order; the latch rate only
// when it is fitted.
TEST(CylinderProjectedResidual, SwitchParametersRoundTrip) {
  const MauchSwitchParams start{1e-3, 2e-4, 5e-5, 300.0};
  const SwitchConstantRanges ranges;
  const auto withLatch = switchParameters(start, ranges, true);
  ASSERT_EQ(withLatch.size(), 4u);
  EXPECT_EQ(switchParameters(start, ranges, false).size(), 3u);
  const double x[] = {2e-3, 3e-4, -1e-4, 50.0};
  const MauchSwitchParams back = switchesFrom(start, x, true);
  EXPECT_EQ(back.velocityWidth, 2e-3);
  EXPECT_EQ(back.hyperextensionPosition, -1e-4);
  EXPECT_EQ(back.latchRate, 50.0);
  EXPECT_EQ(switchesFrom(start, x, false).latchRate, 300.0) << "a latch rate that is not fitted stays";
  EXPECT_EQ(withLatch[3].name, "latch_rate_per_s");
  EXPECT_EQ(withLatch[0].start, start.velocityWidth);
}

}  // namespace
}  // namespace swingsim
