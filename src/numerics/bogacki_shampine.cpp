#include "numerics/bogacki_shampine.h"

#include "numerics/step_error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace swingsim {

namespace {

// Bogacki & Shampine (1989), Eq. (3): nodes, coefficients, 3rd-order weights (also the
// 4th stage: FSAL) and the 2nd-order weights; the error estimate is y3 - y2.
constexpr double c2 = 1.0 / 2, c3 = 3.0 / 4;
constexpr double a21 = 1.0 / 2;
constexpr double a32 = 3.0 / 4;
constexpr double b1 = 2.0 / 9, b2 = 1.0 / 3, b3 = 4.0 / 9;
constexpr double e1 = 2.0 / 9 - 7.0 / 24, e2 = 1.0 / 3 - 1.0 / 4, e3 = 4.0 / 9 - 1.0 / 3, e4 = -1.0 / 8;

constexpr double kSafety = 0.9;
constexpr double kMinShrink = 0.2;
constexpr double kMaxGrow = 5.0;
constexpr double kExponent = 1.0 / 3;  // the error estimate is O(h^3)

}  // namespace

BogackiShampine::BogackiShampine(const OdeSystem& system, double relTol, double absTol)
    : system_(system), n_(system.numStates()), relTol_(relTol), absTol_(absTol) {
  if (n_ <= 0) throw std::invalid_argument("Bogacki-Shampine: the system has no states");
  checkStepTolerances("Bogacki-Shampine", relTol, absTol);
  for (auto* v : {&y_, &yNew_, &yStage_, &yErr_, &k1_, &k2_, &k3_, &k4_}) v->assign(static_cast<std::size_t>(n_), 0.0);
}

void BogackiShampine::initialize(double t0, const double* y0, const double* dydt0, double firstStep) {
  if (!(firstStep > 0) || !std::isfinite(firstStep))
    throw std::invalid_argument("Bogacki-Shampine: the first step must be positive and finite");
  t_ = t0;
  std::copy(y0, y0 + n_, y_.begin());
  std::copy(dydt0, dydt0 + n_, k1_.begin());
  h_ = firstStep;
  numSteps_ = numRejected_ = numEvaluations_ = 0;
}

void BogackiShampine::step(double tStop) {
  if (!(tStop > t_)) throw std::invalid_argument("Bogacki-Shampine: step end must lie after the current time");
  const double hMin = 16 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(t_));
  bool rejected = false;
  while (true) {
    double h = h_;
    bool clipped = false;
    if (t_ + h >= tStop - hMin) {
      h = tStop - t_;
      clipped = true;
    }
    if (h < hMin && !clipped)
      throw std::runtime_error("Bogacki-Shampine: step size underflow at t = " + std::to_string(t_) + " s");
    const double* y = y_.data();
    double* ys = yStage_.data();
    for (int i = 0; i < n_; ++i) ys[i] = y[i] + h * a21 * k1_[i];
    system_.calcDerivatives(t_ + c2 * h, ys, k2_.data());
    for (int i = 0; i < n_; ++i) ys[i] = y[i] + h * a32 * k2_[i];
    system_.calcDerivatives(t_ + c3 * h, ys, k3_.data());
    for (int i = 0; i < n_; ++i) yNew_[i] = y[i] + h * (b1 * k1_[i] + b2 * k2_[i] + b3 * k3_[i]);
    const double tNew = clipped ? tStop : t_ + h;
    system_.calcDerivatives(tNew, yNew_.data(), k4_.data());
    numEvaluations_ += 3;
    for (int i = 0; i < n_; ++i) yErr_[i] = h * (e1 * k1_[i] + e2 * k2_[i] + e3 * k3_[i] + e4 * k4_[i]);
    const double err = calcStepErrorNorm(y_, yNew_, yErr_, relTol_, absTol_);
    if (!std::isfinite(err))
      throw std::runtime_error("Bogacki-Shampine: the state became non-finite at t = " + std::to_string(t_) + " s");
    if (err <= 1.0) {
      double grow = err == 0 ? kMaxGrow : std::clamp(kSafety * std::pow(err, -kExponent), kMinShrink, kMaxGrow);
      if (rejected) grow = std::min(grow, 1.0);
      h_ = clipped ? std::max(h_, h * grow) : h * grow;
      t_ = tNew;
      y_.swap(yNew_);
      k1_.swap(k4_);  // FSAL
      ++numSteps_;
      return;
    }
    ++numRejected_;
    rejected = true;
    h_ = h * std::max(kMinShrink, kSafety * std::pow(err, -kExponent));
  }
}

}  // namespace swingsim
