#include "numerics/residual_analysis.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace swingsim {

namespace {

// Two-sided 99 % normal quantile.
constexpr double kZ99 = 2.5758293035489004;

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

double calcChiSquaredSurvival(double x, double dof) {
  if (!(x > 0)) return 1.0;
  // Regularised upper incomplete gamma Q(dof/2, x/2) (Numerical Recipes: series below a+1,
  // continued fraction above).
  const double a = 0.5 * dof, z = 0.5 * x;
  const double lnPrefix = -z + a * std::log(z) - std::lgamma(a);
  if (z < a + 1) {
    double term = 1.0 / a, sum = term;
    for (int k = 1; k < 1000; ++k) {
      term *= z / (a + k);
      sum += term;
      if (term < sum * 1e-15) break;
    }
    return std::max(0.0, 1.0 - sum * std::exp(lnPrefix));
  }
  const double tiny = 1e-300;
  double b = z + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
  for (int i = 1; i < 1000; ++i) {
    const double an = -i * (i - a);
    b += 2;
    d = an * d + b;
    if (std::fabs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1 / d;
    const double del = d * c;
    h *= del;
    if (std::fabs(del - 1) < 1e-15) break;
  }
  return std::min(1.0, std::exp(lnPrefix) * h);
}

WhitenessTest calcWhitenessTest(const ResidualSegments& residuals, int lags) {
  WhitenessTest t;
  t.lags = lags;
  std::size_t n = 0;
  for (const auto& s : residuals) n += s.size();
  const auto acf = calcAutocorrelation(residuals, lags);
  const double N = static_cast<double>(n), band = kZ99 / std::sqrt(N);
  for (int k = 1; k <= lags; ++k) {
    const double r = acf[static_cast<std::size_t>(k)];
    t.q += r * r / (N - k);
    if (std::fabs(r) > band) ++t.lagsOutsideBand;
  }
  t.q *= N * (N + 2);
  t.pValue = calcChiSquaredSurvival(t.q, lags);
  return t;
}

BinnedResidual calcBinnedResidual(const std::vector<double>& variable, const std::vector<double>& residual, int bins,
                                  double nEffOverN) {
  if (variable.size() != residual.size()) throw std::invalid_argument("calcBinnedResidual: sizes differ");
  BinnedResidual out;
  const std::size_t n = variable.size();
  if (n == 0 || bins < 1) return out;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return variable[a] < variable[b]; });
  const double ratio = std::clamp(nEffOverN, 1e-6, 1.0);
  for (int b = 0; b < bins; ++b) {
    const std::size_t lo = n * static_cast<std::size_t>(b) / static_cast<std::size_t>(bins);
    const std::size_t hi = n * static_cast<std::size_t>(b + 1) / static_cast<std::size_t>(bins);
    if (hi <= lo + 1) continue;
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
    out.mean.push_back(mean);
    out.halfWidth.push_back(half);
    const double sig = half > 0 ? std::fabs(mean) / half : 0.0;
    if (sig > out.maxSignificance) {
      out.maxSignificance = sig;
      out.maxBin = out.center.size() - 1;
    }
  }
  return out;
}

}  // namespace swingsim
