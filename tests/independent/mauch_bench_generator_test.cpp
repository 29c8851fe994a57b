// The independent bench generator's moving mass: its closed-form piston acceleration against
// a central difference of its own velocity, and the force it adds (m xdd, nothing else).
#include "mauch_bench_generator.h"

#include <gtest/gtest.h>

namespace {

// A central difference over 2h = 2e-5 s has truncation error ~h^2/6 |x''''| ~ 1e-8 m/s^2
// for these bumps; rounding of xd (~1e-17) / h ~ 1e-12. Far below the 1.8 m/s^2 RMS.
constexpr double kDifferenceStep = 1e-5;
constexpr double kDifferenceTol = 1e-5;  // m/s^2

TEST(MauchBenchGenerator, AccelerationIsTheVelocitysDerivative) {
  double largest = 0;
  for (const auto& g : independent::chienGaits()) {
    for (double t = 0.0; t < g.stride; t += g.stride / 97.0) {
      double x, xdPlus, xdMinus;
      independent::pistonMotion(t + kDifferenceStep, g, x, xdPlus);
      independent::pistonMotion(t - kDifferenceStep + g.stride, g, x, xdMinus);  // a stride later: same motion
      const double difference = (xdPlus - xdMinus) / (2.0 * kDifferenceStep);
      EXPECT_NEAR(independent::pistonAcceleration(t, g), difference, kDifferenceTol) << g.name << " t " << t;
      largest = std::max(largest, std::abs(difference));
    }
  }
  EXPECT_GT(largest, 1.0);  // the swing flexion accelerates the piston by several m/s^2
}

TEST(MauchBenchGenerator, MovingMassAddsMassTimesAcceleration) {
  constexpr double kMassKg = 10.0;
  independent::MauchTruth still = independent::drawTruth(4, 7), moving = still;
  moving.movingMass = kMassKg;
  const independent::Gait g = independent::chienGaits()[1];
  const auto a = independent::generate(still, g, 0.0, 1), b = independent::generate(moving, g, 0.0, 1);
  ASSERT_EQ(a.cleanForce.size(), b.cleanForce.size());
  for (std::size_t i = 0; i < a.time.size(); i += 37)
    EXPECT_NEAR(b.cleanForce[i] - a.cleanForce[i], kMassKg * independent::pistonAcceleration(a.time[i], g), 1e-9)
        << "t " << a.time[i];
}

}  // namespace
