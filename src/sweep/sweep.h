#pragma once
// The knee-axis sweep (Burkett 2004): for each participant, lower the knee axis in fixed
// steps from the standard location and simulate a swing at each step; optionally also
// add a shank mass (Bach 1994) at each step. Runs on a thread pool; results are stored by
// job index, so they are identical whatever the number of threads.
#include <cstdint>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include <map>

#include "model/knee_model.h"
#include "sweep/burkett_published.h"
#include "sweep/calibration.h"
#include "sweep/sweep_symmetry.h"
#include "sweep/swing_time_jumps.h"
#include "swing/swing_simulation.h"

namespace swingsim {

struct SweepStudy {
  std::string path;
  std::string name;
  std::vector<Participant> participants;
  std::string description;
  std::string kneeModelOverride;  ///< resolved path, "" = each participant's own model
  /// A sensitivity study's COM rule for every participant (else each participant's own).
  bool overridesComRule = false;
  ComRule comRule = ComRule::kFixedFromProximal;
  /// Every knee model the participants or the override name, by resolved path (the study
  /// reader loads them; runSweep reads no files).
  std::map<std::string, KneeModel> kneeModels;
  double loweringStep = 0.010;  ///< m
  double loweringMax = 0.200;   ///< m, capped per participant at calcMaxLowering
  /// Added shank masses (kg) and their distances below the knee (m). The sweep always
  /// includes 0 kg; more entries make a lowering x mass x position grid.
  std::vector<double> addedMasses = {0.0};
  std::vector<double> addedMassDistances = {};
  /// Also simulate the lowerings of Burkett Table 4 that are off the step grid (0.125 m,
  /// 0.175 m, ...), up to the participant's physical limit, for the side-by-side table.
  bool includePublishedLowerings = true;
  SwingOptions swing;
  std::string outputDir;  ///< "" = out/<name>
  /// `calibrate_to:` calibrate every Burkett participant's hip time scale before the sweep
  /// (calibrateSweepParticipants), to Table 3's model or measured column; kStored = keep
  /// the files' time scales.
  CalibrationTarget calibrateTo = CalibrationTarget::kStored;
  /// Monte Carlo samples of the uncertainty analysis run after the sweep (`uncertainty:`
  /// in the study, `--uncertainty N`; sweep_uncertainty.h), 0 = none.
  int uncertaintySamples = 0;
  int uncertaintySeed = 1;  ///< std::mt19937_64 seed of its draws, 0 to 1e9
};

/// One simulated (participant, lowering, added mass) point.
struct SweepPoint {
  double lowering = 0;
  bool onGrid = true;  ///< a study step (false: an extra Table 4 lowering, never "fastest")
  AddedMass added;
  bool ok = false;      ///< the swing ended
  bool ran = false;     ///< the swing was simulated (false: an interrupted sweep never reached it)
  std::string failure;  ///< why not, if !ok ("not run (interrupted)" if !ran)
  SwingResult result;
};

struct ParticipantSweep {
  std::string name;
  /// Burkett 2004's published rows for this participant (Tables 3 and 4), looked up once by
  /// name when the sweep runs; nullptr if he is not one of Burkett's.
  const PublishedParticipant* published = nullptr;
  double loweringCap = 0;              ///< largest lowering simulated, m
  std::string capNote;                 ///< non-empty if the study's maximum was capped
  std::vector<SweepPoint> points;      ///< the plain sweep (no added mass), by lowering
  std::vector<SweepPoint> massPoints;  ///< the added-mass grid (may be empty)
  /// The jumps of the swing time between neighbouring grid lowerings of `points`, each
  /// narrowed to kJumpBracket (swing_time_jumps.h), by lowering.
  std::vector<SwingTimeJump> jumps;
  /// Index into points of the fastest swing, -1 if none ended.
  int best = -1;
  int bestWithMass = -1;  ///< index into massPoints, -1 if none
  /// The lowering whose grid swing time is closest to the participant's sound limb
  /// (Participant::soundLimbSwingTime; symmetry.given false without one), over the same
  /// points as `best` and the two sides of each jump, interpolated only inside one piece.
  SymmetryLowering symmetry;
};

// Burkett 2004's terminal-impact findings on a sweep (sweep/terminal_impact.h).
/// One swing with its impact bookkeeping (SwingOptions::trackImpactEnergy).
struct TrackedImpactSwing {
  double lowering = 0;  ///< m
  bool ok = false;
  std::string failure;
  SwingResult result;
};

struct TerminalImpactCheck {
  std::string participant;
  double frictionMoment = 0;  ///< N m, the participant's Tc
  /// At the standard location and at the largest lowering simulated.
  std::vector<TrackedImpactSwing> tracked;
  /// The grid lowerings (m) where the knee bounces, as simulated and without friction.
  std::vector<double> bounceLowerings, bounceLoweringsWithoutFriction;
  /// Fastest grid lowering (m) and its swing time (s) without friction; NaN if none ended.
  double fastestWithoutFriction = 0, fastestTimeWithoutFriction = 0;
  bool interiorOptimum = false;  ///< the fastest lowering is below the largest
  bool interiorOptimumWithoutFriction = false;
  /// One sentence per finding: reproduced or not, and which assumption stops it.
  std::vector<std::string> findings;
};

/// One participant's calibration before a sweep (SweepStudy::calibrateTo).
struct ParticipantCalibration {
  std::string participant;
  double targetTime = 0;  ///< s
  double timeScale = 0;   ///< the calibrated scale (the stored one if !ok)
  bool ok = false;
  std::string failure;  ///< why not (a target no time scale reaches)
};

/// Burkett Table 4 as a validation set for one participant: measured prosthetic swing
/// times beside ours and Burkett's model (measured_validation.h).
struct Table4Row {
  double lowering = 0;             ///< m
  double measured = 0, model = 0;  ///< s, Burkett's measured mean and model prediction
  double ours = 0;                 ///< s, this sweep (NaN: not simulated or no swing end)
  double oursLeaveOneOut = 0;      ///< s, with the other participants' mean time scale (NaN: not run)
};

struct Table4Validation {
  std::string participant;
  bool calibrated = false;  ///< the time scale came from this run's calibration to the target
  std::vector<Table4Row> rows;
  /// RMS of (prediction - measured) over the rows with a prediction, s (NaN: none).
  double rmseOurs = 0, rmseModel = 0, rmseLeaveOneOut = 0;
  /// Shortening from the standard location to the largest Table 4 lowering both have, s
  /// (positive: faster when lowered).
  double shorteningMeasured = 0, shorteningOurs = 0, shorteningModel = 0;
};

struct SweepResults {
  std::string study;
  std::vector<ParticipantSweep> participants;
  /// checkTerminalImpact's findings, by participant (empty unless it ran).
  std::vector<TerminalImpactCheck> terminalImpact;
  /// The calibration done before the sweep (empty: the stored time scales were used).
  CalibrationTarget calibratedTo = CalibrationTarget::kStored;
  std::vector<ParticipantCalibration> calibrations;
  /// Table 4 as validation, per Burkett participant (empty unless validateOnTable4 ran).
  std::vector<Table4Validation> table4;
};

/// Path of the knee model participant `p` uses in `study` (the study's override, else the
/// participant's own).
std::string studyKneeModelPath(const SweepStudy& study, const Participant& p);
/// That knee model, as the study reader loaded it; throws RunError if it was not loaded.
const KneeModel& findStudyKneeModel(const SweepStudy& study, const Participant& p);

/// Swings of the plain sweep (runSweep): per participant, each lowering of sweepLowerings
/// once without added mass and once per added mass above 0 kg and distance that fits on the
/// shortened shank. Counted without listing them, so a grid of billions is counted at once.
std::uint64_t countSweepSwings(const SweepStudy& study);

/// Largest plain sweep run unless the user raises the limit (`sweep --max-swings N`): about
/// 230 times the Burkett study (435 swings), some 10 min on one core at the measured 6 ms a
/// swing (docs/robustness.md, "Large runs"); a grid of millions of swings (long added-mass
/// lists) would run for hours to days.
constexpr std::uint64_t kDefaultMaxSweepSwings = 100000;

/// Starts up to `threads` threads running `worker`. A thread that cannot start (std::thread
/// throws std::system_error under a memory or process limit) ends the starting with a
/// message on stderr ("could start only N of M worker threads"): the threads started are
/// returned, possibly none (then the caller runs `worker` itself).
std::vector<std::thread> startWorkerThreads(int threads, const std::function<void()>& worker);

/// Runs runOne(0) .. runOne(total - 1) on `jobs` worker threads (0 = all cores), each index
/// once, in no set order (results stored by index are the same whatever the thread count).
/// progress(done, total) is called from the calling thread about every 0.1 s and at the end.
/// A stop flag (SIGINT) ends it early. Fewer threads, down to the calling thread alone, run
/// the jobs when threads cannot start (startWorkerThreads) or an address-space limit
/// (ulimit -v) leaves room for fewer (each says so on stderr). An exception a job throws
/// (std::bad_alloc included) stops the workers after their current job and is rethrown
/// here, never std::terminate. Returns how many ran.
int runParallelJobs(int total, int jobs, const std::function<void(int)>& runOne,
                    const std::function<void(int, int)>& progress = {}, const volatile bool* stopFlag = nullptr);

/// Lowerings for a participant: 0, step, 2 step, ... up to min(max, cap), plus the
/// Table 4 lowerings if requested, sorted.
std::vector<double> sweepLowerings(const SweepStudy& study, const Participant& p);
/// The on-grid lowerings of sweepLowerings for a participant (m): 0, step, 2 step, ... up to
/// min(max, cap), without the Table 4 extras (they are never the "fastest" in runSweep
/// either); the lowerings each uncertainty run and each cohort participant sweeps.
std::vector<double> sweepGridLowerings(const SweepStudy& study, const Participant& p);

/// Runs the sweep on `jobs` threads (0 = all cores). `progress(done, total)` is called
/// from the calling thread only. A stop flag (SIGINT) ends it early: unfinished points
/// then have ran = ok = false and failure = "not run (interrupted)".
SweepResults runSweep(const SweepStudy& study, int jobs, const std::function<void(int, int)>& progress = {},
                      const volatile bool* stopFlag = nullptr);

}  // namespace swingsim
