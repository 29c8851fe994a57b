// The missing cylinder force (identify/missing_force.h), on bench records the independent
// generator makes (tests/independent/mauch_bench_generator.h, no code shared with src/).
#include "identify/missing_force.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "../independent/mauch_bench_generator.h"
#include "io/bench_csv.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;

constexpr double kNoise = 15.0;  // N

// On a null the missing force departs from zero nowhere; with the end stop its largest region
// lies beyond the stop's start (20 mm), within 5 mm.
TEST(MissingForce, IsNoneOnANullAndBeyondTheStopWithIt) {
  independent::MauchTruth truth;
  truth.laws = independent::chienTable1(4);
  MauchCylinderParams chien;
  chien.coefficients.clear();
  for (const auto& l : truth.laws) chien.coefficients.push_back({l.f, l.k, l.c});
  chien.initialLatch = 0.0;
  const auto regionsOf = [&](const independent::MauchTruth& t) {
    std::vector<BenchData> records;
    std::uint64_t seed = 331;
    for (const auto& g : independent::chienGaits()) {
      const fs::path path =
          fs::temp_directory_path() / ("swingsim-missing-force-" + std::to_string(::getpid()) + ".csv");
      independent::writeCsv(independent::generate(t, g, kNoise, seed++), path.string());
      records.push_back(readBenchCsv(path.string(), 20));
      fs::remove(path);
    }
    return calcMissingForce(chien, records, std::vector<double>(records.size(), kNoise)).regions;
  };
  const auto null = regionsOf(truth);
  EXPECT_TRUE(null.empty()) << describeMissingForce(null);
  truth.endStop = 3e6;
  truth.endStopStart = 0.020;
  const auto stop = regionsOf(truth);
  ASSERT_FALSE(stop.empty());
  std::printf("  %s\n", describeMissingForce(stop).c_str());
  EXPECT_GT(stop.front().force, 0);
  EXPECT_NEAR(stop.front().positionLowMm, 20.0, 5.0);
}

// One region by hand: a bin's mean is the records' mean residual; a constant offset of 30 N
// against 1 N of noise makes one region per direction, said with its sign and motion.
TEST(MissingForce, SaysTheSignAndTheMotionOfAnOffset) {
  MauchCylinderParams p;
  p.coefficients.assign(4, {});
  BenchData d;
  for (int i = 0; i < 400; ++i) {
    const double t = i * 0.005;
    d.time.push_back(t);
    d.position.push_back(0.005 + 0.004 * std::sin(6.0 * t));  // 1-9 mm, moving both ways
    d.velocity.push_back(0.024 * std::cos(6.0 * t));
    d.force.push_back(30.0);  // the model (all coefficients 0) gives 0 N
  }
  const MissingForce missing = calcMissingForce(p, {d}, {1.0});
  // The map: every sample, with its record's noise.
  ASSERT_EQ(missing.forceN.size(), d.force.size());
  EXPECT_EQ(missing.positionMm.size(), d.force.size());
  EXPECT_NEAR(missing.positionMm[0], 5.0, 1e-12);
  EXPECT_NEAR(missing.speedMmS[0], 24.0, 1e-12);
  EXPECT_NEAR(missing.forceN[0], 30.0, 1e-9);
  EXPECT_EQ(missing.noiseN[0], 1.0);
  const auto& regions = missing.regions;
  ASSERT_EQ(regions.size(), 2u) << describeMissingForce(regions);
  for (const auto& r : regions) {
    EXPECT_NEAR(r.force, 30.0, 1e-9);
    EXPECT_NEAR(r.positionLowMm, 1.0, 0.1);
    EXPECT_NEAR(r.positionHighMm, 9.0, 0.1);
  }
  const std::string line = describeMissingForce(regions);
  EXPECT_NE(line.find("resisting compression at piston 1-9 mm while compressing"), std::string::npos) << line;
  EXPECT_NE(line.find("assisting extension at piston 1-9 mm while extending"), std::string::npos) << line;
  EXPECT_THROW(calcMissingForce(p, {d}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
