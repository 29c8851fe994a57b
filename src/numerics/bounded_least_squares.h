#pragma once
// Bounded nonlinear least squares, a thin front end to Ceres Solver (trust region,
// Levenberg-Marquardt strategy, numeric Jacobian or the caller's exact one): for residual
// functions that run a simulation or a regression (the swing plant's refits, the Mauch
// switch constants), with
// bounds from physics, an iteration and wall-clock budget, and the parameter covariance
// from the Jacobian at the solution (Ceres' Jacobian, pseudo-inverse by SVD).
#include <Eigen/Dense>

#include <functional>
#include <string>
#include <vector>

namespace swingsim {

/// Residual vector at a parameter vector. May throw RunError (or any std::exception) where
/// the model cannot run; Ceres then rejects that trial step.
using ResidualFunction = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

/// One free parameter: start value, physical bounds (may be +-infinity) and how it is
/// searched. A log-scaled parameter (positive bounds) is optimised as log(value): right for
/// constants known only to a decade, such as switch widths and rates.
struct BoundedParameter {
  std::string name;
  double start = 0;
  double lower = -1e300;
  double upper = 1e300;
  bool logScale = false;
  /// Typical size of a linear parameter: the difference step is relative to it.
  double typical = 1.0;
};

struct BoundedFitSettings {
  /// Difference step in the scaled coordinates (value / typical, or log value). A residual
  /// smooth to ~1e-9 (an integration at 1e-9) gives derivative errors of ~1e-4.
  double differenceStep = 1e-5;
  bool centralDifferences = false;  ///< forward differences cost half as many evaluations
  int maxIterations = 60;
  double maxSeconds = 60.0;         ///< wall-clock budget of one solve
  double functionTolerance = 1e-9;  ///< relative cost fall that ends the iterations
  double parameterTolerance = 1e-9;
  bool computeCovariance = true;
  /// Ceres' non-monotonic steps (Conn, Gould & Toint, Trust-Region Methods, Sec. 10.1): a
  /// step may raise the cost a little if the iterations as a whole fall, which crosses
  /// curved, narrow valleys in fewer iterations.
  bool nonmonotonicSteps = false;
  /// Ceres' projected line search along each trust-region step of a bounded problem (every
  /// parameter here has bounds). Off, the trust region alone sizes the steps: a residual with a
  /// steep one-sided penalty otherwise gets Armijo steps of ~1e-4 of the trust-region step,
  /// each costing a residual and Jacobian evaluation.
  bool boundsLineSearch = true;
};

struct BoundedFitResult {
  Eigen::VectorXd x;         ///< the solution, in the parameters' own units
  Eigen::VectorXd residual;  ///< at x
  double cost = 0;           ///< squared norm of the residual (not Ceres' half of it)
  int iterations = 0;
  bool converged = false;     ///< Ceres reported convergence (not a budget or failure)
  std::string stopReason;     ///< Ceres' message when it did not converge
  std::vector<bool> atBound;  ///< a parameter within 1e-6 (scaled) of a bound
  /// s^2 (J'J)^+ in the parameters' units, s^2 = cost / (residuals - parameters); NaN if
  /// not computed.
  Eigen::MatrixXd covariance;
  Eigen::VectorXd standardErrors;  ///< sqrt(diag(covariance))
  /// The covariance as correlations (1 on the diagonal).
  Eigen::MatrixXd correlation() const;
};

/// Minimises |f(x)|^2 over the box given by `parameters` from their start values. Starts
/// outside the bounds are moved onto them. Throws RunError if f cannot run at the start.
BoundedFitResult solveBoundedLeastSquares(const ResidualFunction& f, const std::vector<BoundedParameter>& parameters,
                                          const BoundedFitSettings& settings = {});

/// Residual vector at a parameter vector and, when `jacobian` is not null, its Jacobian
/// d residual / d x (residuals x parameters, in the parameters' own units) written there.
/// May throw as ResidualFunction.
using ResidualJacobianFunction = std::function<Eigen::VectorXd(const Eigen::VectorXd&, Eigen::MatrixXd* jacobian)>;

/// The same with the residual function's own (analytic) Jacobian instead of numeric
/// differences: one evaluation per Jacobian instead of one per parameter plus one
/// (settings.differenceStep and centralDifferences are not used).
BoundedFitResult solveBoundedLeastSquares(const ResidualJacobianFunction& f,
                                          const std::vector<BoundedParameter>& parameters,
                                          const BoundedFitSettings& settings = {});

/// Pairs (i, j), i < j, whose correlation magnitude exceeds `limit`, strongest first.
std::vector<std::pair<int, int>> findCollinearPairs(const Eigen::MatrixXd& correlation, double limit = 0.95);

}  // namespace swingsim
