#include "identify/switch_search.h"

#include <gtest/gtest.h>

#include <set>

#include "io/knee_model_loader.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;

BenchData strokeOf(std::vector<double> positions) {
  BenchData d;
  d.position = std::move(positions);
  return d;
}

// The grid: 3 velocity widths x 4 position widths x 5 xhy x (2 latch rates when fitted), all
// within the physical ranges; xhy from the lowest training positions.
TEST(CylinderSwitchSearch, StartsSpreadOverThePhysicalRanges) {
  const MauchCylinderParams model = loadMauchCylinder(kRoot + "/models/mauch-4phase.yaml");
  std::vector<double> positions;
  for (int i = 0; i <= 100; ++i) positions.push_back(-1e-3 + 3e-5 * i);  // m, within the xhy range
  const std::vector<BenchData> train = {strokeOf(positions)};
  CylinderFitOptions options;
  const auto grid = makeSwitchStarts(model, train, options);
  EXPECT_EQ(grid.size(), 3u * 4u * 5u * 2u);
  const SwitchConstantRanges& r = options.ranges;
  std::set<double> xhy;
  for (const auto& g : grid) {
    EXPECT_GE(g.velocityWidth, r.velocityWidth[0]);
    EXPECT_LE(g.velocityWidth, r.velocityWidth[1]);
    EXPECT_GE(g.positionWidth, r.positionWidth[0]);
    EXPECT_LE(g.positionWidth, r.positionWidth[1]);
    EXPECT_GE(g.latchRate, r.latchRate[0]);
    EXPECT_LE(g.latchRate, r.latchRate[1]);
    xhy.insert(g.hyperextensionPosition);
  }
  EXPECT_EQ(xhy.size(), 5u);
  EXPECT_EQ(*xhy.begin(), -1e-3 + 3e-5 * 2);  // the 2 % quantile of the 101 positions
  options.fitLatchRate = false;
  for (const auto& g : makeSwitchStarts(model, train, options)) EXPECT_EQ(g.latchRate, model.switches.latchRate);
  options.multiStart = false;
  const auto own = makeSwitchStarts(model, train, options);
  ASSERT_EQ(own.size(), 1u);
  EXPECT_EQ(own[0].positionWidth, model.switches.positionWidth);
}

}  // namespace
}  // namespace swingsim
