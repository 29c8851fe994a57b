#pragma once
// Fitting Mauch cylinder coefficients to bench data (Chien 2014, "multiple linear
// regression"): all phases' f, k, c together by rank-revealing least squares, with the
// condition number and standard errors; optionally profiling the switch widths and xhy.
#include <Eigen/Dense>

#include <functional>
#include <string>
#include <vector>

#include "identify/bench_data.h"
#include "knee/mauch_cylinder.h"

namespace swingsim {

/// Result of a linear least-squares fit y ~ X b.
struct LinearFit {
  std::vector<double> coefficients;
  /// sqrt(diag(s^2 (X'X)^-1)), s^2 = RSS / (n - p); NaN when rank-deficient or n <= p.
  std::vector<double> standardErrors;
  int rank = 0;
  /// Ratio of largest to smallest singular value of X with its columns scaled to unit
  /// length (so it measures collinearity, not the choice of units). Inf if rank-deficient.
  double conditionNumber = 0;
  double residualRms = 0;  ///< sqrt(RSS / n)
  std::size_t samples = 0;
};

/// Solves by singular value decomposition of the column-scaled X (rank-revealing; the
/// minimum-norm solution if rank-deficient). Throws std::invalid_argument on size mismatch.
LinearFit fitLeastSquares(const Eigen::MatrixXd& X, const Eigen::VectorXd& y);

/// Above this scaled condition number the fit warns: a relative error of 1e-16 in the data
/// can then move some coefficient combination by more than 1e-8 relative, and noise of a
/// few percent makes individual coefficients meaningless (only their sum is determined).
constexpr double kIllConditionedLimit = 1e8;

struct CylinderFitOptions {
  bool fitSwitches = false;  ///< also profile velocity width, position width and xhy
  int gridPoints = 9;        ///< per switch constant, log-spaced
  double gridFactor = 10.0;  ///< grid spans value / factor .. value * factor
  /// Called as progress(done, total) while profiling.
  std::function<void(int, int)> progress;
};

struct CylinderFit {
  MauchCylinderParams params;   ///< the model with fitted coefficients (and switches)
  LinearFit regression;         ///< at the final switches
  MauchSwitchParams startSwitches;
  double trainRmseAtStart = 0;  ///< N, coefficients fitted at the YAML switches
  bool switchesFitted = false;
  std::vector<std::string> warnings;
};

/// Fits `model`'s coefficients (its values are only a start for switches) to the training
/// files, each starting unlatched (S2 = 0: bench records start at heel strike).
/// Throws InputError if there are fewer samples than coefficients, or if fitSwitches is
/// set with a non-positive xhy (no log grid). Throws RunError if a phase is active in fewer
/// than 3 training samples (gate summed over samples): its coefficients are not identified.
CylinderFit fitCylinder(const MauchCylinderParams& model, const std::vector<BenchData>& train,
                        const CylinderFitOptions& options = {});

/// Predicted force and switch traces of a cylinder along a bench file (S2 = 0 at start).
CylinderTrace predictBench(const MauchCylinder& cylinder, const BenchData& data);

}  // namespace swingsim
