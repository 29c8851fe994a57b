#pragma once
// How sure is the optimum (docs/uncertainty.md): the knee-axis sweep re-run under the
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
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "sweep/sweep.h"
#include "sweep/sweep_assumptions.h"

namespace swingsim {

/// The most Monte Carlo samples a study or `--uncertainty` may ask for: far beyond what a
/// 5-95 % interval needs; the Burkett study would run for hours (about 0.3 s per sample on
/// 2 cores).
constexpr int kMaxUncertaintySamples = 100000;

/// What to run.
struct UncertaintyOptions {
  int samples = 0;          ///< Monte Carlo samples, >= 1 (0: sensitivity only)
  std::uint64_t seed = 1;   ///< std::mt19937_64 seed
  bool sensitivity = true;  ///< also the one-at-a-time runs (2 per assumption)
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
/// Sets `s.best` to the fastest finite swing time (ties within 1e-12 s keep the smaller
/// lowering), -1 if none ended.
void pickBest(LoweringSweepSummary& s);

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
  /// With a sound-limb swing time (symmetry.given): the nominal run's symmetry lowering
  /// (sweep_symmetry.h), its 5-95 % interval over the samples with a swing end (each
  /// sample's crossing, or its closest point where it has none), and how many of those
  /// samples do not reach the sound limb's time.
  SymmetryLowering symmetry;
  Interval symmetryLowering;
  int symmetryNotReached = 0;
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

/// One lowering sweep of the analysis: one participant under one set of assumption values.
struct UncertaintyRun {
  enum class Kind { kNominal, kLow, kHigh, kSample };
  std::size_t participant = 0;  ///< index in the study
  Kind kind = Kind::kNominal;
  std::size_t assumption = 0;     ///< kLow, kHigh: index in sweepAssumptions()
  std::size_t sample = 0;         ///< kSample: Monte Carlo sample index
  std::vector<double> lowerings;  ///< m, the study's grid up to this variant's cap
  std::size_t firstSwing = 0;     ///< index of its first lowering in the plan's swing order
};

/// One swing of an analysis, ready to run: the variant its run sweeps, that variant's knee
/// law and its participant adapted to the lowering (calcAdaptedParticipant).
struct PlannedSwing {
  const UncertaintyRun* run = nullptr;
  double lowering = 0;  ///< m
  SweepVariant variant;
  std::shared_ptr<const KneeLawSum> knee;
  Participant participant;
  /// The swing's setup; it shares `knee`.
  SwingSetup makeSetup() const;
};

/// Every swing of an analysis in one fixed order, the swing index that shards slice and
/// partial result files record: first the sensitivity runs (per participant in study order:
/// nominal, then low and high of each applicable assumption), then the Monte Carlo sample by
/// sample (within a sample the participants in study order), each run's lowerings in grid
/// order. Holds the draws and the nominal variants only: a swing's variant and knee law are
/// rebuilt when it runs, so memory grows with the swings only by their lowering and time
/// (tens of bytes a swing, about 2 MB for 84,000).
struct UncertaintyPlan {
  UncertaintyOptions options;
  std::vector<std::vector<double>> draws;            ///< [sample][assumption], u in [0, 1)
  std::vector<SweepVariant> nominals;                ///< per participant
  std::vector<std::vector<AssumptionRange>> ranges;  ///< [participant][assumption]
  std::vector<UncertaintyRun> runs;                  ///< in swing order
  std::size_t swingCount = 0;                        ///< sum of the runs' lowerings
  std::size_t sensitivitySwings = 0;                 ///< the swings before the first sample's
  /// The variant a run sweeps (nominal with the run's assumption values applied).
  SweepVariant makeVariant(const UncertaintyRun& run) const;
  /// The run holding swing `swing` (< swingCount).
  const UncertaintyRun& findRun(std::size_t swing) const;
  /// Swing `swing` (< swingCount), built to run. Throws std::invalid_argument if its knee
  /// law cannot be built (planSweepUncertainty checked every run's).
  PlannedSwing makeSwing(std::size_t swing) const;
};

/// Builds the plan: the draws, each run's variant (to check that its knee law can be built
/// and to find its lowering grid). Throws RunError if an assumption's value makes an
/// unusable knee law or a knee model was not loaded.
UncertaintyPlan planSweepUncertainty(const SweepStudy& study, const UncertaintyOptions& options);

/// Swing times of a plan's swings by swing index, and which of them have run.
struct UncertaintySwingTimes {
  std::vector<double> swingTimes;  ///< s; NaN where no swing ended or not run
  std::vector<char> finished;      ///< 1 where the swing has run
  /// `count` swings, none run.
  static UncertaintySwingTimes makeEmpty(std::size_t count);
  std::size_t countFinished() const;
};

/// Swings [first, last) of `count` as shard `index` of `shards` takes them: contiguous
/// slices in swing order, sizes differing by at most one (0 <= index < shards).
std::pair<std::size_t, std::size_t> calcShardSwings(std::size_t count, int index, int shards);

/// How a run of swings reports and stops.
struct UncertaintyRunControl {
  /// progress(done, total) over the swings this call runs; from the calling thread only.
  std::function<void(int, int)> progress;
  const volatile bool* stopFlag = nullptr;  ///< when set (SIGINT), no further swing starts
  /// Stop as if the stop flag were set once this many swings have finished in this call;
  /// negative = never. Lets a test interrupt a run at a known point.
  long stopAfterSwings = -1;
};

/// Runs the swings in [first, last) not yet `finished` in `times` on `jobs` threads (0 = all
/// cores), storing each swing time and marking it finished. Returns true if all of them ran
/// (false: stopped early; what finished is kept).
bool runUncertaintySwings(const UncertaintyPlan& plan, std::size_t first, std::size_t last,
                          UncertaintySwingTimes& times, int jobs, const UncertaintyRunControl& control = {});

/// Monte Carlo samples whose swings (every participant's) have all run.
int countFinishedSamples(const UncertaintyPlan& plan, const UncertaintySwingTimes& times);

/// The results from the swing times (`interrupted` set if any swing has not run).
UncertaintyResults assembleUncertaintyResults(const SweepStudy& study, const UncertaintyPlan& plan,
                                              const UncertaintySwingTimes& times);

/// Runs the sensitivity and the Monte Carlo on `jobs` threads (0 = all cores): plan, run
/// every swing, assemble. `progress(done, total)` is called from the calling thread only; a
/// stop flag ends it early with `interrupted` set. Throws RunError if a knee model was not
/// loaded.
UncertaintyResults runSweepUncertainty(const SweepStudy& study, const UncertaintyOptions& options, int jobs,
                                       const std::function<void(int, int)>& progress = {},
                                       const volatile bool* stopFlag = nullptr);

}  // namespace swingsim
