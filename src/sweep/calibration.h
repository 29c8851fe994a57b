#pragma once
// Calibration of the one free hip-moment parameter per participant (docs/assumptions.md,
// "Hip moment"): the profile's time scale, chosen so the standard-location swing time equals a
// target (Burkett Table 3's model prediction).
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sweep/burkett_published.h"
#include "swing/swing_simulation.h"

namespace swingsim {

/// Which standard-location swing time a participant's hip time scale is calibrated to.
enum class CalibrationTarget {
  kStored,    ///< none: keep the time scale in the participant file
  kModel,     ///< Burkett 2004 Table 3, model prediction (the default participants' calibration)
  kMeasured,  ///< Burkett 2004 Table 3, measured mean (then Table 4 measured is the validation)
};

/// Every target with its key, in enum order: stored, model, measured.
const std::vector<std::pair<std::string, CalibrationTarget>>& calibrationTargetChoices();
/// The key of a target ("stored", "model", "measured").
const char* calibrationTargetKey(CalibrationTarget target);
/// The target of a key, or nullopt.
std::optional<CalibrationTarget> findCalibrationTarget(const std::string& key);
/// Table 3's swing time for `column` (kModel or kMeasured), s.
double table3Target(const PublishedParticipant& published, CalibrationTarget column);

struct CalibrationResult {
  double timeScale = 0;  ///< calibrated hip-moment time scale
  double swingTime = 0;  ///< s, swing time at that scale (lowering 0)
  /// The scan that checked monotonicity: scale and swing time (NaN where no swing end).
  std::vector<double> scanScales, scanSwingTimes;
  /// d(swing time)/d(scale) at the solution, s per unit scale, from the last two swings
  /// (NaN if unknown): what a swing-time error means for the scale.
  double swingTimePerScale = std::numeric_limits<double>::quiet_NaN();
  int swings = 0;  ///< swings simulated: the scan and the bisection
};

struct CalibrationOptions {
  double minScale = 0.85, maxScale = 1.8;
  int scanPoints = 14;
  double timeTolerance = 1e-5;  ///< s: stop when |swing time - target| is below this
};

/// InputError with the reason if `p` has no hip moment time scale to calibrate (its swing is
/// driven by the measured thigh), whatever the target.
void checkCalibratable(const Participant& p);

/// Finds the scale. Throws RunError if swing time does not rise monotonically with the time scale over the
/// scan, or the target is outside the reachable range.
CalibrationResult calibrateHipTimeScale(const SwingSetup& setup, double targetSwingTime,
                                        const SwingOptions& swingOptions = {}, const CalibrationOptions& options = {});

/// The same, starting from a scale known to be close (`start`, e.g. the solution for a
/// slightly different model): secant steps on the scale, about 3-5 swings instead of the
/// scan's 20-30. Falls back to calibrateHipTimeScale (the scan and its monotonicity check)
/// when a step leaves the range, a swing does not end or the secant does not close in 8 steps.
CalibrationResult calibrateHipTimeScaleNear(const SwingSetup& setup, double targetSwingTime, double start,
                                            const SwingOptions& swingOptions = {},
                                            const CalibrationOptions& options = {});

}  // namespace swingsim
