// The cylinder fit: the regression at the model's switch constants, optionally the switch
// constants by a multi-start search (identify/switch_search.h), the coefficients kept within
// their physical bounds, the joint covariance of every fitted constant and its warnings.
// The regression is identify/cylinder_regression.h, the variable-projection objective
// identify/projected_residual.h.
#include "identify/cylinder_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "core/input_error.h"
#include "identify/cylinder_regression.h"
#include "identify/projected_residual.h"
#include "identify/switch_search.h"
#include "numerics/bounded_least_squares.h"

namespace swingsim {

namespace {

// Three significant digits, for messages.
std::string fmt3(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// A phase the training data (almost) never enters has coefficients fixed by round-off:
// the column scaling in fitLeastSquares hides it from the rank test, and the "fit" then
// returns numbers like 1e16 N. Refuse, and say which phase and why.
void checkPhasesEntered(const MauchCylinderParams& model, const std::vector<BenchData>& train, std::size_t rows) {
  constexpr double kMinPhaseSamples = 3.0;  // a phase's gate summed over samples: at least its 3 coefficients
  std::vector<double> active(static_cast<std::size_t>(MauchCylinder(model).numPhaseGates()), 0.0);
  double xMin = 1e300, xMax = -1e300;
  std::string files;
  for (const auto& d : train) {
    const CylinderTrace tr = calcCylinderTrace(MauchCylinder(model), d.time, d.position, d.velocity, 0.0);
    for (const auto& g : tr.gates)
      for (std::size_t ph = 0; ph < active.size() && ph < g.size(); ++ph) active[ph] += g[ph];
    for (double x : d.position) {
      xMin = std::min(xMin, x);
      xMax = std::max(xMax, x);
    }
    files += (files.empty() ? "" : ", ") + d.path;
  }
  std::string idle;
  for (std::size_t ph = 0; ph < active.size(); ++ph) {
    if (active[ph] < kMinPhaseSamples)
      idle += (idle.empty() ? "phase " : ", phase ") + std::to_string(ph + 1) + " in " + fmt3(active[ph]);
  }
  if (!idle.empty())
    throw RunError("cannot fit the " + std::to_string(model.phases) + "-phase model: " + idle + " of " +
                   std::to_string(rows) + " training samples (" + files + "; piston position " + fmt3(xMin * 1e3) +
                   " to " + fmt3(xMax * 1e3) + " mm, hyperextension switch at " +
                   fmt3(model.switches.hyperextensionPosition * 1e3) +
                   " mm): those coefficients are not identified (singular regression). Likely cause: the training "
                   "record never enters those phases (no hyperextension in the gait cycle, so no S2 latch either, "
                   "or a position offset); train on a record that does, or use a model with fewer phases");
}

// Every fitted constant's value, standard error, whether it sits on a bound, and their
// correlation; the linear coefficients first (nLinear of them), then any switch constants.
struct ConstantEstimates {
  std::vector<BoundedParameter> all;
  std::size_t nLinear = 0;
  std::vector<double> values, errors;
  std::vector<bool> atBound;
  Eigen::MatrixXd correlation;
};

// The covariance of every constant (coefficients and switches) at the variable-projection
// optimum, from Ceres' Jacobian; updates `est`, `current` and `best` with the joint solution.
void calcJointCovariance(const std::vector<BenchData>& train, bool latch, std::size_t rows,
                         MauchCylinderParams& current, LinearFit& best, ConstantEstimates& est) {
  const std::size_t nLinear = est.nLinear;
  const TrainingSet set(current, train);
  Eigen::MatrixXd X;
  std::array<Eigen::MatrixXd, kSwitchConstants> dX;
  // r = y - X(switches) b: d r / d b = -X, d r / d switch k = -(d X / d switch k) b.
  ResidualJacobianFunction f = [&](const Eigen::VectorXd& x, Eigen::MatrixXd* jacobian) {
    MauchCylinderParams trial = current;
    setMauchCoefficientVector(trial, std::vector<double>(x.data(), x.data() + nLinear));
    trial.switches = switchesFrom(current.switches, x.data() + nLinear, latch);
    Eigen::VectorXd residual = predictionResidual(trial, set, X);
    if (jacobian) {
      const Eigen::Index nl = static_cast<Eigen::Index>(nLinear);
      jacobian->resize(X.rows(), x.size());
      jacobian->leftCols(nl) = -X;
      buildRegressorDerivatives(MauchCylinder(trial), set, dX);
      const Eigen::Map<const Eigen::VectorXd> b(x.data(), nl);
      for (Eigen::Index k = nl; k < x.size(); ++k) jacobian->col(k) = -(dX[static_cast<std::size_t>(k - nl)] * b);
    }
    return residual;
  };
  BoundedFitSettings settings;
  // Variable projection (with the active set) already found the joint optimum: only the
  // covariance of every constant at that point is needed.
  settings.maxIterations = 0;
  settings.maxSeconds = 30.0;
  const BoundedFitResult r = solveBoundedLeastSquares(f, est.all, settings);
  est.values.assign(r.x.data(), r.x.data() + r.x.size());
  est.errors.assign(r.standardErrors.data(), r.standardErrors.data() + r.standardErrors.size());
  for (std::size_t j = nLinear; j < r.atBound.size(); ++j) est.atBound.push_back(r.atBound[j]);
  for (std::size_t j = 0; j < nLinear; ++j)
    if (est.atBound[j]) est.errors[j] = std::numeric_limits<double>::quiet_NaN();
  est.correlation = r.correlation();
  const auto& values = est.values;
  setMauchCoefficientVector(current, std::vector<double>(values.begin(), values.begin() + static_cast<long>(nLinear)));
  current.switches = switchesFrom(current.switches, values.data() + nLinear, latch);
  best.coefficients.assign(values.begin(), values.begin() + static_cast<long>(nLinear));
  best.standardErrors.assign(est.errors.begin(), est.errors.begin() + static_cast<long>(nLinear));
  best.residualRms = std::sqrt(r.cost / static_cast<double>(rows));
}

// Coefficients that left their physical range are put on their bound (active set). With
// fitted switch constants, the covariance of every constant (coefficients and switches) at
// that point comes from Ceres' Jacobian; otherwise the regression's standard errors are
// exact.
ConstantEstimates estimateConstants(const std::vector<BenchData>& train, const CylinderFitOptions& options,
                                    bool switchesFitted, std::size_t rows, MauchCylinderParams& current,
                                    LinearFit& best) {
  const std::size_t p = static_cast<std::size_t>(MauchCylinder(current).numCoefficients());
  const std::vector<std::string> names = mauchCoefficientNames(current);
  const auto bounds = coefficientBounds(current);
  bool outside = false;
  for (std::size_t j = 0; j < bounds.size(); ++j)
    outside = outside || best.coefficients[j] < bounds[j].first || best.coefficients[j] > bounds[j].second;
  ConstantEstimates est;
  est.atBound.assign(names.size(), false);
  if (outside && best.rank == static_cast<int>(p)) {
    const double conditionNumber = best.conditionNumber;
    best = regressWithinBounds(current, train, bounds, est.atBound);
    best.conditionNumber = conditionNumber;  // of the whole regression, as reported before
    setMauchCoefficientVector(current, best.coefficients);
  }
  est.values = best.coefficients;
  est.errors = best.standardErrors;
  est.correlation = best.correlation;
  for (std::size_t j = 0; j < names.size(); ++j) {
    const double se = std::isfinite(best.standardErrors[j]) ? best.standardErrors[j] : 0.0;
    est.all.push_back({names[j], best.coefficients[j], bounds[j].first, bounds[j].second, false,
                       std::max({std::abs(best.coefficients[j]), se, 1e-6})});
  }
  est.nLinear = est.all.size();
  if (switchesFitted)
    for (const auto& b : switchParameters(current.switches, options.ranges, options.fitLatchRate)) est.all.push_back(b);
  if (switchesFitted && best.rank == static_cast<int>(p))
    calcJointCovariance(train, options.fitLatchRate, rows, current, best, est);
  return est;
}

// The fitted constants into `out`, with a warning for each that sits on its physical bound
// or that the training data do not determine.
void addFittedConstants(const ConstantEstimates& est, CylinderFit& out) {
  for (std::size_t j = 0; j < est.all.size(); ++j) {
    FittedConstant c;
    c.name = est.all[j].name;
    c.value = est.values[j];
    c.standardError = est.errors[j];
    c.lower = est.all[j].lower;
    c.upper = est.all[j].upper;
    c.atBound = j < est.atBound.size() && est.atBound[j];
    c.includesZero = std::isfinite(c.standardError) && j < est.nLinear && std::abs(c.value) < 1.96 * c.standardError;
    out.constants.push_back(c);
    if (c.atBound && j < est.nLinear)
      out.warnings.push_back(c.name + " = " + fmt3(c.value) + " sits on its physical bound: the data ask for a value " +
                             (c.value <= c.lower ? "below " + fmt3(c.lower) : "above " + fmt3(c.upper)) +
                             " (a non-physical sign); the model may be missing an effect");
    else if (j >= est.nLinear && (c.atBound || !(c.standardError < std::abs(c.value))))
      out.warnings.push_back(c.name + " = " + fmt3(c.value) + " is not determined by the training data (" +
                             (c.atBound ? "at the edge of its range " + fmt3(c.lower) + ".." + fmt3(c.upper)
                                        : "standard error " + fmt3(c.standardError) + " larger than the value") +
                             "): records that differ from the training one there (another speed, another "
                             "hyperextension hold) may fit worse; train on more than one speed to pin it down");
  }
  out.correlation = est.correlation;
  if (est.correlation.size() > 0 && out.switchesFitted) {
    for (const auto& [i, j] : findCollinearPairs(est.correlation, kCollinearLimit))
      out.collinear.push_back({est.all[static_cast<std::size_t>(i)].name, est.all[static_cast<std::size_t>(j)].name,
                               est.correlation(i, j)});
  }
}

}  // namespace

CylinderFit fitCylinder(const MauchCylinderParams& model, const std::vector<BenchData>& train,
                        const CylinderFitOptions& options) {
  CylinderFit out;
  out.params = model;
  std::size_t rows = 0;
  for (const auto& d : train) rows += d.time.size();
  const std::size_t p = static_cast<std::size_t>(MauchCylinder(model).numCoefficients());
  if (rows < p)
    throw InputError("training data: fewer samples (" + std::to_string(rows) + ") than coefficients (" +
                     std::to_string(p) + ") of a " + std::to_string(model.phases) + "-phase model");
  checkPhasesEntered(model, train, rows);

  LinearFit best = regress(model, train);
  out.trainRmseAtStart = best.residualRms;
  MauchCylinderParams current = model;
  if (options.fitSwitches) {
    current.switches = fitSwitchConstants(model, train, options, out);
    out.switchesFitted = true;
    best = regress(current, train);
  }
  setMauchCoefficientVector(current, best.coefficients);
  const ConstantEstimates est = estimateConstants(train, options, out.switchesFitted, rows, current, best);
  out.params = current;
  out.regression = best;
  addFittedConstants(est, out);
  if (best.rank < static_cast<int>(p))
    out.warnings.push_back(
        "rank-deficient regression (rank " + std::to_string(best.rank) + " of " + std::to_string(p) +
        "): some phase is (almost) never active in the training data; its coefficients are not identified");
  else if (best.conditionNumber > kIllConditionedLimit)
    out.warnings.push_back("ill-conditioned regression (condition number " + formatNumber(best.conditionNumber) +
                           " > " + formatNumber(kIllConditionedLimit) + "): coefficients are poorly determined");
  return out;
}

}  // namespace swingsim
