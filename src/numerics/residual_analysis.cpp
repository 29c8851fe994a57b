#include "numerics/residual_analysis.h"

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/non_central_chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/special_functions/gamma.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace swingsim {

namespace {

// Two-sided 99 % normal quantile.
const double kZ99 = calcNormalQuantile(0.995);

}  // namespace

std::vector<double> calcAutocorrelation(const ResidualSegments& residuals, int maxLag) {
  if (maxLag < 0) throw std::invalid_argument("calcAutocorrelation: maxLag must be >= 0");
  double sum = 0;
  std::size_t n = 0;
  for (const auto& s : residuals) {
    sum += std::accumulate(s.begin(), s.end(), 0.0);
    n += s.size();
  }
  if (n == 0) throw std::invalid_argument("calcAutocorrelation: no samples");
  const double mean = sum / static_cast<double>(n);
  std::vector<double> acf(static_cast<std::size_t>(maxLag) + 1, 0.0);
  for (const auto& s : residuals) {
    for (int lag = 0; lag <= maxLag; ++lag) {
      const auto L = static_cast<std::size_t>(lag);
      for (std::size_t i = L; i < s.size(); ++i) acf[L] += (s[i] - mean) * (s[i - L] - mean);
    }
  }
  const double c0 = acf[0];
  for (double& a : acf) a = c0 > 0 ? a / c0 : 0.0;
  return acf;
}

double calcEffectiveSampleSize(const ResidualSegments& residuals) {
  std::size_t n = 0;
  for (const auto& s : residuals) n += s.size();
  if (n < 2) return static_cast<double>(n);
  // Clamp: a negative rho1 would claim more independent samples than rows; 0.999 keeps
  // n_eff finite and positive for a pure misfit.
  const double rho1 = std::clamp(calcAutocorrelation(residuals, 1)[1], 0.0, 0.999);
  return static_cast<double>(n) * (1.0 - rho1) / (1.0 + rho1);
}

double calcNormalQuantile(double p) { return boost::math::quantile(boost::math::normal(), p); }

double calcChiSquaredQuantile(double p, double dof) { return boost::math::quantile(boost::math::chi_squared(dof), p); }

double calcChiSquaredSurvival(double x, double dof) {
  if (std::isnan(x) || !(dof > 0)) return std::numeric_limits<double>::quiet_NaN();
  if (!(x > 0)) return 1.0;
  if (std::isinf(x)) return 0.0;
  // Q(dof/2, x/2), the regularised upper incomplete gamma function (Boost.Math).
  return boost::math::gamma_q(0.5 * dof, 0.5 * x);
}

double calcChiSquaredPower(double lambda, double dof, double alpha) {
  const double critical = calcChiSquaredQuantile(1.0 - alpha, dof);
  if (!(lambda > 0)) return alpha;
  return boost::math::cdf(boost::math::complement(boost::math::non_central_chi_squared(dof, lambda), critical));
}

int calcRecordsForPower(double lambdaPerRecord, double dof, double alpha, double power, int maxRecords) {
  if (!(lambdaPerRecord > 0) || maxRecords < 1) return 0;
  if (calcChiSquaredPower(lambdaPerRecord * maxRecords, dof, alpha) < power) return 0;
  // Power rises with lambda: bisect on the record count.
  int lo = 0, hi = maxRecords;  // power(lo) < power (or lo = 0), power(hi) >= power
  while (hi - lo > 1) {
    const int mid = lo + (hi - lo) / 2;
    (calcChiSquaredPower(lambdaPerRecord * mid, dof, alpha) >= power ? hi : lo) = mid;
  }
  return hi;
}

int calcWhitenessLags(const ResidualSegments& residuals, int requested) {
  std::size_t shortest = 0;
  for (const auto& s : residuals)
    if (!s.empty() && (shortest == 0 || s.size() < shortest)) shortest = s.size();
  const auto limit = static_cast<int>(std::min<std::size_t>(shortest / kWhitenessLagDivisor, 1000000));
  return std::max(0, std::min(requested, limit));
}

WhitenessTest calcWhitenessTest(const ResidualSegments& residuals, int lags) {
  WhitenessTest t;
  t.requestedLags = lags;
  t.lags = calcWhitenessLags(residuals, lags);
  std::size_t n = 0, shortest = 0;
  for (const auto& s : residuals) {
    n += s.size();
    if (!s.empty() && (shortest == 0 || s.size() < shortest)) shortest = s.size();
    for (double v : s)
      if (!std::isfinite(v)) {
        t.note = "the residual holds a non-finite value";
        return t;
      }
  }
  if (t.lags < kMinWhitenessLags) {
    t.note = "the shortest record has " + std::to_string(shortest) + " samples, too few for " +
             std::to_string(kMinWhitenessLags) + " lags (at most 1 lag per " + std::to_string(kWhitenessLagDivisor) +
             " samples)";
    return t;
  }
  const auto acf = calcAutocorrelation(residuals, t.lags);
  const double N = static_cast<double>(n), band = kZ99 / std::sqrt(N);
  for (int k = 1; k <= t.lags; ++k) {
    const double r = acf[static_cast<std::size_t>(k)];
    t.q += r * r / (N - k);
    if (std::fabs(r) > band) ++t.lagsOutsideBand;
  }
  t.q *= N * (N + 2);
  t.pValue = calcChiSquaredSurvival(t.q, t.lags);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& s : residuals)
    for (double v : s) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  if (!(hi > lo)) {
    t.note = "the residual is constant";
  } else if (!std::isfinite(t.q) || !std::isfinite(t.pValue)) {
    t.note = "the statistic is not finite (Q = " + std::to_string(t.q) + ")";
  } else {
    t.computed = true;
    if (t.lags < lags)
      t.note = std::to_string(t.lags) + " of the " + std::to_string(lags) + " lags asked for: at most 1 lag per " +
               std::to_string(kWhitenessLagDivisor) + " samples of the shortest record (" + std::to_string(shortest) +
               ")";
  }
  return t;
}

Whiteness judgeWhiteness(const WhitenessTest& test, double alpha) {
  if (!test.computed) return Whiteness::kCannotTell;
  return test.pValue >= alpha ? Whiteness::kWhite : Whiteness::kNotWhite;
}

BinnedResidual calcBinnedResidual(const std::vector<double>& variable, const std::vector<double>& residual, int bins,
                                  double nEffOverN) {
  if (variable.size() != residual.size()) throw std::invalid_argument("calcBinnedResidual: sizes differ");
  BinnedResidual out;
  const std::size_t n = variable.size();
  if (n < kMinBinSamples || bins < 1) return out;
  bins = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(bins), n / kMinBinSamples));
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return variable[a] < variable[b] || (variable[a] == variable[b] && a < b);
  });
  const double ratio = std::clamp(nEffOverN, 1e-6, 1.0);
  for (int b = 0; b < bins; ++b) {
    const std::size_t lo = n * static_cast<std::size_t>(b) / static_cast<std::size_t>(bins);
    const std::size_t hi = n * static_cast<std::size_t>(b + 1) / static_cast<std::size_t>(bins);
    double sv = 0, sr = 0;
    for (std::size_t i = lo; i < hi; ++i) {
      sv += variable[order[i]];
      sr += residual[order[i]];
    }
    const double m = static_cast<double>(hi - lo), mean = sr / m;
    double ss = 0;
    for (std::size_t i = lo; i < hi; ++i) ss += (residual[order[i]] - mean) * (residual[order[i]] - mean);
    const double sd = std::sqrt(ss / (m - 1));
    const double half = kZ99 * sd / std::sqrt(std::max(1.0, m * ratio));
    out.center.push_back(sv / m);
    out.lower.push_back(variable[order[lo]]);
    out.upper.push_back(variable[order[hi - 1]]);
    out.mean.push_back(mean);
    out.halfWidth.push_back(half);
    const double sig = half > 0 ? std::fabs(mean) / half : 0.0;
    if (sig > out.maxSignificance) {
      out.maxSignificance = sig;
      out.maxBin = out.center.size() - 1;
    }
  }
  // The run of significant bins of the same sign around the most significant one.
  if (out.maxSignificance > 1) {
    const auto significantLike = [&](std::size_t k) {
      return out.halfWidth[k] > 0 && std::fabs(out.mean[k]) > out.halfWidth[k] &&
             (out.mean[k] > 0) == (out.mean[out.maxBin] > 0);
    };
    out.runFirst = out.runLast = out.maxBin;
    while (out.runFirst > 0 && significantLike(out.runFirst - 1)) --out.runFirst;
    while (out.runLast + 1 < out.center.size() && significantLike(out.runLast + 1)) ++out.runLast;
  }
  return out;
}

}  // namespace swingsim
