#include "identify/projected_residual.h"

#include <cmath>

#include <ceres/jet.h>

namespace swingsim {

namespace {

using SwitchJet = ceres::Jet<double, kSwitchConstants>;

}  // namespace

// d X / d (velocity width, position width, xhy, latch rate) at the model's switch constants:
// the latch history (calcLatchHistory, Eq. 6) differentiated by hand, the switches and gates
// (calcMauchSwitches, MauchCylinder::calcGates; Chien 2014 Eqs. 3-4, 12-16) by forward-mode
// differentiation (ceres::Jet). These equations are written here a second time; the fit's
// test checks the result against finite differences of the residual. Only the phase-gate
// columns depend on the switch constants; the added effects' columns get zero derivatives.
// With X, also the regressors themselves (the latch from the same floating-point operations
// as calcLatchHistory's), so they need no second latch history.
void buildRegressorDerivatives(const MauchCylinder& cylinder, const TrainingSet& set,
                               std::array<Eigen::MatrixXd, kSwitchConstants>& dX, Eigen::MatrixXd* X) {
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

const Eigen::VectorXd& ProjectedResidual::calc(const MauchSwitchParams& switches) {
  model_.switches = switches;
  buildRegressors(model_, set_, X_);
  return project();
}

const Eigen::VectorXd& ProjectedResidual::calc(const MauchSwitchParams& switches, int n, Eigen::MatrixXd& jacobian) {
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

// Scales X's columns to unit length and fits y by QR: the residual, with b and the QR kept.
const Eigen::VectorXd& ProjectedResidual::project() {
  scale_ = calcColumnScale(X_);
  for (Eigen::Index j = 0; j < X_.cols(); ++j) X_.col(j) *= 1.0 / scale_(j);
  qr_.compute(X_);
  b_ = qr_.solve(set_.y);
  residual_ = set_.y - X_ * b_;
  return residual_;
}

Eigen::VectorXd calcProjectedResidual(const MauchCylinderParams& params, const std::vector<BenchData>& train,
                                      Eigen::MatrixXd* jacobian) {
  const TrainingSet set(params, train);
  ProjectedResidual projected(params, set);
  return jacobian ? projected.calc(params.switches, kSwitchConstants, *jacobian) : projected.calc(params.switches);
}

std::vector<BoundedParameter> switchParameters(const MauchSwitchParams& start, const SwitchConstantRanges& r,
                                               bool latch) {
  std::vector<BoundedParameter> ps = {
      {"velocity_width_m_per_s", start.velocityWidth, r.velocityWidth[0], r.velocityWidth[1], true, 1.0},
      {"position_width_m", start.positionWidth, r.positionWidth[0], r.positionWidth[1], true, 1.0},
      {"hyperextension_position_m", start.hyperextensionPosition, r.hyperextension[0], r.hyperextension[1], false,
       1e-4},
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

}  // namespace swingsim
