#pragma once
// One knee-axis sweep run, from the loaded study to its written outputs: the one home of the
// main job's sequence, which `swingsim sweep`, `swingsim merge` and Python's `sweep()` call.
//
//   calibrate()            hip time scales to Burkett Table 3, if the study asks (calibrate_to:)
//   sweep()                the plain sweep, then its checks: terminal impact, the calibration
//                          it ran with, the Table 4 validation
//   runUncertainty(path)   how sure the fastest lowering is (uncertainty: map / --uncertainty),
//                          resumable from the partial file at `path`
//   runShard(K, N, out)    one shard of the uncertainty swings into its shard file (no sweep)
//   writeOutputs(out, json) report, CSV, figures and JSON, staged and moved in together
//
// The caller's side is a SweepRunControl: the terminal (progress bars, step lines and tables
// on stderr/stdout, Ctrl-C through a stop flag) or Python (silent, its signals polled).
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "study/uncertainty_swings_file.h"
#include "sweep/measured_validation.h"
#include "sweep/sweep.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim {

/// The data and report files a sweep or a cohort run (and their merge) writes into its
/// output folder (report/sweep_markdown.cpp, report/cohort_report.cpp): an input by one of
/// these names in that folder would be replaced.
inline const std::vector<std::string> kSweepReportFiles = {"sweep.csv", "report.md", "report.html", "cohort.csv"};

/// After the plain sweep: Burkett's bounce and interior optimum (terminal impact check, with
/// `jobs` worker threads, 0 = all cores), the calibration the sweep ran with, and the Table 4
/// validation, all stored in `results`.
void completeSweepResults(const SweepStudy& study, SweepResults& results,
                          const std::vector<ParticipantCalibration>& calibrations, int jobs);

/// The uncertainty analysis's options from the study (samples, seed, with the sensitivity).
UncertaintyOptions makeUncertaintyOptions(const SweepStudy& study);

/// How a run talks to whoever started it.
struct SweepRunControl {
  /// Set from outside (Ctrl-C): no further swing starts, and nothing half-written is left.
  volatile bool* stop = nullptr;
  /// Tests: stop as `stop` would after this many swings of a resumable run (-1: never).
  long stopAfterSwings = -1;
  /// Progress bars and step lines on stderr, tables and the report's path on stdout.
  bool terminal = false;
  /// Called at every progress update, on the thread that started the run (Python checks
  /// its signals here and sets `stop`).
  std::function<void()> poll;

  bool stopped() const { return stop && *stop; }
};

/// The terminal's line before a sweep: its swing count and an estimate of its time on `jobs`
/// threads (0 = all cores), on stderr; InputError if the count is above `maxSwings`, naming
/// the grid's sizes.
void announceSweepGrid(const SweepStudy& study, std::uint64_t maxSwings, int jobs);

/// The output folder: `out` if given, else the study's output_dir, else out/<study name>;
/// the last two checked for writability and length first (checkOutputFolder): InputError.
std::string chooseSweepOutputFolder(const SweepStudy& study, const std::optional<std::string>& out);

/// The file an earlier interrupted run of the same analysis and slice as `file` left at
/// `path`, if any; one from another analysis or slice is an InputError (file, key, expected,
/// found), so a command can refuse it before it runs anything.
std::optional<UncertaintySwingsFile> readResumableSlice(const UncertaintySwingsFile& file, const std::string& path);

class SweepRun {
 public:
  /// `jobs`: worker threads, 0 = all cores.
  SweepRun(SweepStudy study, int jobs, SweepRunControl control);

  const SweepStudy& study() const { return study_; }
  const SweepResults& results() const { return results_; }
  /// The uncertainty analysis's results; nullptr before runUncertainty or takeUncertainty.
  const UncertaintyResults* uncertainty() const { return uncertainty_ ? &*uncertainty_ : nullptr; }

  /// Calibrates the hip time scales if the study asks (`calibrate_to:`), saying so.
  void calibrate();
  /// The plain sweep with its checks; false if stopped (the results then hold what finished).
  bool sweep();
  /// The uncertainty analysis's plan and the file of its whole run; an earlier run's partial
  /// file at `partialPath` ("" = none) from another analysis is refused here, before any
  /// swing. Call before sweep() so that a refusal costs nothing.
  void planUncertainty(const std::string& partialPath);
  /// Runs the analysis planned (its swings not finished yet); false if stopped, the finished
  /// swings then kept in the partial file (if any) for the same command to resume.
  bool runUncertainty();
  /// The identity of the planned analysis (planUncertainty first), which shard and partial
  /// files must match.
  const UncertaintyRunIdentity& uncertaintyRun() const { return file_.run; }
  /// The planned analysis's swing times computed elsewhere (the shards `merge` combines):
  /// runToOutputs assembles them after the plain sweep instead of running the swings.
  void takeUncertaintySwings(UncertaintySwingTimes times) { merged_ = std::move(times); }
  /// Shard K of N of the uncertainty swings into OUT/uncertainty-shard-K-of-N.json. Returns
  /// the exit code.
  int runShard(int index, int count, const std::string& out);
  /// The plain sweep, the analysis if planned (or taken), then the outputs; a stop keeps the
  /// finished rows in OUT/sweep.partial.csv (a merge: nothing) and writes no report.
  /// Returns the exit code.
  int runToOutputs(const std::string& out, const std::optional<std::string>& json);
  /// Stages report, figures and --json, and moves them into `out` together (also removing
  /// an earlier run's sweep.partial.csv and, after an analysis, uncertainty.partial.json); a
  /// stop meanwhile leaves `out` unchanged. Returns the exit code.
  int writeOutputs(const std::string& out, const std::optional<std::string>& json);
  /// `swingsim sweep --json`'s content.
  std::string formatJson() const;

 private:
  /// Runs the swings of `file`'s slice not finished yet, after taking those of `earlier` (the
  /// file an interrupted run left at `path`, read once, before any swing); see runUncertainty.
  bool runSlice(UncertaintySwingsFile& file, const std::string& path, const std::string& label,
                const std::optional<UncertaintySwingsFile>& earlier);
  /// After a stop: the finished rows into OUT/sweep.partial.csv, and which did not run.
  void writePartialRows(const std::string& out) const;

  SweepStudy study_;
  int jobs_ = 0;
  SweepRunControl control_;
  std::vector<ParticipantCalibration> calibrations_;
  SweepResults results_;
  std::optional<UncertaintyPlan> plan_;
  UncertaintySwingsFile file_;
  std::string partialPath_;
  std::optional<UncertaintySwingsFile> earlier_;  ///< the partial file found at partialPath_
  std::optional<UncertaintySwingTimes> merged_;
  std::optional<UncertaintyResults> uncertainty_;
};

}  // namespace swingsim
