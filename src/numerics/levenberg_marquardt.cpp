#include "numerics/levenberg_marquardt.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/input_error.h"

namespace swingsim {

LeastSquaresResult solveLevenbergMarquardt(const ResidualFunction& f, Eigen::VectorXd x, const Eigen::VectorXd& typical,
                                           const LeastSquaresSettings& settings) {
  LeastSquaresResult out;
  out.residual = f(x);
  out.cost = out.residual.squaredNorm();
  double lambda = 1e-3;
  const Eigen::Index n = x.size();
  for (int iter = 0; iter < settings.maxIterations; ++iter) {
    Eigen::MatrixXd J(out.residual.size(), n);
    for (Eigen::Index j = 0; j < n; ++j) {
      Eigen::VectorXd xh = x;
      const double h = settings.differenceStep * std::max(std::abs(x[j]), typical[j]);
      xh[j] += h;
      J.col(j) = (f(xh) - out.residual) / h;
    }
    out.jacobian = J;
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * out.residual;
    bool improved = false;
    double fall = 0;
    for (int tries = 0; tries < 12 && !improved; ++tries) {
      Eigen::MatrixXd A = JtJ;
      for (Eigen::Index k = 0; k < n; ++k) A(k, k) += lambda * std::max(JtJ(k, k), 1e-12);
      const Eigen::VectorXd step = A.ldlt().solve(-g);
      const Eigen::VectorXd trial = x + step;
      Eigen::VectorXd r;
      double cost = std::numeric_limits<double>::infinity();
      try {
        r = f(trial);
        cost = r.squaredNorm();
      } catch (const RunError&) {
      }
      if (std::isfinite(cost) && cost < out.cost) {
        fall = (out.cost - cost) / std::max(out.cost, 1e-300);
        x = trial;
        out.residual = r;
        out.cost = cost;
        lambda = std::max(lambda / 3, 1e-9);
        improved = true;
      } else {
        lambda *= 4;
      }
    }
    if (!improved || fall < settings.costTolerance) break;
  }
  out.x = x;
  return out;
}

}  // namespace swingsim
