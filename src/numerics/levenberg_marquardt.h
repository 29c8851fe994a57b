#pragma once
// Unbounded nonlinear least squares by Levenberg-Marquardt with a forward-difference
// Jacobian, for residual functions that run a simulation (the swing plant's refits).
#include <Eigen/Dense>
#include <functional>

namespace swingsim {

/// Residual vector at a parameter vector. May throw RunError where the model cannot run;
/// such a trial step is rejected.
using ResidualFunction = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

struct LeastSquaresSettings {
  /// Forward-difference step relative to a parameter's typical size (a residual smooth to
  /// ~1e-9, as the reference integrator at 1e-9, gives derivative errors of ~1e-4).
  double differenceStep = 1e-5;
  int maxIterations = 40;
  double costTolerance = 1e-9;  ///< relative cost fall that ends the iterations
};

struct LeastSquaresResult {
  Eigen::VectorXd x;
  Eigen::VectorXd residual;  ///< at x
  Eigen::MatrixXd jacobian;  ///< at the last accepted iterate before x (forward differences)
  double cost = 0;           ///< squared norm of the residual
};

/// Minimises |f(x)|^2 from `x0`; `typical` sets each parameter's difference step scale.
LeastSquaresResult solveLevenbergMarquardt(const ResidualFunction& f, Eigen::VectorXd x0, const Eigen::VectorXd& typical,
                                           const LeastSquaresSettings& settings = {});

}  // namespace swingsim
