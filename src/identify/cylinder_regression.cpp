#include "identify/cylinder_regression.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace swingsim {

namespace {

// Singular values below this fraction of the largest count as zero (rank detection):
// well above double round-off accumulated over a few thousand rows.
constexpr double kRankTolerance = 1e-12;

// One linear coefficient: its name with unit, and whether physics keeps it >= 0. A hydraulic
// cylinder dissipates, so every damping (c, orifice a) is >= 0; seal friction opposes motion
// (Fc >= 0); a moving mass is >= 0. Offsets, stiffnesses and the stroke-dependent damping
// change are free.
struct CoefficientSpec {
  std::string name;
  bool nonNegative;
};

// The coefficients of a model in regressor order (MauchCylinder::calcRegressorRow).
std::vector<CoefficientSpec> mauchCoefficients(const MauchCylinderParams& params) {
  std::vector<CoefficientSpec> c;
  auto phase = [&](const std::string& prefix) {
    c.push_back({prefix + " f_N", false});
    c.push_back({prefix + " k_N_per_m", false});
    c.push_back({prefix + " c_Ns_per_m", true});
  };
  for (int i = 1; i <= params.phases; ++i) phase("phase " + std::to_string(i));
  const MauchAddedEffects& e = params.effects;
  if (e.hyperextensionPhase) phase("hyperextension_phase");
  if (e.coulombFriction) c.push_back({"coulomb_friction force_N", true});
  if (e.orificeQuadratic) c.push_back({"orifice_quadratic coefficient_Ns2_per_m2", true});
  if (e.inertia) c.push_back({"inertia mass_kg", true});
  if (e.positionDependentDamping) c.push_back({"position_dependent_damping coefficient_Ns_per_m2", false});
  return c;
}

}  // namespace

Eigen::VectorXd calcColumnScale(const Eigen::MatrixXd& X) {
  Eigen::VectorXd scale = X.colwise().norm().transpose();
  for (Eigen::Index j = 0; j < scale.size(); ++j)
    if (!(scale(j) > 0)) scale(j) = 1.0;
  return scale;
}

LinearFit fitLeastSquares(const Eigen::MatrixXd& X, const Eigen::VectorXd& y) {
  if (X.rows() != y.rows()) throw std::invalid_argument("fitLeastSquares: X and y differ in rows");
  const Eigen::Index n = X.rows(), p = X.cols();
  LinearFit fit;
  fit.samples = static_cast<std::size_t>(n);
  const Eigen::VectorXd scale = calcColumnScale(X);
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
    // (Xs'Xs)^-1 = V S^-2 V'; the column scaling cancels in the correlation.
    const Eigen::MatrixXd inverse = V * sv.cwiseAbs2().cwiseInverse().asDiagonal() * V.transpose();
    for (Eigen::Index j = 0; j < p; ++j)
      fit.standardErrors[static_cast<std::size_t>(j)] = std::sqrt(s2 * inverse(j, j)) / scale(j);
    const Eigen::VectorXd d = inverse.diagonal().cwiseSqrt().cwiseInverse();
    fit.correlation = d.asDiagonal() * inverse * d.asDiagonal();
  }
  return fit;
}

std::vector<std::string> mauchCoefficientNames(const MauchCylinderParams& params) {
  std::vector<std::string> n;
  for (const auto& c : mauchCoefficients(params)) n.push_back(c.name);
  return n;
}

CylinderTrace predictBench(const MauchCylinder& cylinder, const BenchData& data) {
  return calcCylinderTrace(cylinder, data.time, data.position, data.velocity, 0.0);
}

// The regressors X (rows x coefficients) of y ~ X b at the model's switch constants, written
// into X (resized only if its shape changes: the fit builds them thousands of times).
void buildRegressors(const MauchCylinderParams& params, const TrainingSet& set, Eigen::MatrixXd& X) {
  const MauchCylinder cylinder(params);
  const int p = cylinder.numCoefficients();
  if (X.rows() != set.rows || X.cols() != p) X.resize(set.rows, p);
  Eigen::Index r = 0;
  double row[3 * MauchCylinder::kMaxGates + 4];
  for (std::size_t f = 0; f < set.files.size(); ++f) {
    const BenchData& d = set.files[f];
    const auto latch = calcLatchHistory(d.time, d.position, d.velocity, params.switches, 0.0);
    const std::vector<double>& accel = set.accel[f];
    for (std::size_t i = 0; i < d.time.size(); ++i, ++r) {
      cylinder.calcRegressorRow(d.position[i], d.velocity[i], accel[i], latch[i], row);
      for (int j = 0; j < p; ++j) X(r, j) = row[j];
    }
  }
}

// The regression problem y ~ X b at fixed switch constants.
void buildRegression(const MauchCylinderParams& params, const std::vector<BenchData>& train, Eigen::MatrixXd& X,
                     Eigen::VectorXd& y) {
  const TrainingSet set(params, train);
  buildRegressors(params, set, X);
  y = set.y;
}

// Regression at fixed switch constants.
LinearFit regress(const MauchCylinderParams& params, const std::vector<BenchData>& train) {
  Eigen::MatrixXd X;
  Eigen::VectorXd y;
  buildRegression(params, train, X, y);
  return fitLeastSquares(X, y);
}

Eigen::VectorXd predictionResidual(const MauchCylinderParams& params, const TrainingSet& set, Eigen::MatrixXd& X) {
  buildRegressors(params, set, X);
  const std::vector<double> b = MauchCylinder(params).getCoefficientVector();
  return set.y - X * Eigen::Map<const Eigen::VectorXd>(b.data(), static_cast<Eigen::Index>(b.size()));
}

std::vector<std::pair<double, double>> coefficientBounds(const MauchCylinderParams& params) {
  std::vector<std::pair<double, double>> b;
  for (const auto& c : mauchCoefficients(params)) b.push_back({c.nonNegative ? 0.0 : -1e300, 1e300});
  return b;
}

LinearFit regressWithinBounds(const MauchCylinderParams& params, const std::vector<BenchData>& train,
                              const std::vector<std::pair<double, double>>& bounds, std::vector<bool>& fixed) {
  Eigen::MatrixXd X;
  Eigen::VectorXd y;
  buildRegression(params, train, X, y);
  const Eigen::Index p = X.cols();
  fixed.assign(static_cast<std::size_t>(p), false);
  std::vector<double> value(static_cast<std::size_t>(p), 0.0);
  LinearFit fit;
  for (Eigen::Index pass = 0; pass <= p; ++pass) {
    std::vector<Eigen::Index> freeCols;
    Eigen::VectorXd target = y;
    for (Eigen::Index j = 0; j < p; ++j) {
      if (fixed[static_cast<std::size_t>(j)])
        target -= X.col(j) * value[static_cast<std::size_t>(j)];
      else
        freeCols.push_back(j);
    }
    Eigen::MatrixXd Xf(X.rows(), static_cast<Eigen::Index>(freeCols.size()));
    for (std::size_t k = 0; k < freeCols.size(); ++k) Xf.col(static_cast<Eigen::Index>(k)) = X.col(freeCols[k]);
    fit = fitLeastSquares(Xf, target);
    bool violated = false;
    for (std::size_t k = 0; k < freeCols.size(); ++k) {
      const auto j = static_cast<std::size_t>(freeCols[k]);
      const double v = fit.coefficients[k];
      if (v < bounds[j].first || v > bounds[j].second) {
        fixed[j] = true;
        value[j] = v < bounds[j].first ? bounds[j].first : bounds[j].second;
        violated = true;
      } else {
        value[j] = v;
      }
    }
    if (!violated) {
      LinearFit out = fit;
      out.coefficients = value;
      out.standardErrors.assign(static_cast<std::size_t>(p), std::numeric_limits<double>::quiet_NaN());
      for (std::size_t k = 0; k < freeCols.size(); ++k)
        out.standardErrors[static_cast<std::size_t>(freeCols[k])] = fit.standardErrors[k];
      out.rank += static_cast<int>(p - static_cast<Eigen::Index>(freeCols.size()));
      if (fit.correlation.size() > 0) {
        out.correlation = Eigen::MatrixXd::Zero(p, p);
        for (std::size_t a = 0; a < freeCols.size(); ++a)
          for (std::size_t b = 0; b < freeCols.size(); ++b)
            out.correlation(freeCols[a], freeCols[b]) =
                fit.correlation(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
      }
      return out;
    }
  }
  return fit;  // unreachable: each pass fixes at least one more coefficient
}

}  // namespace swingsim
