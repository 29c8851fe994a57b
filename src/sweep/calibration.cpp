#include "sweep/calibration.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "core/input_error.h"

namespace swingsim {

namespace {

double swingTimeAt(SwingSetup setup, double scale, const SwingOptions& options) {
  setup.participant.hipMoment.timeScale = scale;
  try {
    return simulateSwing(setup, options).swingTime;
  } catch (const RunError&) {
    return std::numeric_limits<double>::quiet_NaN();  // no swing end at this scale
  }
}

}  // namespace

const std::vector<std::pair<std::string, CalibrationTarget>>& calibrationTargetChoices() {
  static const std::vector<std::pair<std::string, CalibrationTarget>> choices = {
      {"stored", CalibrationTarget::kStored},
      {"model", CalibrationTarget::kModel},
      {"measured", CalibrationTarget::kMeasured}};
  return choices;
}

const char* calibrationTargetKey(CalibrationTarget target) {
  return calibrationTargetChoices()[static_cast<std::size_t>(target)].first.c_str();
}

std::optional<CalibrationTarget> findCalibrationTarget(const std::string& key) {
  for (const auto& [name, target] : calibrationTargetChoices())
    if (name == key) return target;
  return std::nullopt;
}

double table3Target(const PublishedParticipant& published, CalibrationTarget column) {
  return column == CalibrationTarget::kMeasured ? published.table3Measured : published.table3Model;
}

void checkCalibratable(const Participant& p) {
  if (p.drive == SwingDrive::kThighKinematics)
    throw InputError(p.path + ": drive: thigh_kinematics: the measured thigh drives " + p.name +
                     "'s swing, so there is no hip moment time scale to calibrate (with any --target); calibrate a "
                     "participant with drive: hip_moment");
}

CalibrationResult calibrateHipTimeScale(const SwingSetup& base, double target, const SwingOptions& swingOptions,
                                        const CalibrationOptions& options) {
  checkCalibratable(base.participant);
  SwingOptions fast = swingOptions;
  fast.recordTrajectory = false;
  SwingSetup setup = base;
  setup.lowering = 0;
  CalibrationResult r;
  // Geometric scan: swing time must rise with the time scale wherever a swing ends.
  const double ratio = std::pow(options.maxScale / options.minScale, 1.0 / (options.scanPoints - 1));
  for (int i = 0; i < options.scanPoints; ++i) {
    const double s = options.minScale * std::pow(ratio, i);
    r.scanScales.push_back(s);
    r.scanSwingTimes.push_back(swingTimeAt(setup, s, fast));
  }
  int bracket = -1;
  for (int i = 0; i + 1 < options.scanPoints; ++i) {
    const double a = r.scanSwingTimes[static_cast<std::size_t>(i)],
                 b = r.scanSwingTimes[static_cast<std::size_t>(i) + 1];
    if (std::isnan(a) || std::isnan(b)) continue;
    if (!(b > a)) {
      throw RunError(setup.participant.name + ": swing time is not monotonic in the hip-moment time scale between " +
                     formatNumber(r.scanScales[static_cast<std::size_t>(i)]) + " and " +
                     formatNumber(r.scanScales[static_cast<std::size_t>(i) + 1]) + " (" + formatNumber(a) + " s, " +
                     formatNumber(b) + " s): the calibration would not be unique");
    }
    if (a <= target && target <= b) bracket = i;
  }
  if (bracket < 0) {
    throw RunError(setup.participant.name + ": target swing time " + formatNumber(target) +
                   " s is outside what hip-moment time scales " + formatNumber(options.minScale) + ".." +
                   formatNumber(options.maxScale) + " reach (change the profile shape or the range)");
  }
  // Bisection on log(scale): robust, and the scan proved monotonicity in the bracket.
  double lo = r.scanScales[static_cast<std::size_t>(bracket)], hi = r.scanScales[static_cast<std::size_t>(bracket) + 1];
  double mid = lo, t = 0;
  r.swings = options.scanPoints;
  for (int it = 0; it < 60; ++it) {
    mid = std::sqrt(lo * hi);
    t = swingTimeAt(setup, mid, fast);
    ++r.swings;
    if (std::fabs(t - target) < options.timeTolerance) break;
    if (t < target)
      lo = mid;
    else
      hi = mid;
  }
  r.timeScale = mid;
  r.swingTime = t;
  const double a = r.scanSwingTimes[static_cast<std::size_t>(bracket)],
               b = r.scanSwingTimes[static_cast<std::size_t>(bracket) + 1];
  r.swingTimePerScale =
      (b - a) / (r.scanScales[static_cast<std::size_t>(bracket) + 1] - r.scanScales[static_cast<std::size_t>(bracket)]);
  return r;
}

CalibrationResult calibrateHipTimeScaleNear(const SwingSetup& base, double target, double start,
                                            const SwingOptions& swingOptions, const CalibrationOptions& options) {
  if (base.participant.drive == SwingDrive::kThighKinematics ||
      !(start >= options.minScale && start <= options.maxScale))
    return calibrateHipTimeScale(base, target, swingOptions, options);
  SwingOptions fast = swingOptions;
  fast.recordTrajectory = false;
  SwingSetup setup = base;
  setup.lowering = 0;
  double s0 = start, t0 = swingTimeAt(setup, s0, fast);
  if (!std::isfinite(t0) || !(t0 > 0)) return calibrateHipTimeScale(base, target, swingOptions, options);
  // First step: swing time roughly proportional to the time scale.
  double s1 = s0 * target / t0;
  if (std::fabs(s1 - s0) < 1e-9 * s0) s1 = s0 * (1 + 1e-4);  // already there: one more swing for the slope
  for (int it = 0; it < 8; ++it) {
    if (!(s1 >= options.minScale && s1 <= options.maxScale)) break;
    const double t1 = swingTimeAt(setup, s1, fast);
    if (!std::isfinite(t1)) break;
    if (std::fabs(t1 - target) < options.timeTolerance) {
      CalibrationResult r;
      r.timeScale = s1;
      r.swingTime = t1;
      r.swingTimePerScale = (t1 - t0) / (s1 - s0);
      if (!(r.swingTimePerScale > 0)) break;  // not monotonic here: let the scan decide
      return r;
    }
    const double slope = (t1 - t0) / (s1 - s0);
    if (!(slope > 0) || !std::isfinite(slope)) break;
    s0 = s1;
    t0 = t1;
    s1 = s1 + (target - t1) / slope;
  }
  return calibrateHipTimeScale(base, target, swingOptions, options);
}

}  // namespace swingsim
