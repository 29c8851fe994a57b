#include "numerics/local_polynomial.h"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace swingsim {

LocalPolynomialFit fitLocalPolynomial(const std::vector<double>& time, const std::vector<double>& values,
                                      double halfWindow, int degree) {
  if (time.size() != values.size()) throw std::invalid_argument("fitLocalPolynomial: time and values differ in length");
  if (degree < 2) throw std::invalid_argument("fitLocalPolynomial: the degree must be 2 or more (an acceleration)");
  const std::size_t n = time.size();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  LocalPolynomialFit f;
  for (auto* v : {&f.value, &f.rate, &f.acceleration, &f.accelerationGain}) v->assign(n, nan);
  f.windowStart.assign(n, 0);
  f.accelerationWeights.assign(n, {});
  std::size_t lo = 0, hi = 0;  // the window [lo, hi)
  for (std::size_t i = 0; i < n; ++i) {
    if (time[i] - halfWindow < time.front() || time[i] + halfWindow > time.back()) continue;
    while (time[lo] < time[i] - halfWindow) ++lo;
    while (hi < n && time[hi] <= time[i] + halfWindow) ++hi;
    const Eigen::Index m = static_cast<Eigen::Index>(hi - lo);
    if (m < degree + 2) continue;  // too few samples to tell the fit from the noise: left NaN
    // Columns (t - t_i)^k / halfWindow^k: scaled so the normal equations stay well conditioned.
    Eigen::MatrixXd a(m, degree + 1);
    Eigen::VectorXd y(m);
    for (Eigen::Index r = 0; r < m; ++r) {
      const double u = (time[lo + static_cast<std::size_t>(r)] - time[i]) / halfWindow;
      double p = 1.0;
      for (int k = 0; k <= degree; ++k, p *= u) a(r, k) = p;
      y[r] = values[lo + static_cast<std::size_t>(r)];
    }
    // The estimates are rows of the pseudo-inverse applied to y; their norms are the noise gains.
    const Eigen::MatrixXd pinv = a.completeOrthogonalDecomposition().pseudoInverse();
    const Eigen::VectorXd c = pinv * y;
    f.value[i] = c[0];
    f.rate[i] = c[1] / halfWindow;
    f.acceleration[i] = 2.0 * c[2] / (halfWindow * halfWindow);
    f.accelerationGain[i] = 2.0 * pinv.row(2).norm() / (halfWindow * halfWindow);
    f.windowStart[i] = lo;
    f.accelerationWeights[i].resize(static_cast<std::size_t>(m));
    for (Eigen::Index r = 0; r < m; ++r)
      f.accelerationWeights[i][static_cast<std::size_t>(r)] = 2.0 * pinv(2, r) / (halfWindow * halfWindow);
  }
  return f;
}

}  // namespace swingsim
