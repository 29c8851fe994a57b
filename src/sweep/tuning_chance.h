#pragma once
// The chance that a tuned setting meets every hard limit of its study when the sweep's
// unpublished assumptions (sweep/sweep_assumptions.h: the hip moment's shape and timing, the
// thigh target, the knee friction, the settle dwell, the stop, the integrator's accuracy)
// take any value in their plausible ranges: a Monte Carlo over the same table and the same
// draws (drawUncertaintySamples) as the sweep's uncertainty analysis. A tuning study asks for
// it with `uncertainty: {samples: N, seed: S}` (docs/tuning.md).
#include <cstdint>
#include <string>
#include <vector>

#include "model/knee_model.h"
#include "model/leg_parameters.h"
#include "sweep/knee_tuning.h"
#include "swing/swing_simulation.h"

namespace swingsim {

struct TuningChanceOptions {
  int samples = 0;         ///< Monte Carlo draws; 0: not asked for
  std::uint64_t seed = 1;  ///< of the draws
};

/// The tuned setting the chance is of: the participant as loaded, the tuned knee, lowering
/// and added mass, and the swing options the tuning used.
struct TunedLeg {
  Participant participant;
  KneeModel knee;
  double lowering = 0;  ///< m
  AddedMass added;
  SwingOptions options;
};

struct TuningChance {
  bool ran = false;
  TuningChanceOptions options;
  int met = 0;     ///< samples that meet every hard limit
  int failed = 0;  ///< samples whose swing could not run (they meet nothing)
  /// Wilson score 95 % interval of the chance (Wilson 1927, J Am Stat Assoc 22:209).
  double low = 0, high = 0;
  /// Per target, in the study's order: the samples that miss it (hard limits; 0 for a soft
  /// target).
  std::vector<int> misses;
  /// The nominal draw (every assumption at the files' value): the tuned swing itself.
  double nominalSwingTime = 0;  ///< s
  /// One sentence: "meets every hard limit in 187 of 200 samples: 94 % (95 % CI 89-96 %);
  /// missed most: swing_time_s (13 samples)".
  std::string verdict;
  double chance() const { return options.samples > 0 ? double(met) / options.samples : 0; }
};

/// The Wilson score 95 % interval of `k` successes in `n` trials, as fractions.
std::pair<double, double> calcWilsonInterval(int k, int n);

/// Runs options.samples swings of `leg` (on `jobs` threads, 0: all cores), each with every
/// assumption of sweepAssumptions() at its drawn value, and counts those meeting every hard
/// limit of `targets`. A stop flag ends it early (ran false).
TuningChance calcTuningChance(const TunedLeg& leg, const std::vector<TuningTarget>& targets,
                              const TuningChanceOptions& options, int jobs, const volatile bool* stop = nullptr);

}  // namespace swingsim
