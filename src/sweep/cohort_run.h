#pragma once
// A cohort study's runs (docs/cohort.md): each drawn participant's hip time scale is
// calibrated to its drawn swing time (calibrateHipTimeScale, as `calibrate_to:` does for
// Burkett's four), then its knee axis is lowered over the study's grid (the plain sweep's
// lowerings, no Table 4 extras, no added mass) and its fastest lowering and the time it gains
// are found. One participant is one job, stored by index, so results are the same whatever
// the number of threads or shards. The summary ranks the participant properties by how well
// they predict the time gained (Spearman's rho with a Fisher-z interval).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "numerics/rank_correlation.h"
#include "sweep/cohort_sampling.h"
#include "sweep/sweep.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim {

/// The most participants a cohort study may draw (about 0.1 s of swings each on one core).
constexpr int kMaxCohortParticipants = 100000;

/// A cohort, drawn and ready to run.
struct Cohort {
  /// Name, path, lowering grid, integrator, knee models, output folder; `participants` are
  /// the drawn ones (their hip time scales still the template's until calibrated).
  SweepStudy study;
  std::string templatePath;                       ///< the participant file every drawn participant starts from
  int count = 0;                                  ///< participants
  std::uint64_t seed = 1;                         ///< std::mt19937_64 seed of the draws
  std::vector<CohortDistribution> distributions;  ///< one per cohortProperties() row
  std::vector<std::vector<double>> values;        ///< [participant][property]
  /// s, participant i's drawn swing time (its `swing_time_s` value).
  double targetSwingTime(std::size_t participant) const;
};

/// Draws the participants of `cohort` (count, seed, distributions and study set; the study's
/// participants are replaced by `templ` with the drawn values). Throws InputError if a drawn
/// leg is impossible.
void drawCohortParticipants(Cohort& cohort, const Participant& templ);

/// One participant's calibration and lowering sweep.
struct CohortParticipantResult {
  bool ran = false;            ///< computed (false: not yet, in a partial or shard file)
  bool calibrated = false;     ///< a time scale reaches the target swing time
  std::string failure;         ///< why not calibrated ("" if calibrated)
  double timeScale = 0;        ///< the calibrated hip time scale (NaN if not calibrated)
  LoweringSweepSummary sweep;  ///< the grid and its swing times (empty if not calibrated)
  int calibrationSwings = 0;   ///< swings the calibration simulated (its scan, if it failed)
  /// s, swing time at the standard location (lowering 0); NaN if none.
  double calcStandardTime() const;
  /// s, standard-location swing time minus the fastest one (>= 0); NaN if either is missing.
  double calcTimeGained() const;
};

/// Calibrates participant `index` of `cohort` and sweeps its lowerings.
CohortParticipantResult runCohortParticipant(const Cohort& cohort, std::size_t index);

/// How a run of participants reports and stops (as UncertaintyRunControl).
struct CohortRunControl {
  std::function<void(int, int)> progress;   ///< (done, total) from the calling thread only
  const volatile bool* stopFlag = nullptr;  ///< when set (SIGINT), no further participant starts
  long stopAfterParticipants = -1;          ///< stop once this many finished in this call (tests)
};

/// Runs participants [first, last) of `cohort` that have not run in `results` (sized
/// cohort.count) on `jobs` threads (0 = all cores). Returns true if all of them ran.
bool runCohortParticipants(const Cohort& cohort, std::size_t first, std::size_t last,
                           std::vector<CohortParticipantResult>& results, int jobs,
                           const CohortRunControl& control = {});

/// A property (drawn or derived) of every participant, as a predictor of the gain.
struct CohortPredictor {
  std::string key, what;
  std::vector<double> values;  ///< per participant (NaN where undefined)
  RankCorrelation withGain;    ///< Spearman's rho with the time gained, 95 % Fisher-z interval
};

struct CohortSummary {
  int participants = 0, calibrated = 0;                  ///< how many were drawn, and calibrated
  std::vector<double> fastestLowering, timeGained;       ///< per participant, m and s (NaN if none)
  Interval fastestLoweringInterval, timeGainedInterval;  ///< median and 5-95 % over those with one
  /// Every drawn property, then body mass, thigh, shank and foot mass, the shank + foot
  /// inertia about the knee and the calibrated time scale; sorted by |rho| with the gain,
  /// largest first (undefined rho last).
  std::vector<CohortPredictor> predictors;
};

/// The summary of a complete run (every result ran).
CohortSummary summarizeCohort(const Cohort& cohort, const std::vector<CohortParticipantResult>& results);

}  // namespace swingsim
