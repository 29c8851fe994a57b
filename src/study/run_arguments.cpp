#include "study/run_arguments.h"

#include <cmath>

#include "core/input_error.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim {

std::string WholeNumberRange::check(long long value) const { return value >= min && value <= max ? "" : expected; }

std::string WholeNumberRange::check(double value) const {
  // Compared as doubles first: 1e300 is not cast to long long.
  if (!std::isfinite(value) || value != std::floor(value) || value < static_cast<double>(min) ||
      value > static_cast<double>(max))
    return expected;
  return check(static_cast<long long>(value));
}

const WholeNumberRange& uncertaintySamplesRange() {
  static const WholeNumberRange range{
      1, kMaxUncertaintySamples,
      "expected a whole number of samples from 1 to " + std::to_string(kMaxUncertaintySamples)};
  return range;
}

const WholeNumberRange& uncertaintyOrNoneRange() {
  static const WholeNumberRange range{
      0, kMaxUncertaintySamples,
      "expected 0 (none) or a whole number of samples from 1 to " + std::to_string(kMaxUncertaintySamples)};
  return range;
}

const WholeNumberRange& seedRange() {
  static const WholeNumberRange range{0, kMaxSeed, "expected a seed from 0 to " + std::to_string(kMaxSeed)};
  return range;
}

const WholeNumberRange& jobsRange() {
  static const WholeNumberRange range{0, kMaxJobs, "expected 0 (all cores) or a positive whole number"};
  return range;
}

const WholeNumberRange& maxSwingsRange() {
  static const WholeNumberRange range{1, kMaxMaxSwings, "expected a whole number of swings from 1"};
  return range;
}

const WholeNumberRange& maxRowsRange() {
  static const WholeNumberRange range{1, kMaxMaxSwings, "expected a whole number of rows from 1"};
  return range;
}

std::string checkLowering(double lowering) { return std::isfinite(lowering) ? "" : "expected a number"; }

std::string checkPositive(double value) { return std::isfinite(value) && value > 0 ? "" : "expected a positive value"; }

std::string checkForceThreshold(double thresholdN) {
  return std::isfinite(thresholdN) && thresholdN > 0 ? "" : "expected a positive force";
}

std::string checkKneeSign(double sign) { return sign == 1 || sign == -1 ? "" : "expected +1 or -1"; }

std::string checkKneeFriction(double moment) {
  return std::isfinite(moment) && moment >= 0 ? "" : "expected a moment >= 0 N m";
}

std::string formatArgumentProblem(const std::string& name, const std::string& expected, const std::string& got) {
  return name + ": " + expected + ", got " + got;
}

void applyUncertaintyArguments(SweepStudy& study, std::optional<int> samples, std::optional<int> seed,
                               const UncertaintyArgumentNames& names) {
  if (samples) study.uncertaintySamples = *samples;
  if (!seed) return;
  if (study.uncertaintySamples == 0)
    throw InputError(names.seed + ": sets the seed of the uncertainty analysis, which needs " + names.samples +
                     " or an `uncertainty:` map in " + study.path + " (got " + names.seedGot + " alone)");
  study.uncertaintySeed = *seed;
}

}  // namespace swingsim
