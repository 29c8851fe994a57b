#include "numerics/dormand_prince.h"

#include "numerics/step_error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace swingsim {

namespace {

// Butcher tableau of Dormand & Prince (1980), Table 2 (RK5(4)7M); Hairer I, Table II.5.2.
constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
constexpr double a21 = 1.0 / 5;
constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176, a65 = -5103.0 / 18656;
// 5th-order weights (also the 7th stage: FSAL).
constexpr double a71 = 35.0 / 384, a73 = 500.0 / 1113, a74 = 125.0 / 192, a75 = -2187.0 / 6784, a76 = 11.0 / 84;
// y5 - y4 (Hairer's DOPRI5, E1..E7).
constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200, e6 = 22.0 / 525,
                 e7 = -1.0 / 40;
// Dense output (Hairer's DOPRI5, D1..D7; Hairer I, Sec. II.6).
constexpr double d1 = -12715105075.0 / 11282082432, d3 = 87487479700.0 / 32700410799, d4 = -10690763975.0 / 1880347072,
                 d5 = 701980252875.0 / 199316789632, d6 = -1453857185.0 / 822651844, d7 = 69997945.0 / 29380423;

// Step-size controller (Hairer I, Eq. II.4.13): safety factor and limits on the change;
// with Lund's PI stabilization (Hairer II, Sec. IV.2, Eq. 2.43c; DOPRI5's BETA = 0.04): the
// new step is h * 0.9 err^(-(0.2 - 0.75 beta)) errPrev^beta, and a step that follows a
// rejection may not grow (DOPRI5). Both cut rejections where the solution has kinks (the
// damping table's cubic pieces meet with a jump in curvature, the hip moment's half-sines
// with a jump in slope).
constexpr double kSafety = 0.9;
constexpr double kMinShrink = 0.2;
constexpr double kMaxGrow = 5.0;
constexpr double kBeta = 0.04;
constexpr double kExponent = 0.2 - 0.75 * kBeta;
constexpr double kMinErrPrev = 1e-4;  // DOPRI5's floor on the remembered error

[[noreturn]] void throwUnderflow(double t) {
  throw std::runtime_error("Dormand-Prince: step size underflow at t = " + std::to_string(t) +
                           " s (the equations are too stiff or singular here)");
}

}  // namespace

DormandPrince::DormandPrince(const OdeSystem& system, double relTol, double absTol)
    : system_(system),
      n_(system.numStates()),
      relTol_(relTol),
      absTol_(absTol),
      maxStep_(std::numeric_limits<double>::infinity()) {
  if (n_ <= 0) throw std::invalid_argument("Dormand-Prince: the system has no states");
  checkStepTolerances("Dormand-Prince", relTol, absTol);
  for (auto* v : {&y_, &yPrev_, &yStage_, &yErr_, &k1_, &k2_, &k3_, &k4_, &k5_, &k6_, &k7_, &cont1_, &cont2_, &cont3_,
                  &cont4_, &cont5_})
    v->assign(static_cast<std::size_t>(n_), 0.0);
}

void DormandPrince::setMaxStep(double maxStep) {
  if (!(maxStep > 0)) throw std::invalid_argument("Dormand-Prince: the maximum step must be positive");
  maxStep_ = maxStep;
}

void DormandPrince::initialize(double t0, const double* y0) {
  t_ = tPrev_ = t0;
  std::copy(y0, y0 + n_, y_.begin());
  std::copy(y0, y0 + n_, yPrev_.begin());
  system_.calcDerivatives(t_, y_.data(), k1_.data());
  numEvaluations_ = 1;
  numSteps_ = numRejected_ = 0;
  errPrev_ = kMinErrPrev;
  // Dense output over the empty interval returns the initial state.
  for (int i = 0; i < n_; ++i) {
    cont1_[i] = y_[i];
    cont2_[i] = cont3_[i] = cont4_[i] = cont5_[i] = 0;
  }

  // Starting step size (Hairer I, Sec. II.4, algorithm (a)-(f)).
  double d0 = 0, d1n = 0;
  for (int i = 0; i < n_; ++i) {
    const double sk = absTol_ + relTol_ * std::abs(y_[i]);
    d0 += (y_[i] / sk) * (y_[i] / sk);
    d1n += (k1_[i] / sk) * (k1_[i] / sk);
  }
  d0 = std::sqrt(d0 / n_);
  d1n = std::sqrt(d1n / n_);
  double h0 = (d0 < 1e-5 || d1n < 1e-5) ? 1e-6 : 0.01 * d0 / d1n;
  h0 = std::min(h0, maxStep_);
  for (int i = 0; i < n_; ++i) yStage_[i] = y_[i] + h0 * k1_[i];
  system_.calcDerivatives(t_ + h0, yStage_.data(), k2_.data());
  ++numEvaluations_;
  double d2 = 0;
  for (int i = 0; i < n_; ++i) {
    const double sk = absTol_ + relTol_ * std::abs(y_[i]);
    d2 += ((k2_[i] - k1_[i]) / sk) * ((k2_[i] - k1_[i]) / sk);
  }
  d2 = std::sqrt(d2 / n_) / h0;
  const double dMax = std::max(d1n, d2);
  const double h1 = dMax <= 1e-15 ? std::max(1e-6, h0 * 1e-3) : std::pow(0.01 / dMax, 1.0 / 5);
  h_ = std::min({100 * h0, h1, maxStep_});
}

void DormandPrince::prepareDenseOutput(double h) {
  // Hairer's DOPRI5: y(t + s h) = c1 + s (c2 + (1-s) (c3 + s (c4 + (1-s) c5))).
  for (int i = 0; i < n_; ++i) {
    const double ydiff = y_[i] - yPrev_[i];
    const double bspl = h * k1_[i] - ydiff;  // k1_ still holds f at the step start here
    cont1_[i] = yPrev_[i];
    cont2_[i] = ydiff;
    cont3_[i] = bspl;
    cont4_[i] = ydiff - h * k7_[i] - bspl;
    cont5_[i] = h * (d1 * k1_[i] + d3 * k3_[i] + d4 * k4_[i] + d5 * k5_[i] + d6 * k6_[i] + d7 * k7_[i]);
  }
}

void DormandPrince::step(double tStop) {
  if (!(tStop > t_)) throw std::invalid_argument("Dormand-Prince: step end must lie after the current time");
  // The smallest step that still changes t in floating point.
  const double hMin = 16 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(t_));
  bool rejected = false;
  while (true) {
    const double* y = y_.data();
    double* ys = yStage_.data();
    double h = std::min(h_, maxStep_);
    bool clipped = false;
    // Land exactly on tStop; also avoid leaving a sliver shorter than hMin behind.
    if (t_ + h >= tStop - hMin) {
      h = tStop - t_;
      clipped = true;
    }
    // A clipped step may be shorter than hMin (two stop times closer than round-off): it
    // is taken as is. An unclipped one that small means the error control has given up.
    if (h < hMin && !clipped) throwUnderflow(t_);
    const double t = t_;
    for (int i = 0; i < n_; ++i) ys[i] = y[i] + h * a21 * k1_[i];
    system_.calcDerivatives(t + c2 * h, ys, k2_.data());
    for (int i = 0; i < n_; ++i) ys[i] = y[i] + h * (a31 * k1_[i] + a32 * k2_[i]);
    system_.calcDerivatives(t + c3 * h, ys, k3_.data());
    for (int i = 0; i < n_; ++i) ys[i] = y[i] + h * (a41 * k1_[i] + a42 * k2_[i] + a43 * k3_[i]);
    system_.calcDerivatives(t + c4 * h, ys, k4_.data());
    for (int i = 0; i < n_; ++i) ys[i] = y[i] + h * (a51 * k1_[i] + a52 * k2_[i] + a53 * k3_[i] + a54 * k4_[i]);
    system_.calcDerivatives(t + c5 * h, ys, k5_.data());
    for (int i = 0; i < n_; ++i)
      ys[i] = y[i] + h * (a61 * k1_[i] + a62 * k2_[i] + a63 * k3_[i] + a64 * k4_[i] + a65 * k5_[i]);
    system_.calcDerivatives(t + h, ys, k6_.data());
    for (int i = 0; i < n_; ++i)
      ys[i] = y[i] + h * (a71 * k1_[i] + a73 * k3_[i] + a74 * k4_[i] + a75 * k5_[i] + a76 * k6_[i]);
    const double tNew = clipped ? tStop : t + h;
    system_.calcDerivatives(tNew, ys, k7_.data());
    numEvaluations_ += 6;
    for (int i = 0; i < n_; ++i)
      yErr_[i] = h * (e1 * k1_[i] + e3 * k3_[i] + e4 * k4_[i] + e5 * k5_[i] + e6 * k6_[i] + e7 * k7_[i]);
    const double err = calcStepErrorNorm(y_, yStage_, yErr_, relTol_, absTol_);
    if (!std::isfinite(err)) {
      throw std::runtime_error("Dormand-Prince: the state became non-finite at t = " + std::to_string(t_) + " s");
    }
    if (err <= 1.0) {
      double grow = err == 0 ? kMaxGrow
                             : std::min(kMaxGrow, std::max(kMinShrink, kSafety * std::pow(err, -kExponent) *
                                                                           std::pow(errPrev_, kBeta)));
      if (rejected) grow = std::min(grow, 1.0);
      errPrev_ = std::max(err, kMinErrPrev);
      // A step clipped to tStop says little about the step the solution allows: keep
      // the longer of the two proposals.
      h_ = clipped ? std::max(h_, h * grow) : h * grow;
      tPrev_ = t_;
      t_ = tNew;
      yPrev_.swap(y_);   // yPrev_ = step start
      y_.swap(yStage_);  // y_ = step end; yStage_ becomes scratch
      prepareDenseOutput(h);
      k1_.swap(k7_);  // FSAL: f at the new step start
      ++numSteps_;
      return;
    }
    ++numRejected_;
    rejected = true;
    if (h < hMin) throwUnderflow(t_);
    h_ = h * std::max(kMinShrink, kSafety * std::pow(err, -kExponent));
  }
}

void DormandPrince::integrateTo(double tEnd) {
  while (t_ < tEnd) step(tEnd);
}

double DormandPrince::interpolate(double t, int i) const {
  const double h = t_ - tPrev_;
  if (h <= 0) return y_[i];
  const double s = (t - tPrev_) / h;
  const double s1 = 1.0 - s;
  return cont1_[i] + s * (cont2_[i] + s1 * (cont3_[i] + s * (cont4_[i] + s1 * cont5_[i])));
}

void DormandPrince::interpolate(double t, double* y) const {
  for (int i = 0; i < n_; ++i) y[i] = interpolate(t, i);
}

}  // namespace swingsim
