// The cylinder bench inputs (io/bench_csv.h): a bench record read whole with its velocity
// estimate, refused when its position is in millimetres or out of the plausible ranges; a
// knee-angle stride cut from a Winter-style file by frame, in radians, the closing heel
// strike dropped. (Errors every CSV shares: tests/io/csv_table_test.cpp.)
#include "io/bench_csv.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/input_error.h"
#include "core/units.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

constexpr double kRoundOff = 1e-12;

std::string writeTemp(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "swingsim_bench_csv_test";
  std::filesystem::create_directories(dir);
  const auto path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

template <class F>
std::string inputErrorOf(F read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(BenchCsv, ReadsTheRecordWithItsVelocityEstimate) {
  const std::string path =
      writeTemp("steady.csv", "time_s,position_m,force_N\n0,0,5\n0.01,0.001,6\n0.02,0.002,7\n0.03,0.003,8\n");
  const BenchData d = readBenchCsv(path, 1);
  EXPECT_EQ(d.path, path);
  EXPECT_EQ(d.stem, "steady");
  EXPECT_EQ(d.force, (std::vector<double>{5, 6, 7, 8}));
  ASSERT_EQ(d.velocity.size(), 4u);
  for (double v : d.velocity) EXPECT_NEAR(v, 0.1, kRoundOff) << "a piston moving at 0.1 m/s";
  EXPECT_THAT(
      inputErrorOf([&] { readBenchCsv(writeTemp("two.csv", "time_s,position_m,force_N\n0,0,5\n0.01,0.001,6\n"), 1); }),
      HasSubstr("too few data rows (got 2, need at least 3)"))
      << "at least 3 rows whatever is asked";
}

TEST(BenchCsv, PositionInMillimetresAndImplausibleValuesAreRefused) {
  EXPECT_THAT(inputErrorOf([&] {
                readBenchCsv(writeTemp("mm.csv", "time_s,position_m,force_N\n0,0,5\n0.01,12,6\n0.02,24,7\n"), 3);
              }),
              HasSubstr("mm.csv: position_m: the piston reaches 24 m (a knee cylinder's stroke is a few centimetres; "
                        "more than 1 m): the column looks like millimetres, expected metres"));
  EXPECT_THAT(inputErrorOf([&] {
                readBenchCsv(writeTemp("kn.csv", "time_s,position_m,force_N\n0,0,5\n0.01,0.001,2e6\n0.02,0.002,7\n"),
                             3);
              }),
              HasSubstr("kn.csv:3: force_N: expected a force in"));
  EXPECT_THAT(inputErrorOf([&] {
                readBenchCsv(writeTemp("dense.csv", "time_s,position_m,force_N\n0,0,5\n1e-12,0.001,6\n0.02,0.002,7\n"),
                             3);
              }),
              HasSubstr("dense.csv:3: time_s: expected steps of at least"));
}

// Frames 1-12 of a Winter-style file: knee_deg = 5 x frame.
std::string winterStyle() {
  std::string text = "frame,time_s,knee_deg\n";
  for (int f = 1; f <= 12; ++f)
    text += std::to_string(f) + "," + std::to_string(0.01 * f) + "," + std::to_string(5 * f) + "\n";
  return text;
}

TEST(BenchCsv, KneeAngleStrideTakesItsFramesInRadiansWithoutTheClosingHeelStrike) {
  const std::string path = writeTemp("winter.csv", winterStyle());
  const KneeAngleStride s = readKneeAngleStride(path, 2, 11);
  EXPECT_EQ(s.source, path);
  ASSERT_EQ(s.flexion.size(), 9u) << "frames 2 to 10: frame 11 is the next heel strike";
  EXPECT_NEAR(s.flexion.front(), 10 * kDegToRad, kRoundOff);
  EXPECT_NEAR(s.flexion.back(), 50 * kDegToRad, kRoundOff);
}

TEST(BenchCsv, KneeAngleStrideRefusesTooFewOrMissingFrames) {
  const std::string path = writeTemp("winter.csv", winterStyle());
  EXPECT_EQ(inputErrorOf([&] { readKneeAngleStride(path, 2, 9); }),
            path + ": stride frames 2-9: need at least 8 frames per stride");
  EXPECT_EQ(inputErrorOf([&] { readKneeAngleStride(path, 5, 20); }),
            path + ": frame: frames 5 to 20 are not all present (found 8)");
  const std::string far = writeTemp("far.csv", "frame,knee_deg\n1,5\n2,900\n");
  EXPECT_THAT(inputErrorOf([&] { readKneeAngleStride(far, 1, 9); }),
              StartsWith(far + ":3: knee_deg: expected a knee angle in"));
}

}  // namespace
}  // namespace swingsim
