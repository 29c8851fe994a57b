#pragma once
// The switch-constant fit's objective by variable projection: the regressors' derivatives with
// respect to the switch constants, and the projected residual with its exact Jacobian
// (Golub & Pereyra 1973), as the multi-start polish and the joint covariance use them.
#include <array>
#include <vector>

#include <Eigen/Dense>

#include "identify/cylinder_regression.h"
#include "numerics/bounded_least_squares.h"

namespace swingsim {

/// Number of switch constants the fit can free: velocity width, position width, xhy, latch rate.
constexpr int kSwitchConstants = 4;

/// d X / d (velocity width, position width, xhy, latch rate) at the model's switch constants
/// (projected_residual.cpp says how); with X, also the regressors themselves.
void buildRegressorDerivatives(const MauchCylinder& cylinder, const TrainingSet& set,
                               std::array<Eigen::MatrixXd, kSwitchConstants>& dX, Eigen::MatrixXd* X = nullptr);

/// Residual of the regression at given switch constants (the variable projection functional),
/// by column-pivoting QR of the column-scaled X: the SVD of fitLeastSquares is kept for the
/// final fit, where its rank and condition number are reported. One per thread: it keeps its
/// matrices from one evaluation to the next (a new X and QR each time cost more in page
/// faults than in arithmetic).
class ProjectedResidual {
 public:
  ProjectedResidual(const MauchCylinderParams& model, const TrainingSet& set) : model_(model), set_(set) {}
  /// The residual at `switches`.
  const Eigen::VectorXd& calc(const MauchSwitchParams& switches);
  /// The regressors to fill for projectRegressors (rows x p).
  Eigen::MatrixXd& updRegressors(Eigen::Index rows, Eigen::Index p) {
    if (X_.rows() != rows || X_.cols() != p) X_.resize(rows, p);
    return X_;
  }
  /// The residual of the regressors written through updRegressors.
  const Eigen::VectorXd& projectRegressors() { return project(); }
  /// The residual and its Jacobian with respect to the first `n` switch constants (in
  /// switchParameters' order, their own units), r = (I - P) y with P the projection on the
  /// columns of X: d r = -(I - P) dX b - X+' dX' r (Golub & Pereyra 1973, Eq. 5.4; with the
  /// columns scaled by D, X b = (X D^-1)(D b), and the scale's own derivative drops out
  /// because P depends only on the span). Columns QR leaves out as dependent (rank below p)
  /// are left out here too, as qr.solve does.
  const Eigen::VectorXd& calc(const MauchSwitchParams& switches, int n, Eigen::MatrixXd& jacobian);

 private:
  // Scales X's columns to unit length and fits y by QR: the residual, with b and the QR kept.
  const Eigen::VectorXd& project();

  MauchCylinderParams model_;
  const TrainingSet& set_;
  Eigen::MatrixXd X_;
  std::array<Eigen::MatrixXd, kSwitchConstants> dX_;
  Eigen::VectorXd scale_, b_, residual_;
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr_;
};

/// The switch constants as bounded parameters, in the order of switchesFrom.
std::vector<BoundedParameter> switchParameters(const MauchSwitchParams& start, const SwitchConstantRanges& r,
                                               bool latch);
/// `s` with the fitted switch constants x (switchParameters' order) written in.
MauchSwitchParams switchesFrom(MauchSwitchParams s, const double* x, bool latch);

}  // namespace swingsim
