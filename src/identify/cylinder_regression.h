#pragma once
// The cylinder fit's regression at fixed switch constants, shared by the units of the fit
// (cylinder_fit.cpp, projected_residual.cpp, switch_grid_costs.cpp, switch_search.cpp): the
// training records laid end to end, the regressors y ~ X b of Chien 2014's force law, the
// physical bounds of the coefficients and the regression kept within them.
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "identify/bench_data.h"
#include "identify/cylinder_fit.h"
#include "knee/mauch_cylinder.h"

namespace swingsim {

// The training records laid end to end with what does not depend on the model's constants:
// the measured force less the users' expression forces and, for an added inertia, the piston acceleration estimate.
struct TrainingSet {
  TrainingSet(const MauchCylinderParams& model, const std::vector<BenchData>& files) : files(files) {
    for (const auto& d : files) rows += static_cast<Eigen::Index>(d.time.size());
    y.resize(rows);
    Eigen::Index r = 0;
    // The users' expression forces add no column: the regression fits what they leave.
    const CylinderExpressionForces expressions(model.effects.expressions);
    for (const auto& d : files) {
      accel.push_back(model.effects.inertia ? estimatePistonVelocity(d.time, d.velocity)
                                            : std::vector<double>(d.time.size(), 0.0));
      for (std::size_t i = 0; i < d.force.size(); ++i)
        y(r++) = d.force[i] - (expressions.empty() ? 0.0 : expressions.calcForce(d.position[i], d.velocity[i]));
    }
  }
  const std::vector<BenchData>& files;
  Eigen::Index rows = 0;
  Eigen::VectorXd y;                       // N
  std::vector<std::vector<double>> accel;  // m/s^2, per file
};

/// Euclidean norm of each column of X (1 for an all-zero column): dividing by it makes the
/// conditioning a measure of collinearity, not of the choice of units.
Eigen::VectorXd calcColumnScale(const Eigen::MatrixXd& X);

/// The regressors X (rows x coefficients) of y ~ X b at the model's switch constants, written
/// into X (resized only if its shape changes: the fit builds them thousands of times).
void buildRegressors(const MauchCylinderParams& params, const TrainingSet& set, Eigen::MatrixXd& X);
/// The regression problem y ~ X b at fixed switch constants.
void buildRegression(const MauchCylinderParams& params, const std::vector<BenchData>& train, Eigen::MatrixXd& X,
                     Eigen::VectorXd& y);
/// Regression at fixed switch constants.
LinearFit regress(const MauchCylinderParams& params, const std::vector<BenchData>& train);
/// Training residual y - X b of a model (its coefficients as given) along every record.
Eigen::VectorXd predictionResidual(const MauchCylinderParams& params, const TrainingSet& set, Eigen::MatrixXd& X);

/// Physical bounds of the linear coefficients, in regressor order: a hydraulic cylinder
/// dissipates, so every damping (c, orifice a) is >= 0; seal friction opposes motion
/// (Fc >= 0); a moving mass is >= 0. Offsets, stiffnesses and the stroke-dependent damping
/// change are free.
std::vector<std::pair<double, double>> coefficientBounds(const MauchCylinderParams& params);
/// Regression with coefficients kept within physical bounds, by an active set: solve, fix
/// every coefficient outside its bound on that bound, solve for the others, repeat. Fixed
/// coefficients get a NaN standard error and `fixed` set.
LinearFit regressWithinBounds(const MauchCylinderParams& params, const std::vector<BenchData>& train,
                              const std::vector<std::pair<double, double>>& bounds, std::vector<bool>& fixed);

}  // namespace swingsim
