#include "cli/sweep_steps.h"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <thread>

#include "core/input_error.h"
#include "cli/command.h"
#include "cli/option_checks.h"
#include "core/output_files.h"
#include "core/output_paths.h"
#include "core/progress_reporter.h"
#include "report/sweep_report.h"
#include "study/sweep_run.h"
#include "sweep/measured_validation.h"

namespace swingsim::cli {

volatile bool gInterrupted = false;

namespace {

extern "C" void onInterrupt(int) { gInterrupted = true; }

}  // namespace

long stopAfterSwingsForTests() {
  const char* v = std::getenv("SWINGSIM_TEST_STOP_AFTER_SWINGS");
  if (!v || !*v) return -1;
  char* end = nullptr;
  const long n = std::strtol(v, &end, 10);
  if (*end != '\0' || n < 0)
    throw InputError(std::string("SWINGSIM_TEST_STOP_AFTER_SWINGS: expected a whole number of swings, found \"") + v + "\"");
  return n;
}

void catchInterrupts() {
  std::signal(SIGINT, onInterrupt);
  std::signal(SIGTERM, onInterrupt);
}

void restoreInterrupts() {
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}

void addMaxSwingsOption(CLI::App* sub, long long& maxSwings) {
  sub->add_option("--max-swings", maxSwings,
                  "refuse a plain sweep of more swings than this (default " + std::to_string(kDefaultMaxSweepSwings) +
                      "; the count and a time estimate are printed before it starts)")
      ->type_name("N")
      ->check(wholeNumberFrom(1, "expected a whole number of swings from 1"));
}

void announceSweepGrid(const SweepStudy& study, std::uint64_t maxSwings, int jobs) {
  // Seconds a sweep swing takes on one core, measured (docs/robustness.md, "Large grids":
  // 435 swings of `swingsim sweep studies/burkett2004.yaml --jobs 1` in 2.7 s); a swing with
  // a stiff knee or a tight accuracy can take several times longer: a rough estimate.
  constexpr double kSecondsPerSwing = 0.006;
  const std::uint64_t swings = countSweepSwings(study);
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const double threads = static_cast<double>(
      std::max<std::uint64_t>(1, std::min<std::uint64_t>(jobs > 0 ? static_cast<std::uint64_t>(jobs) : cores, swings)));
  const double seconds = static_cast<double>(swings) * kSecondsPerSwing / std::min(threads, static_cast<double>(cores));
  char estimate[64];
  if (seconds < 120)
    std::snprintf(estimate, sizeof estimate, "%.0f s", std::ceil(seconds));
  else if (seconds < 7200)
    std::snprintf(estimate, sizeof estimate, "%.0f min", std::ceil(seconds / 60));
  else
    std::snprintf(estimate, sizeof estimate, "%.3g hours", seconds / 3600);
  const std::size_t people = study.participants.size();
  const auto masses = std::count_if(study.addedMasses.begin(), study.addedMasses.end(), [](double m) { return m > 0; });
  const std::string grid =
      std::to_string(people) + (people == 1 ? " participant" : " participants") +
      (masses == 0 ? std::string(", no added mass")
                   : ", " + std::to_string(masses) + " added masses above 0 kg x " +
                         std::to_string(study.addedMassDistances.size()) + " distances");
  std::fprintf(stderr, "sweep %s: %llu swings (%s), about %s on %d threads\n", study.name.c_str(),
               static_cast<unsigned long long>(swings), grid.c_str(), estimate, static_cast<int>(threads));
  if (swings > maxSwings)
    throw InputError(study.path + ": the sweep has " + std::to_string(swings) + " swings (" + grid + "; about " +
                     estimate + "), more than the limit of " + std::to_string(maxSwings) +
                     ": shorten the added_mass lists or the lowering grid, or raise the limit with --max-swings " +
                     std::to_string(swings) + " if you mean it");
}

std::string chooseSweepOutputFolder(const SweepStudy& study, const std::optional<std::string>& out) {
  if (out) return *out;  // checked while parsing
  if (study.outputDir.empty()) return chooseStudyOutputFolder(out, study.name, study.path);
  checkOutputFolder(study.outputDir, study.path + ": output_dir");
  return study.outputDir;
}

std::vector<ParticipantCalibration> calibrateForSweep(SweepStudy& study) {
  if (study.calibrateTo == CalibrationTarget::kStored) return {};
  std::fprintf(stderr, "sweep %s: calibrating the hip time scales to Burkett Table 3 (%s)\n", study.name.c_str(),
               calibrationTargetKey(study.calibrateTo));
  std::vector<ParticipantCalibration> calibrations = calibrateSweepParticipants(study);
  for (const auto& c : calibrations)
    std::fprintf(stderr, "sweep %s: %s: %s\n", study.name.c_str(), c.participant.c_str(),
                 c.ok ? ("time scale " + formatNumber(c.timeScale) + " for " + formatNumber(c.targetTime) + " s").c_str()
                      : c.failure.c_str());
  return calibrations;
}

SweepResults runPlainSweep(const SweepStudy& study, const std::vector<ParticipantCalibration>& calibrations, int jobs) {
  SweepResults results = [&] {
    // Scoped: an interrupted run's bar is ended before any message after it.
    ProgressReporter progress("sweep " + study.name, "swings");
    progress.note(std::to_string(study.participants.size()) + " participants (" + study.path + ")");
    return runSweep(study, jobs, [&](int done, int total) { progress.update(done, total); }, &gInterrupted);
  }();
  if (!gInterrupted) {
    // Burkett's bounce and interior optimum, checked (report section "Terminal impact").
    std::fprintf(stderr, "sweep %s: terminal impact check: impact bookkeeping and a friction-free sweep per participant\n",
                 study.name.c_str());
    completeSweepResults(study, results, calibrations, jobs);
  }
  return results;
}

std::optional<UncertaintySwingsFile> readResumableSlice(const UncertaintySwingsFile& file, const std::string& path) {
  if (!std::filesystem::exists(path)) return std::nullopt;
  UncertaintySwingsFile earlier = readUncertaintySwingsFile(path);
  checkSameUncertaintyRun(file.run, earlier, "this run");
  auto shardOf = [](const UncertaintySwingsFile& f) {
    return f.sharded ? std::to_string(f.shardIndex) + "/" + std::to_string(f.shardCount) : std::string("null");
  };
  if (shardOf(earlier) != shardOf(file))
    throw InputError(path + ": shard: expected " + shardOf(file) + " (this run), found " + shardOf(earlier));
  return earlier;
}

bool runUncertaintySlice(const UncertaintyPlan& plan, UncertaintySwingsFile& file, const std::string& path,
                         const std::string& label, int jobs) {
  const long stopAfter = stopAfterSwingsForTests();
  const std::size_t sliceSwings = file.last - file.first;
  UncertaintySwingTimes times = UncertaintySwingTimes::makeEmpty(plan.swingCount);
  std::size_t resumed = 0;
  if (const auto earlier = readResumableSlice(file, path)) {
    copyFinishedSwings(*earlier, times);
    resumed = earlier->times.countFinished();
  }
  ProgressReporter progress(label, "swings");
  progress.setShowRate(true);
  progress.setResumedFrom(static_cast<int>(resumed));
  if (resumed > 0)
    progress.note("resuming from " + path + ": " + std::to_string(resumed) + " of " + std::to_string(sliceSwings) +
                  " swings" +
                  (file.sharded ? std::string()  // a shard holds parts of samples
                                : " and " + std::to_string(countFinishedSamples(plan, times)) + " of " +
                                      std::to_string(plan.options.samples) + " samples") +
                  " done by an earlier run");
  UncertaintyRunControl control;
  control.stopFlag = &gInterrupted;
  control.stopAfterSwings = stopAfter;
  control.progress = [&](int done, int) { progress.update(static_cast<int>(resumed) + done, static_cast<int>(sliceSwings)); };
  const bool complete = runUncertaintySwings(plan, file.first, file.last, times, jobs, control);

  file.times = UncertaintySwingTimes::makeEmpty(sliceSwings);
  for (std::size_t k = 0; k < sliceSwings; ++k) {
    file.times.swingTimes[k] = times.swingTimes[file.first + k];
    file.times.finished[k] = times.finished[file.first + k];
  }
  // A shard holds parts of samples: only a whole run counts them.
  file.samplesFinished = file.sharded ? 0 : countFinishedSamples(plan, times);
  // Interrupted just as the last swing ended: the swings are kept all the same, since the
  // caller writes nothing else.
  if (!complete || gInterrupted) {
    writeFileAtomic(path, formatUncertaintySwingsJson(file));
    std::fprintf(stderr,
                 "swingsim: interrupted; %zu of %zu swings%s (seed %llu) are kept in %s (\"partial\": %s); run the "
                 "same command again to resume\n",
                 file.times.countFinished(), sliceSwings,
                 file.sharded ? "" : (" and " + std::to_string(file.samplesFinished) + " of " +
                                      std::to_string(plan.options.samples) + " Monte Carlo samples").c_str(),
                 static_cast<unsigned long long>(plan.options.seed), path.c_str(), file.isPartial() ? "true" : "false");
  }
  return complete && !gInterrupted;
}

int writeSweepOutputs(const SweepStudy& study, const SweepResults& results, const UncertaintyResults* uncertainty,
                      const std::string& out, const std::optional<std::string>& json) {
  // The write phase: every file is staged inside --out and moved into place at the end, so a
  // run stopped here (or failing) leaves the folder as it was, with no temporary files.
  StagedOutput staged(out);
  for (const auto& [name, contents] : makeSweepReport(study, results, uncertainty)) {
    if (gInterrupted) break;
    staged.add(name, contents);
  }
  if (json && !gInterrupted) staged.addBeside(*json, formatSweepJson(results, uncertainty));
  if (gInterrupted) {
    staged.discard();
    std::fprintf(stderr, "swingsim: interrupted while writing the report; nothing in %s was changed\n", out.c_str());
    return 1;
  }
  // Partial results of an earlier, interrupted run are out of date now (an interrupted
  // analysis only if this run did the analysis).
  std::vector<std::string> stale = {"sweep.partial.csv"};
  if (uncertainty) stale.push_back(uncertaintyPartialFileName());
  staged.commit(stale);
  std::printf("\nreport: %s/report.md\n", out.c_str());
  return 0;
}

}  // namespace swingsim::cli
