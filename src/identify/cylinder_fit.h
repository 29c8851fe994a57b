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
  /// Correlation of the coefficients, from (X'X)^-1 (p x p; empty when rank-deficient).
  /// Coefficients held on a bound (regressWithinBounds) have zero correlation with the rest.
  Eigen::MatrixXd correlation;
};

/// Solves by singular value decomposition of the column-scaled X (rank-revealing; the
/// minimum-norm solution if rank-deficient). Throws std::invalid_argument on size mismatch.
LinearFit fitLeastSquares(const Eigen::MatrixXd& X, const Eigen::VectorXd& y);

/// Above this scaled condition number the fit warns: a relative error of 1e-16 in the data
/// can then move some coefficient combination by more than 1e-8 relative, and noise of a
/// few percent makes individual coefficients meaningless (only their sum is determined).
constexpr double kIllConditionedLimit = 1e8;

/// Physical ranges of the switch constants searched by the fit (docs/mauch.md, "Fitting", says
/// where each comes from).
struct SwitchConstantRanges {
  double velocityWidth[2] = {1e-5, 2e-2};    ///< m/s: sensor resolution .. 10 % of peak piston speed
  double positionWidth[2] = {1e-6, 2e-3};    ///< m: sensor resolution .. 5 % of the stroke
  double hyperextension[2] = {-2e-3, 2e-3};  ///< xhy, m: within 2 mm of full extension
  double latchRate[2] = {5.0, 1e5};          ///< 1/s: time constant 0.2 s .. far below a sample
};

struct CylinderFitOptions {
  /// Also fit the switch constants (velocity and position widths, xhy and, if fitLatchRate,
  /// the latch rate) by bounded nonlinear least squares (Ceres) with the linear coefficients
  /// projected out (variable projection), from a multi-start grid spread over the physical
  /// ranges and the training positions: the model file's switch values are not used.
  bool fitSwitches = false;
  bool fitLatchRate = true;
  /// false: polish from the model's own switch constants only (a refit near a known fit).
  bool multiStart = true;
  /// With multiStart: further starts, each polished besides the grid's best (a refit
  /// starts from the solution it refits and along the grid of a parameter it frees).
  std::vector<MauchSwitchParams> extraStarts;
  SwitchConstantRanges ranges;
  /// Called as progress(done, total) while fitting switch constants.
  std::function<void(int, int)> progress;
};

/// One fitted constant with its uncertainty and what is wrong with it, if anything.
struct FittedConstant {
  std::string name;  ///< "phase 2 c_Ns_per_m", "velocity_width_m_per_s"
  double value = 0;
  double standardError = 0;              ///< NaN if not identified
  double lower = -1e300, upper = 1e300;  ///< physical bounds
  bool atBound = false;                  ///< the data pushed it onto a physical bound
  bool includesZero = false;             ///< its 95 % confidence interval includes 0
};

/// A correlated pair of fitted constants (|r| above the collinearity limit).
struct CollinearPair {
  std::string a, b;
  double correlation = 0;
};

/// Correlation magnitude above which two fitted constants are reported as collinear.
constexpr double kCollinearLimit = 0.95;

struct CylinderFit {
  MauchCylinderParams params;   ///< the model with fitted coefficients (and switches)
  LinearFit regression;         ///< at the final switches (coefficients, standard errors final)
  double trainRmseAtStart = 0;  ///< N, coefficients fitted at the YAML switches
  bool switchesFitted = false;
  int switchStarts = 0;  ///< multi-start points tried
  /// Every fitted constant (linear coefficients in regressor order, then fitted switch
  /// constants), with standard errors from the Jacobian at the solution.
  std::vector<FittedConstant> constants;
  std::vector<CollinearPair> collinear;  ///< |r| > kCollinearLimit, strongest first
  /// Correlation of `constants` (same order): of the regression's coefficients at fixed
  /// switch constants, of every constant when they are fitted. Empty if not computable.
  Eigen::MatrixXd correlation;
  std::vector<std::string> warnings;
};

/// Names (with units) of a model's linear coefficients in regressor order.
std::vector<std::string> mauchCoefficientNames(const MauchCylinderParams& params);

/// Fits `model`'s coefficients (its values are only a start for switches) to the training
/// files, each starting unlatched (S2 = 0: bench records start at heel strike).
/// Throws InputError if there are fewer samples than coefficients. Throws RunError if a phase is active in fewer
/// than 3 training samples (gate summed over samples): its coefficients are not identified.
CylinderFit fitCylinder(const MauchCylinderParams& model, const std::vector<BenchData>& train,
                        const CylinderFitOptions& options = {});

/// The switch-constant fit's objective (variable projection): the training residual y - X b,
/// N per sample, with the linear coefficients b fitted by least squares at `params`' switch
/// constants (each file starting unlatched). With `jacobian`, also its exact derivative with
/// respect to the velocity width, position width, xhy and latch rate (m/s, m, m, 1/s; one
/// column each, Golub & Pereyra 1973), as the fit's Ceres polish uses it.
Eigen::VectorXd calcProjectedResidual(const MauchCylinderParams& params, const std::vector<BenchData>& train,
                                      Eigen::MatrixXd* jacobian = nullptr);

/// The squared norm of calcProjectedResidual (N^2) at each set of switch constants of a
/// multi-start grid, as the fit ranks its starts: switch values that grid points share
/// (the same velocity width and latch rate, or the same position width and xhy) are computed
/// once, on two threads.
std::vector<double> calcSwitchGridCosts(const MauchCylinderParams& model, const std::vector<BenchData>& train,
                                        const std::vector<MauchSwitchParams>& grid);

/// Predicted force and switch traces of a cylinder along a bench file (S2 = 0 at start).
CylinderTrace predictBench(const MauchCylinder& cylinder, const BenchData& data);

}  // namespace swingsim
