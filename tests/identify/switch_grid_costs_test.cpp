#include "identify/switch_grid_costs.h"

#include <gtest/gtest.h>

#include <cmath>

#include "identify/projected_residual.h"
#include "mauch_bench_fixture.h"

namespace swingsim {
namespace {

using namespace mauch_bench_fixture;

// The multi-start grid's shortcut (switch values shared between starts computed once) ranks
// the starts by the same costs as the projected residual itself.
TEST(CylinderSwitchGridCosts, AreTheProjectedResidualsSquaredNorms) {
  constexpr double kSameCost = 1e-12;  // relative: only the order of sums differs, if anything
  const auto truth = model("mauch-4phase.yaml");
  const std::vector<BenchData> train = {makeBench(truth, 0.987, 1.0, kNoise, 6, "normal"),
                                        makeBench(truth, 1.19, 0.9, kNoise, 7, "slow")};
  for (const char* file : {"mauch-4phase.yaml", "mauch-2phase.yaml"}) {
    auto params = model(file);
    std::vector<MauchSwitchParams> grid;
    for (double vw : {2e-4, 3e-3})
      for (double pw : {1e-5, 4e-4, 1e-3})
        for (double xhy : {-1e-4, 3e-4})
          for (double k : {20.0, 2e4}) grid.push_back({vw, pw, xhy, k});
    const std::vector<double> costs = calcSwitchGridCosts(params, train, grid);
    ASSERT_EQ(costs.size(), grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i) {
      params.switches = grid[i];
      const double direct = calcProjectedResidual(params, train).squaredNorm();
      EXPECT_NEAR(costs[i], direct, kSameCost * direct) << file << " grid point " << i;
    }
  }
}

// One thread or two: the same costs, bit for bit (each grid point is computed alone).
TEST(CylinderSwitchGridCosts, SameOnOneAndTwoThreads) {
  const auto truth = model("mauch-4phase.yaml");
  const std::vector<BenchData> train = {makeBench(truth, 0.987, 1.0, kNoise, 8, "normal")};
  const TrainingSet set(truth, train);
  std::vector<MauchSwitchParams> grid;
  for (double vw : {2e-4, 3e-3})
    for (double k : {20.0, 2e4}) grid.push_back({vw, 4e-4, 1e-4, k});
  const std::vector<double> one = calcGridCosts(truth, set, grid, 1);
  EXPECT_EQ(one, calcGridCosts(truth, set, grid, 2));
  // The generating switch constants cost less than a latch 1000 times slower.
  EXPECT_LT(calcGridCosts(truth, set, {truth.switches}, 1)[0],
            calcGridCosts(truth, set,
                          {{truth.switches.velocityWidth, truth.switches.positionWidth,
                            truth.switches.hyperextensionPosition, truth.switches.latchRate / 1000}},
                          1)[0]);
}

}  // namespace
}  // namespace swingsim
