#include "numerics/dormand_prince.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace swingsim {
namespace {

constexpr double kPiTest = 3.14159265358979323846;

// y' = lambda y.
class Decay final : public OdeSystem {
 public:
  explicit Decay(double lambda) : lambda_(lambda) {}
  int numStates() const override { return 1; }
  void calcDerivatives(double, const double* y, double* dydt) const override { dydt[0] = lambda_ * y[0]; }

 private:
  double lambda_;
};

// Harmonic oscillator x'' = -w^2 x as (x, x').
class Oscillator final : public OdeSystem {
 public:
  explicit Oscillator(double omega) : omega_(omega) {}
  int numStates() const override { return 2; }
  void calcDerivatives(double, const double* y, double* dydt) const override {
    dydt[0] = y[1];
    dydt[1] = -omega_ * omega_ * y[0];
  }

 private:
  double omega_;
};

// Compound pendulum about a fixed pivot: I_pivot theta'' = -m g a sin(theta).
class CompoundPendulum final : public OdeSystem {
 public:
  CompoundPendulum(double mass, double comDistance, double inertiaAboutCom)
      : mga_(mass * 9.81 * comDistance), inertiaAboutPivot_(inertiaAboutCom + mass * comDistance * comDistance) {}
  int numStates() const override { return 2; }
  void calcDerivatives(double, const double* y, double* dydt) const override {
    dydt[0] = y[1];
    dydt[1] = -mga_ / inertiaAboutPivot_ * std::sin(y[0]);
  }
  double calcSmallAnglePeriod() const { return 2 * kPiTest * std::sqrt(inertiaAboutPivot_ / mga_); }

 private:
  double mga_, inertiaAboutPivot_;
};

TEST(DormandPrince, RejectsBadTolerances) {
  Decay decay(-1);
  EXPECT_THROW(DormandPrince(decay, 0, 1e-8), std::invalid_argument);
  EXPECT_THROW(DormandPrince(decay, 1e-8, -1), std::invalid_argument);
  EXPECT_THROW(DormandPrince(decay, NAN, 1e-8), std::invalid_argument);
}

TEST(DormandPrince, GlobalErrorFollowsTheTolerance) {
  // Exact: y(t) = exp(-2 t). The global error of an error-per-step controlled method
  // stays within a small multiple of the tolerance over a few time constants.
  constexpr double kGlobalErrorFactor = 10;  // accumulation over ~50 steps, with damping
  Decay decay(-2);
  for (double tol : {1e-6, 1e-9, 1e-12}) {
    DormandPrince dp(decay, tol, tol);
    const double y0 = 1;
    dp.initialize(0, &y0);
    dp.integrateTo(2.0);
    EXPECT_EQ(dp.getTime(), 2.0);
    EXPECT_NEAR(dp.getState()[0], std::exp(-4.0), kGlobalErrorFactor * tol) << "tol " << tol;
  }
}

// What a method taking over at a step end needs (the swing's loose settle dwell hands over
// to Bogacki-Shampine): f at the step end, without a new evaluation, and the planned step.
TEST(DormandPrince, GivesTheDerivativeAndThePlannedStepAtTheStepEnd) {
  Oscillator osc(2 * kPiTest);
  DormandPrince dp(osc, 1e-8, 1e-8);
  const double y0[2] = {1, 0};
  dp.initialize(0, y0);
  dp.step(0.3);
  const long evaluations = dp.getNumEvaluations();
  double f[2];
  osc.calcDerivatives(dp.getTime(), dp.getState(), f);
  EXPECT_EQ(dp.getDerivatives()[0], f[0]);
  EXPECT_EQ(dp.getDerivatives()[1], f[1]);
  EXPECT_EQ(dp.getNumEvaluations(), evaluations);
  EXPECT_GT(dp.getPlannedStep(), 0.0);
  EXPECT_LT(dp.getPlannedStep(), 0.3);  // a 1e-8 step of a 1 s period
}

TEST(DormandPrince, TighterToleranceTakesMoreStepsAtFifthOrderRate) {
  // For a 5th-order pair the step count grows like tol^(-1/5): 1e-4 tighter -> ~6.3x steps.
  constexpr double kMinRatio = 3, kMaxRatio = 12;  // loose bracket around 10^(4/5) = 6.3
  Oscillator osc(2 * kPiTest);
  auto steps = [&](double tol) {
    DormandPrince dp(osc, tol, tol);
    const double y0[2] = {1, 0};
    dp.initialize(0, y0);
    dp.integrateTo(3.0);
    return static_cast<double>(dp.getNumSteps());
  };
  const double ratio = steps(1e-10) / steps(1e-6);
  EXPECT_GT(ratio, kMinRatio);
  EXPECT_LT(ratio, kMaxRatio);
}

TEST(DormandPrince, LandsExactlyOnStopTimesAndDenseOutputIsAccurate) {
  constexpr double kTol = 1e-10;
  // The continuous extension is 4th order: its error is of the order of the local error.
  constexpr double kDenseTol = 100 * kTol;
  const double omega = 3.0;
  Oscillator osc(omega);
  DormandPrince dp(osc, kTol, kTol);
  const double y0[2] = {1, 0};
  dp.initialize(0, y0);
  // Includes two stops one ulp apart, closer than any normal step could be.
  for (double stop : {0.0123, 0.5, 0.5000001, 0.5000001 + 1e-16, 1.7}) {
    while (dp.getTime() < stop) {
      dp.step(stop);
      // Dense output inside the step against the exact solution.
      const double t0 = dp.getStepStartTime(), t1 = dp.getTime();
      for (double s : {0.0, 0.25, 0.5, 0.9, 1.0}) {
        const double t = t0 + s * (t1 - t0);
        EXPECT_NEAR(dp.interpolate(t, 0), std::cos(omega * t), kDenseTol);
        EXPECT_NEAR(dp.interpolate(t, 1), -omega * std::sin(omega * t), omega * kDenseTol);
      }
    }
    EXPECT_EQ(dp.getTime(), stop);
    EXPECT_NEAR(dp.getState()[0], std::cos(omega * stop), kDenseTol);
  }
  EXPECT_THROW(dp.step(1.0), std::invalid_argument);  // stop before the current time
}

TEST(DormandPrince, CompoundPendulumSmallAnglePeriod) {
  // Burkett P1's thigh as a compound pendulum about the hip (Table 2).
  CompoundPendulum pendulum(3.350, 0.410 - 0.284, 0.0264);
  constexpr double kAmplitude = 1e-3;  // rad
  // Relative period error allowed: the finite-amplitude correction amplitude^2/16 = 6e-8
  // plus the integrator (1e-12 tolerance) and the crossing search (1e-13 s).
  constexpr double kPeriodRelTol = 2e-7;
  DormandPrince dp(pendulum, 1e-12, 1e-14);
  const double y0[2] = {kAmplitude, 0};
  dp.initialize(0, y0);
  // Downward zero crossings of the angle, located by bisection on the dense output.
  std::vector<double> crossings;
  double before = kAmplitude;
  while (crossings.size() < 6) {
    dp.step(100.0);
    const double after = dp.getState()[0];
    if (before > 0 && after <= 0) {
      double lo = dp.getStepStartTime(), hi = dp.getTime();
      while (hi - lo > 1e-13) {
        const double mid = 0.5 * (lo + hi);
        (dp.interpolate(mid, 0) > 0 ? lo : hi) = mid;
      }
      crossings.push_back(0.5 * (lo + hi));
    }
    before = after;
  }
  const double period = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  const double expected = pendulum.calcSmallAnglePeriod();
  EXPECT_NEAR(period / expected - 1, 0, kPeriodRelTol) << "period " << period << " s, formula " << expected << " s";
  std::printf("Dormand-Prince compound pendulum: period %.9f s, formula %.9f s, relative error %.1e\n", period,
              expected, period / expected - 1);
}

}  // namespace
}  // namespace swingsim
