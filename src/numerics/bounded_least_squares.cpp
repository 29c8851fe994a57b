#include "numerics/bounded_least_squares.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/input_error.h"

namespace swingsim {

namespace {

// The scaled coordinate u of a parameter: log(value) or value / typical.
double toScaled(const BoundedParameter& p, double value) { return p.logScale ? std::log(value) : value / p.typical; }
double fromScaled(const BoundedParameter& p, double u) { return p.logScale ? std::exp(u) : u * p.typical; }
// d value / d u at u.
double scaledDerivative(const BoundedParameter& p, double u) { return p.logScale ? std::exp(u) : p.typical; }

Eigen::VectorXd toValues(const std::vector<BoundedParameter>& ps, const double* u) {
  Eigen::VectorXd x(static_cast<Eigen::Index>(ps.size()));
  for (std::size_t k = 0; k < ps.size(); ++k) x[static_cast<Eigen::Index>(k)] = fromScaled(ps[k], u[k]);
  return x;
}

// Residuals for Ceres at scaled coordinates. An exception (the model cannot run there)
// rejects the step: Ceres treats `false` as an infeasible point.
class ScaledResiduals {
 public:
  ScaledResiduals(const ResidualFunction& f, const std::vector<BoundedParameter>& ps, Eigen::Index m)
      : f_(f), ps_(ps), m_(m) {}
  bool operator()(double const* const* u, double* r) const {
    try {
      const Eigen::VectorXd res = f_(toValues(ps_, u[0]));
      if (res.size() != m_) return false;
      for (Eigen::Index i = 0; i < m_; ++i) {
        if (!std::isfinite(res[i])) return false;
        r[i] = res[i];
      }
      return true;
    } catch (const std::exception&) {
      return false;
    }
  }

 private:
  const ResidualFunction& f_;
  const std::vector<BoundedParameter>& ps_;
  Eigen::Index m_;
};

// The residuals as a Ceres cost with a numeric Jacobian by `Method` (forward or central).
template <ceres::NumericDiffMethodType Method>
ceres::CostFunction* makeNumericCost(const ResidualFunction& f, const std::vector<BoundedParameter>& ps, Eigen::Index m,
                                     const ceres::NumericDiffOptions& diff) {
  auto* c = new ceres::DynamicNumericDiffCostFunction<ScaledResiduals, Method>(new ScaledResiduals(f, ps, m),
                                                                               ceres::TAKE_OWNERSHIP, diff);
  c->AddParameterBlock(static_cast<int>(ps.size()));
  c->SetNumResiduals(static_cast<int>(m));
  return c;
}

// The residuals for Ceres at scaled coordinates with the function's own Jacobian, converted
// to the scaled coordinates (d value / d u per column).
class AnalyticScaledCost final : public ceres::CostFunction {
 public:
  AnalyticScaledCost(const ResidualJacobianFunction& f, const std::vector<BoundedParameter>& ps, Eigen::Index m)
      : f_(f), ps_(ps), m_(m) {
    set_num_residuals(static_cast<int>(m));
    mutable_parameter_block_sizes()->push_back(static_cast<int>(ps.size()));
  }
  bool Evaluate(double const* const* u, double* r, double** jacobians) const override {
    try {
      const bool wantJacobian = jacobians != nullptr && jacobians[0] != nullptr;
      Eigen::MatrixXd J;
      const Eigen::VectorXd res = f_(toValues(ps_, u[0]), wantJacobian ? &J : nullptr);
      const Eigen::Index n = static_cast<Eigen::Index>(ps_.size());
      if (res.size() != m_ || (wantJacobian && (J.rows() != m_ || J.cols() != n))) return false;
      for (Eigen::Index i = 0; i < m_; ++i) {
        if (!std::isfinite(res[i])) return false;
        r[i] = res[i];
      }
      if (wantJacobian) {
        for (Eigen::Index k = 0; k < n; ++k) {
          const double d = scaledDerivative(ps_[static_cast<std::size_t>(k)], u[0][k]);
          for (Eigen::Index i = 0; i < m_; ++i) {
            const double v = J(i, k) * d;
            if (!std::isfinite(v)) return false;
            jacobians[0][i * n + k] = v;  // row-major
          }
        }
      }
      return true;
    } catch (const std::exception&) {
      return false;
    }
  }

 private:
  const ResidualJacobianFunction& f_;
  const std::vector<BoundedParameter>& ps_;
  Eigen::Index m_;
};

// The solve shared by both fronts: `makeCost(m)` gives the Ceres cost for m residuals, `f0`
// the residual at a point (for the start, and the reason a point cannot run).
template <class MakeCost, class Residual>
BoundedFitResult solveScaled(const MakeCost& makeCost, const Residual& f0,
                             const std::vector<BoundedParameter>& parameters, const BoundedFitSettings& settings);

}  // namespace

Eigen::MatrixXd BoundedFitResult::correlation() const {
  Eigen::MatrixXd c = covariance;
  for (Eigen::Index i = 0; i < c.rows(); ++i)
    for (Eigen::Index j = 0; j < c.cols(); ++j) c(i, j) = covariance(i, j) / (standardErrors[i] * standardErrors[j]);
  return c;
}

BoundedFitResult solveBoundedLeastSquares(const ResidualFunction& f, const std::vector<BoundedParameter>& parameters,
                                          const BoundedFitSettings& settings) {
  ceres::NumericDiffOptions diff;
  diff.relative_step_size = settings.differenceStep;
  const auto makeCost = [&](Eigen::Index m) {
    return settings.centralDifferences ? makeNumericCost<ceres::CENTRAL>(f, parameters, m, diff)
                                       : makeNumericCost<ceres::FORWARD>(f, parameters, m, diff);
  };
  return solveScaled(makeCost, f, parameters, settings);
}

BoundedFitResult solveBoundedLeastSquares(const ResidualJacobianFunction& f,
                                          const std::vector<BoundedParameter>& parameters,
                                          const BoundedFitSettings& settings) {
  const auto makeCost = [&](Eigen::Index m) -> ceres::CostFunction* {
    return new AnalyticScaledCost(f, parameters, m);
  };
  const auto f0 = [&](const Eigen::VectorXd& x) { return f(x, nullptr); };
  return solveScaled(makeCost, f0, parameters, settings);
}

namespace {

/// The fit's start and bounds in scaled coordinates (infinite where a bound is open).
struct ScaledStart {
  std::vector<double> u, lo, hi;
};

/// Checks each parameter's range and converts its start and bounds to scaled coordinates.
ScaledStart calcScaledStart(const std::vector<BoundedParameter>& parameters) {
  const std::size_t n = parameters.size();
  ScaledStart s{std::vector<double>(n), std::vector<double>(n), std::vector<double>(n)};
  for (std::size_t k = 0; k < n; ++k) {
    const BoundedParameter& p = parameters[k];
    if (p.logScale && !(p.lower > 0))
      throw std::invalid_argument("solveBoundedLeastSquares: log-scaled parameter " + p.name +
                                  " needs a positive lower bound");
    if (!(p.lower <= p.upper)) throw std::invalid_argument("solveBoundedLeastSquares: empty range for " + p.name);
    s.lo[k] = toScaled(p, p.lower);
    s.hi[k] = p.upper >= 1e300 ? std::numeric_limits<double>::infinity() : toScaled(p, p.upper);
    if (p.lower <= -1e300) s.lo[k] = -std::numeric_limits<double>::infinity();
    s.u[k] = toScaled(p, std::clamp(p.start, p.lower, p.upper));
  }
  return s;
}

/// Ceres' options from ours: dense QR, silent, one thread.
// Why Ceres stopped, in the words of the problem rather than the solver's: a cost it could not
// evaluate is a model run that failed (a swing without an end), not a solver fault.
std::string describeStop(const ceres::Solver::Summary& summary) {
  if (summary.message.find("evaluation failed") != std::string::npos)
    return "a model run near the last step failed (no result to compare), so the fit stopped at the best point so far";
  if (summary.termination_type == ceres::NO_CONVERGENCE)
    return "the iteration limit was reached (" + std::to_string(summary.iterations.size() - 1) + " iterations)";
  return summary.message;
}

ceres::Solver::Options makeSolverOptions(const BoundedFitSettings& settings) {
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = settings.maxIterations;
  options.max_solver_time_in_seconds = settings.maxSeconds;
  options.function_tolerance = settings.functionTolerance;
  options.parameter_tolerance = settings.parameterTolerance;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  options.num_threads = 1;
  options.use_nonmonotonic_steps = settings.nonmonotonicSteps;
  if (!settings.boundsLineSearch) options.max_num_line_search_step_size_iterations = 0;
  return options;
}

/// Whether each scaled coordinate ended on (within 1e-6 relative of) a finite bound.
std::vector<bool> calcAtBound(const ScaledStart& s) {
  std::vector<bool> atBound(s.u.size(), false);
  for (std::size_t k = 0; k < s.u.size(); ++k) {
    const double tol = 1e-6 * std::max(1.0, std::abs(s.u[k]));
    atBound[k] =
        (std::isfinite(s.lo[k]) && s.u[k] - s.lo[k] < tol) || (std::isfinite(s.hi[k]) && s.hi[k] - s.u[k] < tol);
  }
  return atBound;
}

/// Ceres' sparse Jacobian as a dense rows x cols matrix.
Eigen::MatrixXd toDense(const ceres::CRSMatrix& crs, Eigen::Index rows, Eigen::Index cols) {
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(rows, cols);
  for (int r = 0; r < crs.num_rows; ++r)
    for (int k = crs.rows[static_cast<std::size_t>(r)]; k < crs.rows[static_cast<std::size_t>(r) + 1]; ++k)
      J(r, crs.cols[static_cast<std::size_t>(k)]) = crs.values[static_cast<std::size_t>(k)];
  return J;
}

/// Sets out.covariance to s^2 (J'J)^+ from the Jacobian J in scaled coordinates u, converted
/// to the parameters' own units, and out.standardErrors to the square roots of its diagonal.
/// The pseudo-inverse by SVD drops a direction the data do not fix.
void setCovariance(const Eigen::MatrixXd& J, const std::vector<BoundedParameter>& parameters,
                   const std::vector<double>& u, BoundedFitResult& out) {
  const Eigen::Index m = J.rows();
  const Eigen::Index ni = J.cols();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeThinV);
  const Eigen::VectorXd sv = svd.singularValues();
  const double cutoff = 1e-12 * (sv.size() > 0 ? sv(0) : 0.0);
  Eigen::MatrixXd cu = Eigen::MatrixXd::Zero(ni, ni);
  for (Eigen::Index k = 0; k < sv.size(); ++k)
    if (sv(k) > cutoff) cu += svd.matrixV().col(k) * svd.matrixV().col(k).transpose() / (sv(k) * sv(k));
  const double s2 = out.cost / static_cast<double>(m - ni);
  for (Eigen::Index i = 0; i < ni; ++i) {
    const double di = scaledDerivative(parameters[static_cast<std::size_t>(i)], u[static_cast<std::size_t>(i)]);
    for (Eigen::Index j = 0; j < ni; ++j) {
      const double dj = scaledDerivative(parameters[static_cast<std::size_t>(j)], u[static_cast<std::size_t>(j)]);
      out.covariance(i, j) = s2 * di * dj * cu(i, j);
    }
  }
  for (Eigen::Index i = 0; i < ni; ++i) out.standardErrors[i] = std::sqrt(std::max(0.0, out.covariance(i, i)));
}

template <class MakeCost, class Residual>
BoundedFitResult solveScaled(const MakeCost& makeCost, const Residual& f,
                             const std::vector<BoundedParameter>& parameters, const BoundedFitSettings& settings) {
  const std::size_t n = parameters.size();
  ScaledStart scaled = calcScaledStart(parameters);
  std::vector<double>& u = scaled.u;
  BoundedFitResult out;
  const Eigen::VectorXd r0 = f(toValues(parameters, u.data()));  // throws if the start cannot run
  const Eigen::Index m = r0.size();

  ceres::Problem::Options problemOptions;
  ceres::Problem problem(problemOptions);
  problem.AddResidualBlock(makeCost(m), nullptr, u.data());
  for (std::size_t k = 0; k < n; ++k) {
    if (std::isfinite(scaled.lo[k])) problem.SetParameterLowerBound(u.data(), static_cast<int>(k), scaled.lo[k]);
    if (std::isfinite(scaled.hi[k])) problem.SetParameterUpperBound(u.data(), static_cast<int>(k), scaled.hi[k]);
  }
  ceres::Solver::Summary summary;
  ceres::Solve(makeSolverOptions(settings), &problem, &summary);

  out.x = toValues(parameters, u.data());
  out.iterations = static_cast<int>(summary.iterations.size()) - 1;
  out.converged = summary.termination_type == ceres::CONVERGENCE;
  if (!out.converged) out.stopReason = describeStop(summary);
  out.atBound = calcAtBound(scaled);

  const Eigen::Index ni = static_cast<Eigen::Index>(n);
  out.covariance = Eigen::MatrixXd::Constant(ni, ni, std::numeric_limits<double>::quiet_NaN());
  out.standardErrors = Eigen::VectorXd::Constant(ni, std::numeric_limits<double>::quiet_NaN());
  // The residual at the solution and, for the covariance, the Jacobian there: one Ceres
  // evaluation gives both (the same numeric differences as the fit). s^2 (J'J)^+ is then
  // formed by SVD here, not by ceres::Covariance, whose DENSE_SVD Debian's libceres and our
  // Eigen instantiate differently (AddressSanitizer reports a mismatched free).
  std::vector<double> residual;
  ceres::CRSMatrix crs;
  ceres::Problem::EvaluateOptions eo;
  eo.num_threads = 1;
  const bool withJacobian = settings.computeCovariance && m > ni;
  if (problem.Evaluate(eo, nullptr, &residual, nullptr, withJacobian ? &crs : nullptr)) {
    out.residual = Eigen::Map<const Eigen::VectorXd>(residual.data(), static_cast<Eigen::Index>(residual.size()));
  } else {
    out.residual = f(out.x);  // throws the model's own reason it cannot run there
  }
  out.cost = out.residual.squaredNorm();
  if (withJacobian && crs.num_rows == m) setCovariance(toDense(crs, m, ni), parameters, u, out);
  return out;
}

}  // namespace

std::vector<std::pair<int, int>> findCollinearPairs(const Eigen::MatrixXd& correlation, double limit) {
  std::vector<std::pair<int, int>> pairs;
  for (Eigen::Index i = 0; i < correlation.rows(); ++i)
    for (Eigen::Index j = i + 1; j < correlation.cols(); ++j)
      if (std::abs(correlation(i, j)) > limit) pairs.push_back({static_cast<int>(i), static_cast<int>(j)});
  std::sort(pairs.begin(), pairs.end(), [&](const auto& a, const auto& b) {
    return std::abs(correlation(a.first, a.second)) > std::abs(correlation(b.first, b.second));
  });
  return pairs;
}

}  // namespace swingsim
