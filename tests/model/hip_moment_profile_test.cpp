// The hip moment profile: its kinks (breakpoints), where the default integrator ends a step.
#include "model/hip_moment_profile.h"

#include <gtest/gtest.h>

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
