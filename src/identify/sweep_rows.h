#pragma once
// The measured swing times of a sweep diagnosis, participant by participant: each row
// assigned to its participant and checked, the lowered rows in order of lowering, and their
// error covariance (each row's own noise and the standard row's, shared through the
// calibrated time scale) with its whitening for the likelihood.
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "model/measured_swing_time.h"
#include "sweep/sweep.h"
#include "sweep/sweep_assumptions.h"

namespace swingsim {

/// One participant of the plant with its measured rows.
struct SweepParticipantRows {
  SweepVariant nominal;
  MeasuredSwingTime standard;              ///< the row at lowering 0 (calibration target)
  std::vector<MeasuredSwingTime> lowered;  ///< compared rows, by lowering
  /// s, of each lowered row's prediction error: its own standard error and the standard
  /// row's, carried by the calibrated time scale (sqrt(se^2 + (T_d / T_0)^2 se_0^2))
  std::vector<double> standardErrors;
  /// L^-1, L the Cholesky factor of the rows' error covariance diag(se^2) + v v'
  /// (v_k = (T_k / T_0) se_0): whitens a residual vector (generalized least squares).
  Eigen::MatrixXd whitening;
  /// The independent samples the rows' RMS error is worth, (tr C)^2 / tr C^2 (Satterthwaite).
  double effectiveRows = 0;
  double standardRowError = 0;  ///< s, of the standard row
  bool inModel = true;
  std::string outside;  ///< why not in the model
};

/// The participants of `study` (nominal variant each) with the rows that name them: the row
/// at lowering 0 as the standard row, the others as lowered rows with their standard errors
/// (a row without sd_s takes `defaultStandardError`, s). `hasStandard`: per participant,
/// whether it has a standard row. A lowered row beyond the shank's physical limit is left out
/// with a note in `notes`. Throws InputError (`measuredPath`:line:) for a row naming no
/// participant of the study or without a standard error.
std::vector<SweepParticipantRows> assignSweepRows(const SweepStudy& study, const std::vector<MeasuredSwingTime>& rows,
                                                  const std::string& measuredPath, double defaultStandardError,
                                                  std::vector<bool>& hasStandard, std::vector<std::string>& notes);

/// Puts `p`'s lowered rows in order of lowering and sets their standard errors, whitening and
/// effective number of rows from their error covariance (the standard row's share only when
/// `hasStandard`).
void whitenSweepRows(SweepParticipantRows& p, bool hasStandard);

}  // namespace swingsim
