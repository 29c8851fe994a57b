#include "numerics/bogacki_shampine.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace swingsim {
namespace {

// Harmonic oscillator x'' = -w^2 x as (x, x'): x = cos(w t) from (1, 0).
class Oscillator final : public OdeSystem {
 public:
  explicit Oscillator(double omega) : omega_(omega) {}
  int numStates() const override { return 2; }
  void calcDerivatives(double, const double* y, double* dydt) const override {
    ++evaluations;
    dydt[0] = y[1];
    dydt[1] = -omega_ * omega_ * y[0];
  }
  mutable long evaluations = 0;

 private:
  double omega_;
};

struct Outcome {
  double error;  // |x - cos(w t)| at the end
  long steps, evaluations, rejected;
};

Outcome integrate(double tol, double tEnd) {
  const double omega = 3.0;
  Oscillator ode(omega);
  BogackiShampine bs(ode, tol, tol);
  const double y0[2] = {1.0, 0.0}, f0[2] = {0.0, -omega * omega};
  bs.initialize(0.0, y0, f0, 1e-3);
  while (bs.getTime() < tEnd) bs.step(tEnd);
  EXPECT_EQ(bs.getTime(), tEnd);  // lands on the stop time exactly
  return {std::fabs(bs.getState()[0] - std::cos(omega * tEnd)), bs.getNumSteps(), ode.evaluations,
          bs.getNumRejectedSteps()};
}

// Against the exact solution: the global error follows the tolerance (a 3rd-order method
// under error-per-step control: 100x tighter, about 100x smaller, and well within 100
// tolerances over 4 periods), and steps cost three evaluations each (FSAL), rejected ones
// included.
TEST(BogackiShampine, OscillatorErrorFollowsTheToleranceAtThreeEvaluationsPerStep) {
  const Outcome loose = integrate(1e-4, 8.0), tight = integrate(1e-6, 8.0);
  EXPECT_LT(loose.error, 100 * 1e-4);
  EXPECT_LT(tight.error, 100 * 1e-6);
  EXPECT_GT(loose.error / tight.error, 20.0);
  EXPECT_LT(loose.error / tight.error, 500.0);
  for (const Outcome& r : {loose, tight}) EXPECT_EQ(r.evaluations, 3 * (r.steps + r.rejected));
  // A 3rd-order method: 100x tighter costs about 100^(1/3) = 4.6x the steps.
  const double ratio = static_cast<double>(tight.steps) / static_cast<double>(loose.steps);
  EXPECT_GT(ratio, 3.0);
  EXPECT_LT(ratio, 7.0);
}

TEST(BogackiShampine, StartsFromTheGivenDerivativeWithoutEvaluating) {
  Oscillator ode(1.0);
  BogackiShampine bs(ode, 1e-5, 1e-5);
  const double y0[2] = {1.0, 0.0}, f0[2] = {0.0, -1.0};
  bs.initialize(2.0, y0, f0, 0.01);
  EXPECT_EQ(ode.evaluations, 0);
  EXPECT_EQ(bs.getTime(), 2.0);
  bs.step(2.005);  // shorter than the first step: clipped to it
  EXPECT_EQ(bs.getTime(), 2.005);
  EXPECT_NEAR(bs.getState()[0], std::cos(0.005), 1e-9);
  EXPECT_NEAR(bs.getDerivatives()[1], -bs.getState()[0], 1e-15);  // f at the step end
}

TEST(BogackiShampine, RejectsBadSettings) {
  Oscillator ode(1.0);
  EXPECT_THROW(BogackiShampine(ode, 0, 1e-6), std::invalid_argument);
  EXPECT_THROW(BogackiShampine(ode, 1e-6, -1), std::invalid_argument);
  BogackiShampine bs(ode, 1e-6, 1e-6);
  const double y0[2] = {1.0, 0.0}, f0[2] = {0.0, -1.0};
  EXPECT_THROW(bs.initialize(0, y0, f0, 0), std::invalid_argument);
  bs.initialize(0, y0, f0, 0.1);
  EXPECT_THROW(bs.step(0), std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
