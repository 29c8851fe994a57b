#pragma once
// How sure is the optimum (issue 15 item 4): the knee-axis sweep re-run under the
// unpublished assumptions of sweep_assumptions.h, one at a time at each end of its range
// (sensitivity) and all together in N Monte Carlo samples (uncertainty). Every run is a
// plain lowering sweep (the study's step grid, no Table 4 extras, no added mass) of one
// participant under one set of assumption values; its result is the fastest lowering and
// its swing time. The hip time scale is not recalibrated per sample (that would cost a
// calibration scan per sample); it is itself one ranged assumption.
//
// Reproducible: all draws are made up front from std::mt19937_64(seed), each uniform in
// [0, 1) as (engine() >> 11) * 2^-53 (53 random bits, the same on every standard library),
// sample by sample in table order; every swing is one job stored by its index, so results
// are identical whatever the number of threads.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "swing/sweep.h"
#include "swing/sweep_assumptions.h"

namespace swingsim {

/// The most Monte Carlo samples a study or `--uncertainty` may ask for: far beyond what a
/// 5-95 % interval needs; the Burkett study would run for hours (about 0.3 s per sample on
/// 2 cores).
constexpr int kMaxUncertaintySamples = 100000;

/// What to run.
struct UncertaintyOptions {
  int samples = 0;         ///< Monte Carlo samples, >= 1 (0: sensitivity only)
  std::uint64_t seed = 1;  ///< std::mt19937_64 seed
  bool sensitivity = true; ///< also the one-at-a-time runs (2 per assumption)
};

/// One participant's lowering sweep under one set of assumption values.
struct LoweringSweepSummary {
  std::vector<double> lowerings;   ///< m, the study's grid up to this variant's cap
  std::vector<double> swingTimes;  ///< s, NaN where no swing ended (failed or not run)
  int best = -1;                   ///< index of the fastest swing, -1 if none ended
  /// Lowering (m) and swing time (s) of the fastest swing; NaN if none ended.
  double calcFastestLowering() const;
  double calcFastestTime() const;
};

/// One assumption at the two ends of its range, the others nominal, for one participant.
struct SensitivityRow {
  std::string assumption;  ///< SweepAssumption::key
  std::string name;        ///< SweepAssumption::name
  std::string unit;
  double lowValue = 0, highValue = 0;
  LoweringSweepSummary low, high;
  /// |fastest lowering at high - at low| (m); +infinity if either has no swing end.
  double calcLoweringEffect() const;
  /// |swing time at high - at low| (s) of the fastest swings; +infinity if either has none.
  double calcTimeEffect() const;
};

/// Median and 5-95 % interval of a sample (linear interpolation between order
/// statistics, Hyndman & Fan 1996 type 7); NaN when there are no values.
struct Interval {
  double median = 0, p05 = 0, p95 = 0;
  int count = 0;  ///< values it was computed from
};
/// The interval of the finite values in `values`.
Interval calcInterval(std::vector<double> values);

struct ParticipantUncertainty {
  std::string name;
  LoweringSweepSummary nominal;  ///< every assumption at the files' value
  /// Sorted by calcLoweringEffect, then calcTimeEffect, largest first; inapplicable
  /// assumptions (a tabulated hip moment's shape) are left out.
  std::vector<SensitivityRow> sensitivity;
  std::vector<LoweringSweepSummary> samples;  ///< Monte Carlo, by sample index
  Interval fastestLowering, fastestTime;      ///< over the samples with a swing end
  int samplesWithoutSwingEnd = 0;             ///< samples where no lowering ended a swing
  /// Swing time per lowering of the nominal grid: 5 %, 50 %, 95 % over the samples that
  /// ended a swing there (NaN where fewer than half did).
  std::vector<double> bandLowerings, bandP05, bandMedian, bandP95;
};

struct UncertaintyResults {
  int samples = 0;
  std::uint64_t seed = 0;
  /// The Monte Carlo draws u in [0, 1): draws[sample][assumption], table order.
  std::vector<std::vector<double>> draws;
  std::vector<ParticipantUncertainty> participants;  ///< study order
  bool interrupted = false;                          ///< a stop flag ended it early
};

/// The Monte Carlo draws: samples x sweepAssumptions().size() uniforms in [0, 1).
std::vector<std::vector<double>> drawUncertaintySamples(int samples, std::uint64_t seed);

/// The variant of `participant` in `study` with every assumption nominal.
SweepVariant makeNominalVariant(const SweepStudy& study, const Participant& participant);

/// Runs the sensitivity and the Monte Carlo on `jobs` threads (0 = all cores).
/// `progress(done, total)` is called from the calling thread only; a stop flag ends it
/// early with `interrupted` set. Throws RunError if a knee model was not loaded.
UncertaintyResults runSweepUncertainty(const SweepStudy& study, const UncertaintyOptions& options, int jobs,
                                       const std::function<void(int, int)>& progress = {},
                                       const volatile bool* stopFlag = nullptr);

}  // namespace swingsim
