#include "numerics/monotone_cubic.h"

#include <algorithm>

namespace swingsim {

double interpolateMonotoneCubic(const std::vector<double>& x, const std::vector<double>& y, double t,
                                MonotoneCubicEnds ends) {
  const std::size_t n = x.size();
  if (t <= x.front()) return y.front();
  if (t >= x.back()) return y.back();
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), t) - x.begin()) - 1;
  auto secant = [&](std::size_t k) { return (y[k + 1] - y[k]) / (x[k + 1] - x[k]); };
  auto tangent = [&](std::size_t k) {
    if (k == 0) return ends == MonotoneCubicEnds::kFlat ? 0.0 : secant(0);
    if (k == n - 1) return ends == MonotoneCubicEnds::kFlat ? 0.0 : secant(n - 2);
    // Weighted harmonic mean of the neighbouring secants (Fritsch & Butland 1984's weights,
    // the slopes of PCHIP): w1 = 2 h_k + h_(k-1), w2 = h_k + 2 h_(k-1).
    const double a = secant(k - 1), b = secant(k);
    if (a * b <= 0) return 0.0;
    const double hPrev = x[k] - x[k - 1], hNext = x[k + 1] - x[k];
    const double w1 = 2 * hNext + hPrev, w2 = hNext + 2 * hPrev;
    return (w1 + w2) / (w1 / a + w2 / b);
  };
  const double h = x[i + 1] - x[i];
  const double s = (t - x[i]) / h;
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
  const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
  return h00 * y[i] + h10 * h * tangent(i) + h01 * y[i + 1] + h11 * h * tangent(i + 1);
}

}  // namespace swingsim
