#include "cli/sweep_steps.h"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "core/input_error.h"
#include "core/output_files.h"
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

std::string chooseSweepOutputFolder(const SweepStudy& study, const std::optional<std::string>& out) {
  return out.value_or(study.outputDir.empty() ? "out/" + makeSafeFileStem(study.name) : study.outputDir);
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
