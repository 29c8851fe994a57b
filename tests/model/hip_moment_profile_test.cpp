// The hip moment profile: its kinks (breakpoints), where the default integrator ends a step.
#include "model/hip_moment_profile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace swingsim {
namespace {

// The slope on either side of t, by one-sided differences over dt.
double slopeJump(const HipMomentProfile& h, double t) {
  constexpr double dt = 1e-7;  // s
  const double left = (h.calcMoment(t) - h.calcMoment(t - dt)) / dt;
  const double right = (h.calcMoment(t + dt) - h.calcMoment(t)) / dt;
  return std::fabs(right - left);
}

TEST(HipMomentProfile, BreakpointsAreTheHalfSineEndsStretchedByTheTimeScale) {
  HipMomentProfile h;  // 30 N m for 0.20 s, then 15 N m for 0.20 s
  h.timeScale = 1.25;
  const auto b = h.calcBreakpoints();
  ASSERT_EQ(b.size(), 2u);
  EXPECT_DOUBLE_EQ(b[0], 0.25);
  EXPECT_DOUBLE_EQ(b[1], 0.50);
  // They are kinks: the slope jumps there (by 30 pi/0.2 + 15 pi/0.2 over tau^3 at the
  // first: 453 N m/s at tau = 1.25), and not half-way through a half-sine.
  EXPECT_GT(slopeJump(h, b[0]), 100.0);
  EXPECT_GT(slopeJump(h, b[1]), 100.0);
  EXPECT_LT(slopeJump(h, 0.125), 1e-3);
}

TEST(HipMomentProfile, TableBreakpointsAreItsEndsWhereTheHeldValuesBegin) {
  HipMomentProfile h;
  h.kind = HipMomentProfile::Kind::kTable;
  h.times = {0.05, 0.1, 0.2, 0.3};
  h.moments = {0, 20, -10, 5};
  h.timeScale = 2.0;
  const auto b = h.calcBreakpoints();
  ASSERT_EQ(b.size(), 2u);
  EXPECT_DOUBLE_EQ(b[0], 0.1);
  EXPECT_DOUBLE_EQ(b[1], 0.6);
  // A table starting at t = 0 has no breakpoint there (nothing happens before toe-off).
  h.times = {0, 0.1, 0.2};
  h.moments = {0, 20, 0};
  ASSERT_EQ(h.calcBreakpoints().size(), 1u);
  EXPECT_DOUBLE_EQ(h.calcBreakpoints()[0], 0.4);
}

}  // namespace
}  // namespace swingsim

namespace swingsim {
namespace {

// calcRangeFrom against a dense scan of the moment from t on: every scanned moment inside
// the range, and the range's ends met by the scan (to its resolution).
TEST(HipMomentProfile, RangeFromBoundsEveryLaterMomentTightly) {
  HipMomentProfile sine;
  sine.flexionAmplitude = 30;
  sine.extensionAmplitude = 12;
  sine.flexionDuration = 0.18;
  sine.extensionDuration = 0.23;
  sine.timeScale = 1.1;
  HipMomentProfile table;
  table.kind = HipMomentProfile::Kind::kTable;
  table.times = {0.0, 0.1, 0.2, 0.3, 0.45};
  table.moments = {5, 25, -4, -14, -2};
  table.timeScale = 0.9;
  for (const HipMomentProfile* profile : {&sine, &table}) {
    for (double t = 0; t < 0.7; t += 0.013) {
      const auto [low, high] = profile->calcRangeFrom(t);
      double seenLow = 1e9, seenHigh = -1e9;
      for (double u = t; u < 2.0; u += 1e-4) {
        const double m = profile->calcMoment(u);
        EXPECT_GE(m, low - 1e-12) << t << " " << u;
        EXPECT_LE(m, high + 1e-12) << t << " " << u;
        seenLow = std::min(seenLow, m);
        seenHigh = std::max(seenHigh, m);
      }
      // The scan's 0.1 ms steps pass a table sample by at most 0.05 ms: 250 N m/s x 5e-5 s.
      EXPECT_NEAR(seenLow, low, 0.02) << t;
      EXPECT_NEAR(seenHigh, high, 0.02) << t;
    }
  }
}

}  // namespace
}  // namespace swingsim
