#pragma once
// The steps `swingsim sweep` and `swingsim merge` share, so that a merge of shards prints and
// writes what one sweep run does: Ctrl-C handling, the calibration before the sweep, the
// plain sweep with its checks, the uncertainty swings with resume and partial results, and
// the staged write of the report and JSON.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "study/sweep_run.h"  // makeUncertaintyOptions, completeSweepResults
#include "study/uncertainty_swings_file.h"
#include "sweep/sweep.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim::cli {

/// Set by SIGINT or SIGTERM while catchInterrupts() is in force: no further swing starts;
/// in the write phase the staged files are discarded rather than left half-written.
extern volatile bool gInterrupted;
void catchInterrupts();
void restoreInterrupts();

/// Test hook: SWINGSIM_TEST_STOP_AFTER_SWINGS=N stops a resumable run after N swings (a
/// cohort run: N participants), as Ctrl-C would (the CLI tests of interrupted and resumed
/// runs; not an option, since no user needs it); -1 if unset. Throws InputError if not a
/// whole number.
long stopAfterSwingsForTests();

/// Prints the plain sweep's swing count and an estimate of its time on `jobs` threads (0 =
/// all cores) to stderr, before anything runs; throws InputError if the count is above
/// `maxSwings` (--max-swings, default kDefaultMaxSweepSwings), naming the grid's sizes.
void announceSweepGrid(const SweepStudy& study, std::uint64_t maxSwings, int jobs);

/// `--max-swings N`: the largest plain sweep to run (default kDefaultMaxSweepSwings).
void addMaxSwingsOption(CLI::App* sub, long long& maxSwings);

/// The output folder: `out` if given, else the study's output_dir, else out/<study name>;
/// the last two checked for writability and length first (checkOutputFolder): InputError.
std::string chooseSweepOutputFolder(const SweepStudy& study, const std::optional<std::string>& out);

/// Calibrates the hip time scales if the study asks (`calibrate_to:`), saying so on stderr.
std::vector<ParticipantCalibration> calibrateForSweep(SweepStudy& study);

/// The plain sweep with a progress bar, then (unless interrupted) the terminal impact check
/// and the Table 4 validation.
SweepResults runPlainSweep(const SweepStudy& study, const std::vector<ParticipantCalibration>& calibrations, int jobs);

/// The file an earlier interrupted run of the same analysis and slice as `file` left at
/// `path`, if any; one from another analysis or slice is an InputError (file, key, expected,
/// found), so a command can refuse it before it runs anything.
std::optional<UncertaintySwingsFile> readResumableSlice(const UncertaintySwingsFile& file, const std::string& path);

/// Runs the swings of `file`'s slice ([first, last) of `plan`) that are not finished yet,
/// after taking those an earlier interrupted run of the same analysis left in `path` (a
/// file there from another analysis is an InputError: file, key, expected, found). On an
/// interrupt (Ctrl-C, or SWINGSIM_TEST_STOP_AFTER_SWINGS swings run, for tests) the finished
/// swings are written to `path` atomically, marked partial, and false is returned. `label`
/// names the progress line ("uncertainty burkett2004").
bool runUncertaintySlice(const UncertaintyPlan& plan, UncertaintySwingsFile& file, const std::string& path,
                         const std::string& label, int jobs);

/// Stages report, figures and --json, and moves them into `out` together (also removing an
/// earlier run's sweep.partial.csv, and with `uncertainty` its uncertainty.partial.json);
/// Ctrl-C meanwhile leaves `out` unchanged. Prints the
/// report's path. Returns the exit code.
int writeSweepOutputs(const SweepStudy& study, const SweepResults& results, const UncertaintyResults* uncertainty,
                      const std::string& out, const std::optional<std::string>& json);

}  // namespace swingsim::cli
