#include "numerics/noise_estimate.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace swingsim {

namespace {

// 1 / Phi^-1(3/4): the median absolute deviation of a normal variable times this is its sigma.
constexpr double kMadToSigma = 1.482602218505602;

}  // namespace

NoiseEstimate estimateNoise(const std::vector<double>& t, const std::vector<double>& y) {
  if (t.size() != y.size()) throw std::invalid_argument("estimateNoise: time and values differ in length");
  if (y.size() < 3) throw std::invalid_argument("estimateNoise: needs at least 3 samples");
  std::vector<double> pseudo;
  pseudo.reserve(y.size() - 2);
  for (std::size_t i = 1; i + 1 < y.size(); ++i) {
    // Gasser et al. 1986 Eq. 3: e_i = a y_{i-1} + b y_{i+1} - y_i with a, b the weights of the
    // line through the neighbours, scaled by 1 / sqrt(a^2 + b^2 + 1).
    const double h = t[i + 1] - t[i - 1];
    const double a = (t[i + 1] - t[i]) / h, b = (t[i] - t[i - 1]) / h;
    pseudo.push_back(std::abs(a * y[i - 1] + b * y[i + 1] - y[i]) / std::sqrt(a * a + b * b + 1.0));
  }
  const auto mid = pseudo.begin() + static_cast<std::ptrdiff_t>(pseudo.size() / 2);
  std::nth_element(pseudo.begin(), mid, pseudo.end());
  return {kMadToSigma * *mid, pseudo.size()};
}

NoiseEstimate poolNoise(const std::vector<NoiseEstimate>& estimates) {
  double sum = 0;
  std::size_t n = 0;
  for (const auto& e : estimates) {
    sum += e.sigma * e.sigma * static_cast<double>(e.samples);
    n += e.samples;
  }
  return {n > 0 ? std::sqrt(sum / static_cast<double>(n)) : 0.0, n};
}

}  // namespace swingsim
