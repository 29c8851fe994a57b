#include "identify/cylinder_fit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "core/input_error.h"

namespace swingsim {

namespace {

// Singular values below this fraction of the largest count as zero (rank detection):
// well above double round-off accumulated over a few thousand rows.
constexpr double kRankTolerance = 1e-12;

// Three significant digits, for messages.
std::string fmt3(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace

LinearFit fitLeastSquares(const Eigen::MatrixXd& X, const Eigen::VectorXd& y) {
  if (X.rows() != y.rows()) throw std::invalid_argument("fitLeastSquares: X and y differ in rows");
  const Eigen::Index n = X.rows(), p = X.cols();
  LinearFit fit;
  fit.samples = static_cast<std::size_t>(n);
  Eigen::VectorXd scale = X.colwise().norm().transpose();
  for (Eigen::Index j = 0; j < p; ++j) {
    if (!(scale(j) > 0)) scale(j) = 1.0;
  }
  const Eigen::MatrixXd Xs = X * scale.cwiseInverse().asDiagonal();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(Xs, Eigen::ComputeThinU | Eigen::ComputeThinV);
  svd.setThreshold(kRankTolerance);
  fit.rank = static_cast<int>(svd.rank());
  const Eigen::VectorXd sv = svd.singularValues();
  fit.conditionNumber = fit.rank < p ? std::numeric_limits<double>::infinity() : sv(0) / sv(p - 1);
  const Eigen::VectorXd bs = svd.solve(y);
  const Eigen::VectorXd b = bs.cwiseQuotient(scale);
  const Eigen::VectorXd residual = y - X * b;
  const double rss = residual.squaredNorm();
  fit.residualRms = n > 0 ? std::sqrt(rss / static_cast<double>(n)) : 0.0;
  fit.coefficients.assign(b.data(), b.data() + p);
  fit.standardErrors.assign(static_cast<std::size_t>(p), std::numeric_limits<double>::quiet_NaN());
  if (fit.rank == p && n > p) {
    const double s2 = rss / static_cast<double>(n - p);
    const Eigen::MatrixXd V = svd.matrixV();
    for (Eigen::Index j = 0; j < p; ++j) {
      double var = 0;
      for (Eigen::Index k = 0; k < p; ++k) var += V(j, k) * V(j, k) / (sv(k) * sv(k));
      fit.standardErrors[static_cast<std::size_t>(j)] = std::sqrt(s2 * var) / scale(j);
    }
  }
  return fit;
}

CylinderTrace predictBench(const MauchCylinder& cylinder, const BenchData& data) {
  return calcCylinderTrace(cylinder, data.time, data.position, data.velocity, 0.0);
}

namespace {

// Regression at fixed switch constants.
LinearFit regress(const MauchCylinderParams& params, const std::vector<BenchData>& train) {
  const MauchCylinder cylinder(params);
  std::size_t rows = 0;
  for (const auto& d : train) rows += d.time.size();
  const int p = cylinder.numCoefficients();
  Eigen::MatrixXd X(static_cast<Eigen::Index>(rows), p);
  Eigen::VectorXd y(static_cast<Eigen::Index>(rows));
  Eigen::Index r = 0;
  for (const auto& d : train) {
    const auto latch = calcLatchHistory(d.time, d.position, d.velocity, params.switches, 0.0);
    const std::vector<double> accel = params.effects.inertia ? estimatePistonVelocity(d.time, d.velocity)
                                                             : std::vector<double>(d.time.size(), 0.0);
    for (std::size_t i = 0; i < d.time.size(); ++i, ++r) {
      const auto row = cylinder.calcRegressorRow(d.position[i], d.velocity[i], accel[i], latch[i]);
      for (int j = 0; j < p; ++j) X(r, j) = row[static_cast<std::size_t>(j)];
      y(r) = d.force[i];
    }
  }
  return fitLeastSquares(X, y);
}


}  // namespace

CylinderFit fitCylinder(const MauchCylinderParams& model, const std::vector<BenchData>& train,
                        const CylinderFitOptions& options) {
  CylinderFit out;
  out.params = model;
  out.startSwitches = model.switches;
  std::size_t rows = 0;
  for (const auto& d : train) rows += d.time.size();
  const std::size_t p = static_cast<std::size_t>(MauchCylinder(model).numCoefficients());
  if (rows < p)
    throw InputError("training data: fewer samples (" + std::to_string(rows) + ") than coefficients (" +
                     std::to_string(p) + ") of a " + std::to_string(model.phases) + "-phase model");

  // A phase the training data (almost) never enters has coefficients fixed by round-off:
  // the column scaling in fitLeastSquares hides it from the rank test, and the "fit" then
  // returns numbers like 1e16 N. Refuse, and say which phase and why.
  {
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

  LinearFit best = regress(model, train);
  out.trainRmseAtStart = best.residualRms;
  if (options.fitSwitches) {
    const MauchSwitchParams s0 = model.switches;
    if (!(s0.hyperextensionPosition > 0))
      throw InputError("fit_switches: the model's hyperextension_position_m must be positive for a log grid (got " +
                       formatNumber(s0.hyperextensionPosition) + ")");
    const int g = std::max(2, options.gridPoints);
    std::vector<double> factors;
    for (int i = 0; i < g; ++i)
      factors.push_back(std::pow(options.gridFactor, -1.0 + 2.0 * i / (g - 1)));
    const int total = g * g * g;
    int done = 0;
    MauchSwitchParams bestSwitches = s0;
    for (double fv : factors) {
      for (double fp : factors) {
        for (double fh : factors) {
          MauchCylinderParams trial = model;
          trial.switches.velocityWidth = s0.velocityWidth * fv;
          trial.switches.positionWidth = s0.positionWidth * fp;
          trial.switches.hyperextensionPosition = s0.hyperextensionPosition * fh;
          const LinearFit fit = regress(trial, train);
          if (fit.rank == static_cast<int>(p) && fit.residualRms < best.residualRms) {
            best = fit;
            bestSwitches = trial.switches;
          }
          if (options.progress) options.progress(++done, total);
        }
      }
    }
    out.params.switches = bestSwitches;
    out.switchesFitted = true;
    auto atEdge = [&](double value, double start) {
      const double r = value / start;
      return std::fabs(std::log(r)) > 0.999 * std::log(options.gridFactor);
    };
    if (atEdge(bestSwitches.velocityWidth, s0.velocityWidth) || atEdge(bestSwitches.positionWidth, s0.positionWidth) ||
        atEdge(bestSwitches.hyperextensionPosition, s0.hyperextensionPosition))
      out.warnings.push_back("a fitted switch constant sits at the edge of the search grid; the optimum may lie beyond it");
  }
  out.regression = best;
  setMauchCoefficientVector(out.params, best.coefficients);
  if (best.rank < static_cast<int>(p))
    out.warnings.push_back("rank-deficient regression (rank " + std::to_string(best.rank) + " of " + std::to_string(p) +
                           "): some phase is (almost) never active in the training data; its coefficients are not identified");
  else if (best.conditionNumber > kIllConditionedLimit)
    out.warnings.push_back("ill-conditioned regression (condition number " + formatNumber(best.conditionNumber) +
                           " > " + formatNumber(kIllConditionedLimit) + "): coefficients are poorly determined");
  return out;
}

}  // namespace swingsim
