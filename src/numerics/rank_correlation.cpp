#include "numerics/rank_correlation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "numerics/residual_analysis.h"

namespace swingsim {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Fieller, Hartley & Pearson 1957: var(z) of Spearman's rho is about 1.060 / (n - 3).
constexpr double kSpearmanZVariance = 1.060;

double calcPearson(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = static_cast<double>(a.size());
  const double ma = std::accumulate(a.begin(), a.end(), 0.0) / n;
  const double mb = std::accumulate(b.begin(), b.end(), 0.0) / n;
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  if (saa <= 0 || sbb <= 0) return kNaN;
  return std::clamp(sab / std::sqrt(saa * sbb), -1.0, 1.0);
}

}  // namespace

std::vector<double> calcAverageRanks(const std::vector<double>& values) {
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  std::vector<double> ranks(values.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && values[order[j + 1]] == values[order[i]]) ++j;
    const double rank = 0.5 * static_cast<double>(i + j) + 1.0;  // average of ranks i+1 .. j+1
    for (std::size_t k = i; k <= j; ++k) ranks[order[k]] = rank;
    i = j + 1;
  }
  return ranks;
}

RankCorrelation calcSpearman(const std::vector<double>& x, const std::vector<double>& y, double confidence) {
  if (x.size() != y.size())
    throw std::invalid_argument("calcSpearman: " + std::to_string(x.size()) + " x values but " +
                                std::to_string(y.size()) + " y values");
  if (!(confidence > 0 && confidence < 1))
    throw std::invalid_argument("calcSpearman: confidence must be inside (0, 1), got " + std::to_string(confidence));
  std::vector<double> xs, ys;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (std::isfinite(x[i]) && std::isfinite(y[i])) {
      xs.push_back(x[i]);
      ys.push_back(y[i]);
    }
  RankCorrelation r;
  r.count = static_cast<int>(xs.size());
  r.rho = r.low = r.high = kNaN;
  if (r.count < 3) return r;
  r.rho = calcPearson(calcAverageRanks(xs), calcAverageRanks(ys));
  if (std::isnan(r.rho) || r.count < 4) return r;
  if (std::fabs(r.rho) >= 1) {
    r.low = r.high = r.rho;
    return r;
  }
  const double z = std::atanh(r.rho);
  const double half = calcNormalQuantile(0.5 + 0.5 * confidence) * std::sqrt(kSpearmanZVariance / (r.count - 3));
  r.low = std::tanh(z - half);
  r.high = std::tanh(z + half);
  return r;
}

}  // namespace swingsim
