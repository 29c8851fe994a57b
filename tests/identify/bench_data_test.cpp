#include "identify/bench_data.h"
#include "io/bench_csv.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/input_error.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

std::string writeTemp(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "swingsim_bench_data_test";
  std::filesystem::create_directories(dir);
  const auto path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

std::string errorOf(const std::string& path, std::size_t minRows = 3) {
  try {
    readBenchCsv(path, minRows);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(BenchData, VelocityEstimateIsExactForQuadraticsOnUnevenGrids) {
  const std::vector<double> t = {0.0, 0.1, 0.25, 0.3, 0.5};
  std::vector<double> x;
  for (double ti : t) x.push_back(2 + 3 * ti - 4 * ti * ti);
  const auto v = estimatePistonVelocity(t, x);
  for (std::size_t i = 1; i + 1 < t.size(); ++i) EXPECT_NEAR(v[i], 3 - 8 * t[i], 1e-12);
}

TEST(BenchData, NoiseIsReproducibleAndStandardNormal) {
  NormalNoise a(7), b(7), c(8);
  EXPECT_EQ(a.next(), b.next());
  EXPECT_NE(a.next(), c.next());
  NormalNoise n(2014);
  constexpr int kSamples = 200000;
  double sum = 0, sumSq = 0;
  for (int i = 0; i < kSamples; ++i) {
    const double z = n.next();
    sum += z;
    sumSq += z * z;
  }
  // Sampling error of the mean and variance: about 1/sqrt(N) = 0.0022 and sqrt(2/N) = 0.0032.
  EXPECT_NEAR(sum / kSamples, 0.0, 0.01);
  EXPECT_NEAR(sumSq / kSamples, 1.0, 0.015);
}

TEST(BenchData, ReadsAFileAndIgnoresExtraColumns) {
  const auto d =
      readBenchCsv(writeTemp("ok.csv", "time_s,position_m,force_N,note\n0,0,1,1\n0.1,0.01,2,1\n0.2,0.02,3,1\n"), 3);
  EXPECT_EQ(d.stem, "ok");
  EXPECT_NEAR(d.velocity[1], 0.1, 1e-12);
}

TEST(BenchData, BadFilesGiveErrorsNamingFileLineAndColumn) {
  EXPECT_THAT(errorOf(writeTemp("nocol.csv", "time_s,position_m\n0,0\n0.1,0.01\n0.2,0.02\n")),
              HasSubstr("nocol.csv:1: force_N: required column is missing"));
  EXPECT_THAT(errorOf(writeTemp("time.csv", "time_s,position_m,force_N\n0,0,1\n0.1,0.01,2\n0.1,0.02,3\n")),
              HasSubstr("time.csv:4: time_s: must be strictly increasing (got 0.1 after 0.1)"));
  EXPECT_THAT(errorOf(writeTemp("nan.csv", "time_s,position_m,force_N\n0,0,1\n0.1,0.01,nan\n0.2,0.02,3\n")),
              HasSubstr("nan.csv:3: force_N: expected a finite number (got 'nan')"));
  EXPECT_THAT(errorOf(writeTemp("few.csv", "time_s,position_m,force_N\n0,0,1\n0.1,0.01,2\n0.2,0.02,3\n"), 13),
              HasSubstr("few.csv: too few data rows (got 3, need at least 13)"));
  EXPECT_THAT(errorOf(writeTemp("flat.csv", "time_s,position_m,force_N\n0,0.01,1\n0.1,0.01,2\n0.2,0.01,3\n")),
              HasSubstr("flat.csv: position_m: the piston never moves"));
}

}  // namespace
}  // namespace swingsim
