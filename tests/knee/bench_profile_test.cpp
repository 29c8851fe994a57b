#include "knee/bench_profile.h"
#include "core/units.h"
#include "io/bench_csv.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/input_error.h"

namespace swingsim {
namespace {

constexpr double kDeg = kDegToRad;
const std::string kWinter = std::string(SWINGSIM_SOURCE_DIR) + "/studies/data/winter-natural-cadence.csv";

TEST(BenchProfile, ReadsOneWinterStrideHeelStrikeToHeelStrike) {
  const auto stride = readKneeAngleStride(kWinter, 28, 97);
  ASSERT_EQ(stride.flexion.size(), 69u);
  EXPECT_NEAR(stride.flexion.front(), -0.6 * kDeg, 1e-12);  // frame 28, heel strike
  EXPECT_NEAR(*std::max_element(stride.flexion.begin(), stride.flexion.end()), 66.6 * kDeg, 1e-12);
  EXPECT_THROW(readKneeAngleStride(kWinter, 100, 140), InputError);
}

TEST(BenchProfile, SamplesFiveCyclesAtBenchRateWithHeldHyperextension) {
  const auto stride = readKneeAngleStride(kWinter, 28, 97);
  BenchProfileParams p;  // normal: 0.987 s, 361.4 Hz, 5 cycles, -4 deg, hold 4
  const KneeGeometry g;
  const auto prof = makeBenchProfile(stride, p, g);
  EXPECT_EQ(prof.time.size(), static_cast<std::size_t>(std::floor(5 * 0.987 * 361.4)));
  EXPECT_NEAR(prof.time[1], 1 / 361.4, 1e-15);
  // Each cycle: the minimum sample and 4 either side sit exactly at -4 deg.
  const auto held = std::count(prof.flexion.begin(), prof.flexion.end(), p.hyperextension);
  EXPECT_EQ(held, 5 * 9);
  EXPECT_DOUBLE_EQ(*std::min_element(prof.flexion.begin(), prof.flexion.end()), p.hyperextension);
  // Positions follow Eq. 1: hyperextension is x < 0.
  EXPECT_DOUBLE_EQ(*std::min_element(prof.position.begin(), prof.position.end()),
                   g.calcPistonPosition(p.hyperextension));
}

TEST(BenchProfile, ModificationKeepsPeaksAndTerminalSwingAboveHyperextension) {
  const auto stride = readKneeAngleStride(kWinter, 28, 97);
  BenchProfileParams p;
  BenchProfileParams unmodified = p;
  unmodified.hyperextension = -1e-9;  // stance minimum barely moved
  // Offset: Winter's lowest point (-3 deg, terminal swing) is moved to +3 deg: +6 deg.
  double swingPeak = -1, swingPeakRaw = -1, lowestSwing = 1;
  for (int i = 0; i < 4000; ++i) {
    const double s = i / 4000.0;
    swingPeak = std::max(swingPeak, calcModifiedFlexion(stride, p, s));
    swingPeakRaw = std::max(swingPeakRaw, stride.flexion.empty() ? 0 : calcModifiedFlexion(stride, unmodified, s));
    if (s > 0.85) lowestSwing = std::min(lowestSwing, calcModifiedFlexion(stride, p, s));
  }
  EXPECT_NEAR(swingPeak, swingPeakRaw, 1e-12);
  EXPECT_NEAR(swingPeak, (66.6 + 6.0) * kDeg, 0.2 * kDeg);  // interpolation may overshoot a frame
  EXPECT_NEAR(lowestSwing, 3.0 * kDeg, 0.05 * kDeg);
}

TEST(BenchProfile, TimeAndAmplitudeScaling) {
  const auto stride = readKneeAngleStride(kWinter, 28, 97);
  BenchProfileParams fast;
  fast.strideTime = 0.96;
  fast.amplitudeScale = 1.05;
  const auto prof = makeBenchProfile(stride, fast, KneeGeometry());
  EXPECT_LT(prof.time.back(), 5 * 0.96);
  EXPECT_GT(prof.time.back(), 5 * 0.96 - 2 / 361.4);
  // Heel strikes 0.96 s apart: the profile repeats with the stride.
  const auto lag = static_cast<std::size_t>(std::lround(0.96 * 361.4));
  EXPECT_NEAR(prof.flexion[10], calcModifiedFlexion(stride, fast, prof.time[10] / 0.96), 1e-15);
  EXPECT_NEAR(calcModifiedFlexion(stride, fast, 0.3), calcModifiedFlexion(stride, fast, 1.3), 1e-12);
  (void)lag;
  BenchProfileParams bad;
  bad.hyperextension = 30 * kDeg;  // above the stance minimum
  EXPECT_THROW(makeBenchProfile(stride, bad, KneeGeometry()), std::invalid_argument);
  bad = BenchProfileParams();
  bad.strideTime = 0;
  EXPECT_THROW(makeBenchProfile(stride, bad, KneeGeometry()), std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
