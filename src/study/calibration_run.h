#pragma once
// `swingsim calibrate`: each participant's hip-moment time scale fitted to a standard-location
// swing time (Burkett 2004 Table 3's model or measured column, or a given time) and stored in
// the participant's file.
#include <optional>
#include <string>
#include <vector>

#include "sweep/calibration.h"

namespace swingsim {

/// What a calibration is given.
struct CalibrationRequest {
  std::vector<std::string> participants;                 ///< participant files, each once
  std::optional<double> target;                          ///< s; nullopt: Burkett 2004 Table 3, column `column`
  CalibrationTarget column = CalibrationTarget::kModel;  ///< kModel or kMeasured
  bool dryRun = false;                                   ///< print, do not store
};

/// Calibrates every file (the result and its monotonicity scan on stdout, progress on stderr)
/// before any is written; then, unless dryRun, stores each rewritten time scale (six decimals).
/// Throws InputError for a file that cannot be calibrated or a name not in Burkett's table
/// without a target.
void runCalibration(const CalibrationRequest& request);

}  // namespace swingsim
