#include "numerics/sample_derivative.h"

namespace swingsim {

std::vector<double> estimatePistonVelocity(const std::vector<double>& t, const std::vector<double>& x) {
  const std::size_t n = t.size();
  std::vector<double> v(n, 0.0);
  if (n < 2) return v;
  v[0] = (x[1] - x[0]) / (t[1] - t[0]);
  v[n - 1] = (x[n - 1] - x[n - 2]) / (t[n - 1] - t[n - 2]);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    // Second-order central difference on an uneven grid.
    const double h0 = t[i] - t[i - 1], h1 = t[i + 1] - t[i];
    v[i] = (h0 * h0 * (x[i + 1] - x[i]) + h1 * h1 * (x[i] - x[i - 1])) / (h0 * h1 * (h0 + h1));
  }
  return v;
}

}  // namespace swingsim
