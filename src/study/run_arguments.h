#pragma once
// The numeric arguments that the command line and Python both take (sweep's samples, seed,
// jobs and --max-swings; simulate's lowering): their ranges and what a refusal says, in one
// place. CLI11's validators (cli/option_checks) and the Python module's argument conversions
// (python/src/python_values) both check against these, so a limit changes here only.
#include <optional>
#include <string>

#include "sweep/sweep.h"

namespace swingsim {

/// The largest uncertainty seed (std::mt19937_64), as a study's `seed:` key takes it.
constexpr long long kMaxSeed = 1000000000;
/// The largest --jobs: the command line's limit of a whole-number option; more threads than
/// swings are never started.
constexpr long long kMaxJobs = 1000000000;
/// The largest --max-swings (the limit itself; a sweep of that many would run for weeks).
constexpr long long kMaxMaxSwings = 1000000000;

/// A whole-number argument's range and what its refusal says is expected.
struct WholeNumberRange {
  long long min = 0;
  long long max = 0;
  std::string expected;  ///< "expected a whole number of samples from 1 to 100000"

  /// "" if `value` is from min to max, else `expected`.
  std::string check(long long value) const;
  /// "" if `value` is a whole number from min to max, else `expected`.
  std::string check(double value) const;
};

/// --uncertainty N / a study's `samples:`: 1 to kMaxUncertaintySamples.
const WholeNumberRange& uncertaintySamplesRange();
/// Python's `uncertainty=`: 0 (none, the study's own map applies) or a count as above.
const WholeNumberRange& uncertaintyOrNoneRange();
/// --seed S: 0 to kMaxSeed.
const WholeNumberRange& seedRange();
/// --jobs N: 0 (all cores) to kMaxJobs.
const WholeNumberRange& jobsRange();
/// --max-swings N: 1 to kMaxMaxSwings.
const WholeNumberRange& maxSwingsRange();
/// diagnose --max-rows N: 1 to kMaxMaxSwings rows of measured data.
const WholeNumberRange& maxRowsRange();

/// "" if `lowering` (knee-axis lowering, m) is a finite number, else what was expected; the
/// swing set-up checks it against the leg (makeSwingSetup).
std::string checkLowering(double lowering);

/// "" if `value` is a finite number > 0 (a mass, kg; a length, m), else what was expected.
std::string checkPositive(double value);
/// swings' vertical-force threshold, N: "" if > 0 and finite.
std::string checkForceThreshold(double thresholdN);
/// swings' knee sign: "" if +1 or -1 (knee flexion = sign * knee_angle).
std::string checkKneeSign(double sign);
/// import-osim's knee friction moment, N m: "" if >= 0 and finite.
std::string checkKneeFriction(double moment);

/// The message of a refused argument: "NAME: EXPECTED, got GOT"
/// ("sweep(): seed: expected a seed from 0 to 1000000000, got -1").
std::string formatArgumentProblem(const std::string& name, const std::string& expected, const std::string& got);

/// How a caller names the uncertainty arguments in its messages.
struct UncertaintyArgumentNames {
  std::string seed;     ///< "--seed" / "sweep(): seed"
  std::string samples;  ///< "--uncertainty N" / "uncertainty=N"
  std::string seedGot;  ///< the seed as given: "--seed 3" / "seed=3"
};

/// Applies the overrides of the study's `uncertainty:` map (nullopt: the study's own), each
/// checked against its range already. A seed with nothing to seed (no samples given and no
/// map in the study) is an InputError naming the seed and the study, before any work.
void applyUncertaintyArguments(SweepStudy& study, std::optional<int> samples, std::optional<int> seed,
                               const UncertaintyArgumentNames& names);

}  // namespace swingsim
