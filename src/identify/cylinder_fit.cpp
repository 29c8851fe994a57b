// The cylinder fit: the regression, its derivatives with respect to the switch constants,
// the multi-start switch fit with its variable-projection polish, and the joint covariance.
// One unit over ~600 lines because every step shares the internal TrainingSet (regressors
// per file, each starting unlatched) and the projected residual; split, they would need a
// header of internals that nothing else uses.
#include "identify/cylinder_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <future>
#include <limits>
#include <stdexcept>

#include <ceres/jet.h>

#include "core/input_error.h"
#include "numerics/bounded_least_squares.h"

namespace swingsim {

namespace {

// A thread where one can start, else the work runs in the caller at get() (libstdc++ falls
// back to deferred when std::thread throws resource_unavailable_try_again).
constexpr std::launch kAsyncOrHere = std::launch::async | std::launch::deferred;

// Singular values below this fraction of the largest count as zero (rank detection):
// well above double round-off accumulated over a few thousand rows.
constexpr double kRankTolerance = 1e-12;

// Three significant digits, for messages.
std::string fmt3(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// Euclidean norm of each column of X (1 for an all-zero column): dividing by it makes the
// conditioning a measure of collinearity, not of the choice of units.
Eigen::VectorXd calcColumnScale(const Eigen::MatrixXd& X) {
  Eigen::VectorXd scale = X.colwise().norm().transpose();
  for (Eigen::Index j = 0; j < scale.size(); ++j)
    if (!(scale(j) > 0)) scale(j) = 1.0;
  return scale;
}

}  // namespace

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

namespace {

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

std::vector<std::string> mauchCoefficientNames(const MauchCylinderParams& params) {
  std::vector<std::string> n;
  for (const auto& c : mauchCoefficients(params)) n.push_back(c.name);
  return n;
}

CylinderTrace predictBench(const MauchCylinder& cylinder, const BenchData& data) {
  return calcCylinderTrace(cylinder, data.time, data.position, data.velocity, 0.0);
}

namespace {

// The training records laid end to end with what does not depend on the model's constants:
// the measured force and, for an added inertia, the piston acceleration estimate.
struct TrainingSet {
  TrainingSet(const MauchCylinderParams& model, const std::vector<BenchData>& files) : files(files) {
    for (const auto& d : files) rows += static_cast<Eigen::Index>(d.time.size());
    y.resize(rows);
    Eigen::Index r = 0;
    for (const auto& d : files) {
      accel.push_back(model.effects.inertia ? estimatePistonVelocity(d.time, d.velocity)
                                            : std::vector<double>(d.time.size(), 0.0));
      for (double f : d.force) y(r++) = f;
    }
  }
  const std::vector<BenchData>& files;
  Eigen::Index rows = 0;
  Eigen::VectorXd y;                       // N
  std::vector<std::vector<double>> accel;  // m/s^2, per file
};

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

// Number of switch constants the fit can free: velocity width, position width, xhy, latch rate.
constexpr int kSwitchConstants = 4;
using SwitchJet = ceres::Jet<double, kSwitchConstants>;

// d X / d (velocity width, position width, xhy, latch rate) at the model's switch constants:
// the latch history (calcLatchHistory, Eq. 6) differentiated by hand, the switches and gates
// (calcMauchSwitches, MauchCylinder::calcGates; Chien 2014 Eqs. 3-4, 12-16) by forward-mode
// differentiation (ceres::Jet). These equations are written here a second time; the fit's
// test checks the result against finite differences of the residual. Only the phase-gate
// columns depend on the switch constants; the added effects' columns get zero derivatives.
// With X, also the regressors themselves (the latch from the same floating-point operations
// as calcLatchHistory's), so they need no second latch history.
void buildRegressorDerivatives(const MauchCylinder& cylinder, const TrainingSet& set,
                               std::array<Eigen::MatrixXd, kSwitchConstants>& dX, Eigen::MatrixXd* X = nullptr) {
  const MauchCylinderParams& params = cylinder.params();
  const MauchSwitchParams& sw = params.switches;
  const int p = cylinder.numCoefficients(), numGates = cylinder.numPhaseGates();
  for (auto& d : dX) {
    if (d.rows() != set.rows || d.cols() != p) d.resize(set.rows, p);
    d.setZero();
  }
  if (X && (X->rows() != set.rows || X->cols() != p)) X->resize(set.rows, p);
  double row[3 * MauchCylinder::kMaxGates + 4];
  const SwitchJet velocityWidth(sw.velocityWidth, 0), positionWidth(sw.positionWidth, 1),
      hyperextension(sw.hyperextensionPosition, 2);
  constexpr int kSubsteps = 10;  // calcLatchHistory's default, as buildRegressors uses it
  const double vw = sw.velocityWidth, pw = sw.positionWidth, xhy = sw.hyperextensionPosition, k = sw.latchRate;
  Eigen::Index r = 0;
  for (std::size_t f = 0; f < set.files.size(); ++f) {
    const BenchData& d = set.files[f];
    // S2 and its derivatives (velocity width, position width, xhy, latch rate), by hand in
    // the latch history's inner loop (a Jet there cost three times as much): a depends on
    // the velocity width and the rate only, b on the position width and xhy only.
    double latch = 0.0, dLatch[kSwitchConstants] = {0, 0, 0, 0};
    for (std::size_t i = 0; i < d.time.size(); ++i, ++r) {
      if (i > 0) {
        // calcLatchHistory: Eq. 6 integrated exactly over sub-intervals, s = b + (s - b) E.
        const double h = (d.time[i] - d.time[i - 1]) / kSubsteps;
        for (int j = 0; j < kSubsteps; ++j) {
          const double w = (j + 0.5) / kSubsteps;
          const double xm = d.position[i - 1] + w * (d.position[i] - d.position[i - 1]);
          const double vm = d.velocity[i - 1] + w * (d.velocity[i] - d.velocity[i - 1]);
          const double ta = std::tanh(vm / vw), tb = std::tanh((xm - xhy) / pw);
          const double a = k * (0.5 - 0.5 * ta);
          const double b = 0.5 - 0.5 * tb;
          const double E = std::exp(-a * h);
          const double dbShape = 0.5 * (1.0 - tb * tb) / pw;  // d b / d xhy
          const double dEda = -h * E;
          const double gap = latch - b;
          dLatch[0] = E * dLatch[0] + gap * dEda * (0.5 * k * (1.0 - ta * ta) * vm / (vw * vw));
          dLatch[1] = dbShape * (xm - xhy) / pw * (1.0 - E) + E * dLatch[1];
          dLatch[2] = dbShape * (1.0 - E) + E * dLatch[2];
          dLatch[3] = E * dLatch[3] + gap * dEda * (0.5 - 0.5 * ta);
          latch = b + gap * E;
        }
      }
      SwitchJet s2(latch);
      for (int q = 0; q < kSwitchConstants; ++q) s2.v[q] = dLatch[q];
      // calcMauchSwitches and MauchCylinder::calcGates.
      const double x = d.position[i], xd = d.velocity[i];
      if (X) {
        cylinder.calcRegressorRow(x, xd, set.accel[f][i], latch, row);
        for (int j = 0; j < p; ++j) (*X)(r, j) = row[j];
      }
      const SwitchJet s1 = 0.5 + 0.5 * tanh(xd / velocityWidth);
      const SwitchJet s8 = 0.5 + 0.5 * tanh((x - hyperextension) / positionWidth);
      SwitchJet gates[MauchCylinder::kMaxGates];
      if (params.phases == 2) {
        gates[0] = s1 * (1.0 - s2);
        gates[1] = 1.0 - s1 * (1.0 - s2);
      } else {
        gates[0] = s1 * (1.0 - s2) * s8;
        gates[1] = s1 * s2 * s8;
        gates[2] = (1.0 - s1) * s8;
        gates[3] = 1.0 - s8;
      }
      if (params.effects.hyperextensionPhase) {
        for (int g = 0; g < params.phases; ++g) gates[g] *= s8;
        gates[params.phases] = 1.0 - s8;
      }
      for (int g = 0; g < numGates; ++g)
        for (int c = 0; c < kSwitchConstants; ++c) {
          const double dg = gates[g].v[c];
          dX[static_cast<std::size_t>(c)](r, 3 * g) = dg;
          dX[static_cast<std::size_t>(c)](r, 3 * g + 1) = dg * x;
          dX[static_cast<std::size_t>(c)](r, 3 * g + 2) = dg * xd;
        }
    }
  }
}

// Residual of the regression at given switch constants (the variable projection functional),
// by column-pivoting QR of the column-scaled X: the SVD of fitLeastSquares is kept for the
// final fit, where its rank and condition number are reported. One per thread: it keeps its
// matrices from one evaluation to the next (a new X and QR each time cost more in page
// faults than in arithmetic).
class ProjectedResidual {
 public:
  ProjectedResidual(const MauchCylinderParams& model, const TrainingSet& set) : model_(model), set_(set) {}
  const Eigen::VectorXd& calc(const MauchSwitchParams& switches) {
    model_.switches = switches;
    buildRegressors(model_, set_, X_);
    return project();
  }
  // The regressors to fill for projectRegressors (rows x p).
  Eigen::MatrixXd& updRegressors(Eigen::Index rows, Eigen::Index p) {
    if (X_.rows() != rows || X_.cols() != p) X_.resize(rows, p);
    return X_;
  }
  // The residual of the regressors written through updRegressors.
  const Eigen::VectorXd& projectRegressors() { return project(); }
  // The residual and its Jacobian with respect to the first `n` switch constants (in
  // switchParameters' order, their own units), r = (I - P) y with P the projection on the
  // columns of X: d r = -(I - P) dX b - X+' dX' r (Golub & Pereyra 1973, Eq. 5.4; with the
  // columns scaled by D, X b = (X D^-1)(D b), and the scale's own derivative drops out
  // because P depends only on the span). Columns QR leaves out as dependent (rank below p)
  // are left out here too, as qr.solve does.
  const Eigen::VectorXd& calc(const MauchSwitchParams& switches, int n, Eigen::MatrixXd& jacobian) {
    model_.switches = switches;
    buildRegressorDerivatives(MauchCylinder(model_), set_, dX_, &X_);
    project();
    const Eigen::Index m = X_.rows(), rank = qr_.rank();
    const auto& perm = qr_.colsPermutation().indices();
    const auto R = qr_.matrixR().topLeftCorner(rank, rank).template triangularView<Eigen::Upper>();
    jacobian.resize(m, n);
    for (int k = 0; k < n; ++k) {
      Eigen::MatrixXd& dX = dX_[static_cast<std::size_t>(k)];
      for (Eigen::Index j = 0; j < dX.cols(); ++j) dX.col(j) *= 1.0 / scale_(j);
      // (I - P) dX b
      const Eigen::VectorXd v = dX * b_;
      Eigen::VectorXd term = v - X_ * qr_.solve(v);
      // X+' dX' r with X+ = Pi R^-1 Q' over the kept columns: X (R'R)^-1 (Pi' dX' r).
      Eigen::VectorXd w(rank);
      for (Eigen::Index c = 0; c < rank; ++c) w(c) = dX.col(perm(c)).dot(residual_);
      const Eigen::VectorXd t = R.solve(R.transpose().solve(w));
      for (Eigen::Index c = 0; c < rank; ++c) term += X_.col(perm(c)) * t(c);
      jacobian.col(k) = -term;
    }
    return residual_;
  }

 private:
  // Scales X's columns to unit length and fits y by QR: the residual, with b and the QR kept.
  const Eigen::VectorXd& project() {
    scale_ = calcColumnScale(X_);
    for (Eigen::Index j = 0; j < X_.cols(); ++j) X_.col(j) *= 1.0 / scale_(j);
    qr_.compute(X_);
    b_ = qr_.solve(set_.y);
    residual_ = set_.y - X_ * b_;
    return residual_;
  }

  MauchCylinderParams model_;
  const TrainingSet& set_;
  Eigen::MatrixXd X_;
  std::array<Eigen::MatrixXd, kSwitchConstants> dX_;
  Eigen::VectorXd scale_, b_, residual_;
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr_;
};

// The multi-start grid's costs |r|^2 of the projected residual, with the switch values
// shared between grid points computed once: in the latch history (calcLatchHistory, Eq. 6)
// the decay exp(-a h) of each sub-interval depends only on the velocity width and the latch
// rate, its target b only on the position width and xhy, and so do S1 and S8 of each
// sample; the grid has 6 and 20 such pairs for its 120 points, so the 120 latch histories
// need 11 times fewer tanh and exp. The arithmetic is calcLatchHistory's and
// calcMauchSwitches' (the fit's test checks the costs against calcProjectedResidual).
std::vector<double> calcGridCosts(const MauchCylinderParams& model, const TrainingSet& set,
                                  const std::vector<MauchSwitchParams>& grid, int threads) {
  constexpr int kSubsteps = 10;  // calcLatchHistory's default, as buildRegressors uses it
  // One entry per distinct pair, in first-seen order; per grid point, its pair's index.
  auto index = [](std::vector<std::pair<double, double>>& pairs, std::pair<double, double> key) {
    for (std::size_t i = 0; i < pairs.size(); ++i)
      if (pairs[i] == key) return i;
    pairs.push_back(key);
    return pairs.size() - 1;
  };
  std::vector<std::pair<double, double>> velocityPairs, positionPairs, widths;
  std::vector<std::size_t> velocityOf, positionOf, widthOf;
  for (const auto& g : grid) {
    velocityOf.push_back(index(velocityPairs, {g.velocityWidth, g.latchRate}));
    positionOf.push_back(index(positionPairs, {g.positionWidth, g.hyperextensionPosition}));
    widthOf.push_back(index(widths, {g.velocityWidth, 0.0}));
  }
  std::size_t substeps = 0;
  for (const auto& d : set.files) substeps += kSubsteps * (d.time.size() > 0 ? d.time.size() - 1 : 0);
  const auto rows = static_cast<std::size_t>(set.rows);
  std::vector<std::vector<double>> decay(velocityPairs.size(), std::vector<double>(substeps)),
      target(positionPairs.size(), std::vector<double>(substeps)), s1(widths.size(), std::vector<double>(rows)),
      s8(positionPairs.size(), std::vector<double>(rows));
  auto fill = [&](std::size_t first, std::size_t step) {
    // Tasks: each velocity pair's decays, each position pair's targets and S8, each width's S1.
    const std::size_t tasks = velocityPairs.size() + 2 * positionPairs.size() + widths.size();
    for (std::size_t task = first; task < tasks; task += step) {
      std::size_t k = 0, r = 0;
      for (const auto& d : set.files) {
        for (std::size_t i = 0; i < d.time.size(); ++i, ++r) {
          if (task >= velocityPairs.size() + 2 * positionPairs.size()) {
            const double vw = widths[task - velocityPairs.size() - 2 * positionPairs.size()].first;
            s1[task - velocityPairs.size() - 2 * positionPairs.size()][r] = 0.5 + 0.5 * std::tanh(d.velocity[i] / vw);
            continue;
          }
          if (task >= velocityPairs.size() + positionPairs.size()) {
            const auto [pw, xhy] = positionPairs[task - velocityPairs.size() - positionPairs.size()];
            s8[task - velocityPairs.size() - positionPairs.size()][r] = 0.5 + 0.5 * std::tanh((d.position[i] - xhy) / pw);
            continue;
          }
          if (i == 0) continue;
          const double h = (d.time[i] - d.time[i - 1]) / kSubsteps;
          for (int j = 0; j < kSubsteps; ++j, ++k) {
            const double w = (j + 0.5) / kSubsteps;
            if (task < velocityPairs.size()) {
              const auto [vw, rate] = velocityPairs[task];
              const double vm = d.velocity[i - 1] + w * (d.velocity[i] - d.velocity[i - 1]);
              const double a = rate * (0.5 - 0.5 * std::tanh(vm / vw));
              decay[task][k] = std::exp(-a * h);
            } else {
              const auto [pw, xhy] = positionPairs[task - velocityPairs.size()];
              const double xm = d.position[i - 1] + w * (d.position[i] - d.position[i - 1]);
              target[task - velocityPairs.size()][k] = 0.5 - 0.5 * std::tanh((xm - xhy) / pw);
            }
          }
        }
      }
    }
  };
  std::vector<double> costs(grid.size());
  auto evaluate = [&](std::size_t first, std::size_t step) {
    Eigen::MatrixXd X;
    ProjectedResidual projected(model, set);
    MauchCylinderParams params = model;
    double gates[MauchCylinder::kMaxGates];
    for (std::size_t g = first; g < grid.size(); g += step) {
      params.switches = grid[g];
      const MauchCylinder cylinder(params);
      const int p = cylinder.numCoefficients(), numGates = cylinder.numPhaseGates();
      const std::vector<double>&E = decay[velocityOf[g]], &B = target[positionOf[g]], &S1 = s1[widthOf[g]],
                            &S8 = s8[positionOf[g]];
      Eigen::MatrixXd& Xg = projected.updRegressors(set.rows, p);
      std::size_t k = 0, r = 0;
      for (std::size_t f = 0; f < set.files.size(); ++f) {
        const BenchData& d = set.files[f];
        double s2 = 0.0;
        for (std::size_t i = 0; i < d.time.size(); ++i, ++r) {
          if (i > 0)
            for (int j = 0; j < kSubsteps; ++j, ++k) s2 = B[k] + (s2 - B[k]) * E[k];
          cylinder.calcGates(combineMauchSwitches(S1[r], s2, S8[r]), gates);
          const double x = d.position[i], xd = d.velocity[i];
          for (int q = 0; q < numGates; ++q) {
            Xg(static_cast<Eigen::Index>(r), 3 * q) = gates[q];
            Xg(static_cast<Eigen::Index>(r), 3 * q + 1) = gates[q] * x;
            Xg(static_cast<Eigen::Index>(r), 3 * q + 2) = gates[q] * xd;
          }
          if (p > 3 * numGates) {
            // The added effects' columns do not depend on the switch constants.
            double row[3 * MauchCylinder::kMaxGates + 4];
            cylinder.calcRegressorRow(x, xd, set.accel[f][i], s2, row);
            for (int c = 3 * numGates; c < p; ++c) Xg(static_cast<Eigen::Index>(r), c) = row[c];
          }
        }
      }
      costs[g] = projected.projectRegressors().squaredNorm();
    }
  };
  if (threads > 1) {
    // async | deferred: where a thread cannot start (a memory or process limit), the half
    // runs in this thread at get() instead of throwing std::system_error.
    auto other = std::async(kAsyncOrHere, fill, 1, 2);
    fill(0, 2);
    other.get();
    auto second = std::async(kAsyncOrHere, evaluate, 1, 2);
    evaluate(0, 2);
    second.get();
  } else {
    fill(0, 1);
    evaluate(0, 1);
  }
  return costs;
}

}  // namespace

std::vector<double> calcSwitchGridCosts(const MauchCylinderParams& model, const std::vector<BenchData>& train,
                                        const std::vector<MauchSwitchParams>& grid) {
  const TrainingSet set(model, train);
  return calcGridCosts(model, set, grid, 2);
}

Eigen::VectorXd calcProjectedResidual(const MauchCylinderParams& params, const std::vector<BenchData>& train,
                                      Eigen::MatrixXd* jacobian) {
  const TrainingSet set(params, train);
  ProjectedResidual projected(params, set);
  return jacobian ? projected.calc(params.switches, kSwitchConstants, *jacobian) : projected.calc(params.switches);
}

namespace {

// Training residual y - X b of a model (its coefficients as given) along every record.
Eigen::VectorXd predictionResidual(const MauchCylinderParams& params, const TrainingSet& set, Eigen::MatrixXd& X) {
  buildRegressors(params, set, X);
  const std::vector<double> b = MauchCylinder(params).getCoefficientVector();
  return set.y - X * Eigen::Map<const Eigen::VectorXd>(b.data(), static_cast<Eigen::Index>(b.size()));
}

// The switch constants as bounded parameters, in the order of switchesFrom.
std::vector<BoundedParameter> switchParameters(const MauchSwitchParams& start, const SwitchConstantRanges& r,
                                               bool latch) {
  std::vector<BoundedParameter> ps = {
      {"velocity_width_m_per_s", start.velocityWidth, r.velocityWidth[0], r.velocityWidth[1], true, 1.0},
      {"position_width_m", start.positionWidth, r.positionWidth[0], r.positionWidth[1], true, 1.0},
      {"hyperextension_position_m", start.hyperextensionPosition, r.hyperextension[0], r.hyperextension[1], false, 1e-4},
  };
  if (latch) ps.push_back({"latch_rate_per_s", start.latchRate, r.latchRate[0], r.latchRate[1], true, 1.0});
  return ps;
}

MauchSwitchParams switchesFrom(MauchSwitchParams s, const double* x, bool latch) {
  s.velocityWidth = x[0];
  s.positionWidth = x[1];
  s.hyperextensionPosition = x[2];
  if (latch) s.latchRate = x[3];
  return s;
}

// Physical bounds of the linear coefficients (mauchCoefficients says which are >= 0).
std::vector<std::pair<double, double>> coefficientBounds(const MauchCylinderParams& params) {
  std::vector<std::pair<double, double>> b;
  for (const auto& c : mauchCoefficients(params)) b.push_back({c.nonNegative ? 0.0 : -1e300, 1e300});
  return b;
}

// Best multi-start points polished by Ceres: the switch-width surface has flat regions (a
// width far below the data's resolution makes a step) where a polish started there stalls.
constexpr std::size_t kPolishedStarts = 3;

// Regression with coefficients kept within physical bounds, by an active set: solve, fix
// every coefficient outside its bound on that bound, solve for the others, repeat. Fixed
// coefficients get a NaN standard error and `fixed` set.
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
            out.correlation(freeCols[a], freeCols[b]) = fit.correlation(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
      }
      return out;
    }
  }
  return fit;  // unreachable: each pass fixes at least one more coefficient
}

// Geometric points spread over [lo, hi]: lo (hi/lo)^((i + 1/2) / n).
std::vector<double> spreadLog(const double range[2], int n) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(range[0] * std::pow(range[1] / range[0], (i + 0.5) / n));
  return v;
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

// The multi-start grid: widths and latch rate spread over their physical ranges, xhy at low
// quantiles of the training positions (hyperextension is where the piston is lowest); the
// model's own switch constants alone without options.multiStart.
std::vector<MauchSwitchParams> makeSwitchStarts(const MauchCylinderParams& model, const std::vector<BenchData>& train,
                                                const CylinderFitOptions& options) {
  std::vector<double> positions;
  for (const auto& d : train) positions.insert(positions.end(), d.position.begin(), d.position.end());
  std::sort(positions.begin(), positions.end());
  const SwitchConstantRanges& R = options.ranges;
  std::vector<double> xhyStarts;
  for (double q : {0.02, 0.05, 0.1, 0.2, 0.3}) {
    const double v = positions[static_cast<std::size_t>(q * static_cast<double>(positions.size() - 1))];
    xhyStarts.push_back(std::clamp(v, R.hyperextension[0], R.hyperextension[1]));
  }
  std::vector<double> vws = spreadLog(R.velocityWidth, 3), pws = spreadLog(R.positionWidth, 4);
  std::vector<double> ks = options.fitLatchRate ? spreadLog(R.latchRate, 2) : std::vector<double>{model.switches.latchRate};
  if (!options.multiStart) {
    vws.assign(1, model.switches.velocityWidth);
    pws.assign(1, model.switches.positionWidth);
    xhyStarts.assign(1, model.switches.hyperextensionPosition);
    ks.assign(1, model.switches.latchRate);
  }
  std::vector<MauchSwitchParams> grid;
  for (double vw : vws)
    for (double pw : pws)
      for (double xh : xhyStarts)
        for (double k : ks) grid.push_back({vw, pw, xh, k});
  return grid;
}

// Polishes the best starts by Ceres over the switch constants (linear part projected out),
// each on its own thread; returns the best switch constants found. `done`: starts already
// evaluated, for the progress callback.
MauchSwitchParams polishSwitchStarts(const MauchCylinderParams& model, const TrainingSet& set,
                                     const std::vector<MauchSwitchParams>& sortedStarts, const CylinderFitOptions& options,
                                     int done, CylinderFit& out) {
  const bool latch = options.fitLatchRate;
  BoundedFitSettings settings;
  // A polish near a known fit (no multi-start) needs a few steps; its budget says so.
  settings.maxIterations = options.multiStart ? 50 : 12;
  settings.maxSeconds = 30.0;
  settings.functionTolerance = options.multiStart ? 1e-6 : 1e-5;
  settings.computeCovariance = false;
  // The 2-phase model on 4-phase data has a curved, flat valley: monotone steps crept along
  // it to the iteration budget from one of the three starts.
  settings.nonmonotonicSteps = true;
  auto polish = [&](const MauchSwitchParams& from) {
    ProjectedResidual projected(model, set);
    ResidualJacobianFunction f = [&](const Eigen::VectorXd& x, Eigen::MatrixXd* jacobian) -> Eigen::VectorXd {
      const MauchSwitchParams switches = switchesFrom(model.switches, x.data(), latch);
      return jacobian ? projected.calc(switches, static_cast<int>(x.size()), *jacobian) : projected.calc(switches);
    };
    return solveBoundedLeastSquares(f, switchParameters(from, options.ranges, latch), settings);
  };
  const std::size_t polished = std::min<std::size_t>(kPolishedStarts + options.extraStarts.size(), sortedStarts.size());
  std::vector<std::future<BoundedFitResult>> runs;
  for (std::size_t s = 1; s < polished; ++s) runs.push_back(std::async(kAsyncOrHere, polish, sortedStarts[s]));  // see kAsyncOrHere
  std::vector<BoundedFitResult> results;
  results.push_back(polish(sortedStarts[0]));
  for (auto& r : runs) results.push_back(r.get());
  double bestCost = std::numeric_limits<double>::infinity();
  MauchSwitchParams bestSwitches = model.switches;
  for (std::size_t s = 0; s < results.size(); ++s) {
    const BoundedFitResult& r = results[s];
    if (options.multiStart && !r.converged && r.iterations >= settings.maxIterations)
      out.warnings.push_back("the switch-constant fit stopped at its budget of " + std::to_string(settings.maxIterations) +
                             " iterations without converging");
    if (r.cost < bestCost) {
      bestCost = r.cost;
      bestSwitches = switchesFrom(model.switches, r.x.data(), latch);
    }
    if (options.progress) options.progress(done + static_cast<int>(s) + 1, done + static_cast<int>(polished));
  }
  return bestSwitches;
}

// The switch constants: every start of the grid costed (on two threads, results in grid
// order, so the fit is the same on any machine), the best ones polished.
MauchSwitchParams fitSwitchConstants(const MauchCylinderParams& model, const std::vector<BenchData>& train,
                                     const CylinderFitOptions& options, CylinderFit& out) {
  struct Start {
    double cost;
    MauchSwitchParams switches;
  };
  const std::vector<MauchSwitchParams> grid = makeSwitchStarts(model, train, options);
  const int total = static_cast<int>(grid.size());
  const TrainingSet set(model, train);
  const std::vector<double> costs = calcGridCosts(model, set, grid, grid.size() > 1 ? 2 : 1);
  std::vector<Start> starts;
  for (std::size_t i = 0; i < grid.size(); ++i) starts.push_back({costs[i], grid[i]});
  if (options.progress) options.progress(total, total + static_cast<int>(kPolishedStarts));
  std::stable_sort(starts.begin(), starts.end(), [](const Start& a, const Start& b) { return a.cost < b.cost; });
  out.switchStarts = static_cast<int>(starts.size());
  // The extra starts first: each is polished, then the grid's best.
  std::vector<MauchSwitchParams> sorted = options.multiStart ? options.extraStarts : std::vector<MauchSwitchParams>{};
  for (const auto& s : starts) sorted.push_back(s.switches);
  return polishSwitchStarts(model, set, sorted, options, total, out);
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
void calcJointCovariance(const std::vector<BenchData>& train, bool latch, std::size_t rows, MauchCylinderParams& current,
                         LinearFit& best, ConstantEstimates& est) {
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
      out.collinear.push_back(
          {est.all[static_cast<std::size_t>(i)].name, est.all[static_cast<std::size_t>(j)].name, est.correlation(i, j)});
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
    out.warnings.push_back("rank-deficient regression (rank " + std::to_string(best.rank) + " of " + std::to_string(p) +
                           "): some phase is (almost) never active in the training data; its coefficients are not identified");
  else if (best.conditionNumber > kIllConditionedLimit)
    out.warnings.push_back("ill-conditioned regression (condition number " + formatNumber(best.conditionNumber) +
                           " > " + formatNumber(kIllConditionedLimit) + "): coefficients are poorly determined");
  return out;
}

}  // namespace swingsim
