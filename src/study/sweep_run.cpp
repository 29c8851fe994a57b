#include "study/sweep_run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <thread>
#include <tuple>

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/output_paths.h"
#include "core/progress_reporter.h"
#include "report/sweep_report.h"
#include "study/run_estimate.h"
#include "sweep/measured_validation.h"
#include "sweep/terminal_impact.h"

namespace swingsim {

void completeSweepResults(const SweepStudy& study, SweepResults& results,
                          const std::vector<ParticipantCalibration>& calibrations, int jobs) {
  checkTerminalImpact(study, results, jobs);
  results.calibratedTo = study.calibrateTo;
  results.calibrations = calibrations;
  validateOnTable4(study, results);
}

UncertaintyOptions makeUncertaintyOptions(const SweepStudy& study) {
  UncertaintyOptions options;
  options.samples = study.uncertaintySamples;
  options.seed = static_cast<std::uint64_t>(study.uncertaintySeed);
  options.sensitivity = true;
  return options;
}

namespace {

/// "3 participants, no added mass" or "..., 2 added masses above 0 kg x 3 distances".
std::string describeSweepGrid(const SweepStudy& study) {
  const std::size_t people = study.participants.size();
  const auto masses = std::count_if(study.addedMasses.begin(), study.addedMasses.end(), [](double m) { return m > 0; });
  return std::to_string(people) + (people == 1 ? " participant" : " participants") +
         (masses == 0 ? std::string(", no added mass")
                      : ", " + std::to_string(masses) + " added masses above 0 kg x " +
                            std::to_string(study.addedMassDistances.size()) + " distances");
}

}  // namespace

void announceSweepGrid(const SweepStudy& study, std::uint64_t maxSwings, int jobs) {
  announceRunSize({"sweep " + study.name, "the sweep", countSweepSwings(study), "swings", describeSweepGrid(study),
                   kSecondsPerSwingEstimate, jobs},
                  maxSwings, study.path, "shorten the added_mass lists or the lowering grid", "--max-swings");
}

std::string chooseSweepOutputFolder(const SweepStudy& study, const std::optional<std::string>& out) {
  if (out) return *out;  // checked while parsing
  if (study.outputDir.empty()) return chooseStudyOutputFolder(out, study.name, study.path);
  checkOutputFolder(study.outputDir, study.path + ": output_dir");
  return study.outputDir;
}

std::optional<UncertaintySwingsFile> readResumableSlice(const UncertaintySwingsFile& file, const std::string& path) {
  if (path.empty() || !std::filesystem::exists(path)) return std::nullopt;
  UncertaintySwingsFile earlier = readUncertaintySwingsFile(path);
  checkSameUncertaintyRun(file.run, earlier, "this run");
  checkSameShard(file, earlier, path);
  return earlier;
}

SweepRun::SweepRun(SweepStudy study, int jobs, SweepRunControl control)
    : study_(std::move(study)), jobs_(jobs), control_(std::move(control)) {}

void SweepRun::calibrate() {
  if (study_.calibrateTo == CalibrationTarget::kStored) return;
  if (control_.terminal)
    std::fprintf(stderr, "sweep %s: calibrating the hip time scales to Burkett Table 3 (%s)\n", study_.name.c_str(),
                 calibrationTargetKey(study_.calibrateTo));
  calibrations_ = calibrateSweepParticipants(study_);
  if (!control_.terminal) return;
  for (const auto& c : calibrations_)
    std::fprintf(stderr, "sweep %s: %s: %s\n", study_.name.c_str(), c.participant.c_str(),
                 c.ok
                     ? ("time scale " + formatNumber(c.timeScale) + " for " + formatNumber(c.targetTime) + " s").c_str()
                     : c.failure.c_str());
}

bool SweepRun::sweep() {
  {
    // Scoped: an interrupted run's bar is ended before any message after it.
    std::optional<ProgressReporter> progress;
    if (control_.terminal) {
      progress.emplace("sweep " + study_.name, "swings");
      progress->note(std::to_string(study_.participants.size()) + " participants (" + study_.path + ")");
    }
    results_ = runSweep(
        study_, jobs_,
        [&](int done, int total) {
          if (control_.poll) control_.poll();
          if (progress) progress->update(done, total);
        },
        control_.stop);
  }
  if (control_.stopped()) return false;
  // Burkett's bounce and interior optimum, checked (report section "Terminal impact").
  if (control_.terminal)
    std::fprintf(stderr,
                 "sweep %s: terminal impact check: impact bookkeeping and a friction-free sweep per participant\n",
                 study_.name.c_str());
  completeSweepResults(study_, results_, calibrations_, jobs_);
  return !control_.stopped();
}

void SweepRun::planUncertainty(const std::string& partialPath) {
  if (study_.uncertaintySamples == 0) return;
  plan_ = planSweepUncertainty(study_, makeUncertaintyOptions(study_));
  file_ = UncertaintySwingsFile();
  file_.run = makeUncertaintyRunIdentity(study_, *plan_, SWINGSIM_VERSION);
  file_.first = 0;
  file_.last = plan_->swingCount;
  partialPath_ = partialPath;
  earlier_ = readResumableSlice(file_, partialPath_);
}

bool SweepRun::runUncertainty() {
  if (!plan_) return true;
  if (control_.terminal)
    std::fprintf(stderr,
                 "uncertainty %s: %d samples, seed %d, and each assumption at both ends of its range "
                 "(docs/uncertainty.md)\n",
                 study_.name.c_str(), study_.uncertaintySamples, study_.uncertaintySeed);
  if (!runSlice(file_, partialPath_, "uncertainty " + study_.name, earlier_)) return false;
  UncertaintySwingTimes times = UncertaintySwingTimes::makeEmpty(plan_->swingCount);
  copyFinishedSwings(file_, times);
  uncertainty_ = assembleUncertaintyResults(study_, *plan_, times);
  return true;
}

int SweepRun::runShard(int index, int count, const std::string& out) {
  plan_ = planSweepUncertainty(study_, makeUncertaintyOptions(study_));
  const UncertaintyPlan& plan = *plan_;
  UncertaintySwingsFile file;
  file.run = makeUncertaintyRunIdentity(study_, plan, SWINGSIM_VERSION);
  file.sharded = true;
  file.shardIndex = index;
  file.shardCount = count;
  std::tie(file.first, file.last) = calcShardSwings(plan.swingCount, index, count);
  const std::string path = out + "/" + uncertaintyShardFileName(index, count);
  const std::string label =
      "uncertainty " + study_.name + " shard " + std::to_string(index) + "/" + std::to_string(count);
  if (control_.terminal)
    std::fprintf(stderr,
                 "%s: %zu swings, %zu to %zu of the %zu (%d samples, seed %d, and each assumption at both ends)\n",
                 label.c_str(), file.last - file.first, file.first, file.last - 1, plan.swingCount,
                 study_.uncertaintySamples, study_.uncertaintySeed);
  // Another analysis's file there: refused before any swing.
  const std::optional<UncertaintySwingsFile> earlier = readResumableSlice(file, path);
  if (!runSlice(file, path, label, earlier)) return 1;
  writeFileAtomic(path, formatUncertaintySwingsJson(file));
  if (control_.terminal)
    std::printf(
        "shard %d/%d of %s: %zu swings -> %s\n(when all %d have run: swingsim merge "
        "%s/uncertainty-shard-*-of-%d.json)\n",
        index, count, study_.name.c_str(), file.last - file.first, path.c_str(), count, out.c_str(), count);
  return 0;
}

bool SweepRun::runSlice(UncertaintySwingsFile& file, const std::string& path, const std::string& label,
                        const std::optional<UncertaintySwingsFile>& earlier) {
  const UncertaintyPlan& plan = *plan_;
  const std::size_t sliceSwings = file.last - file.first;
  UncertaintySwingTimes times = UncertaintySwingTimes::makeEmpty(plan.swingCount);
  std::size_t resumed = 0;
  if (earlier) {
    copyFinishedSwings(*earlier, times);
    resumed = earlier->times.countFinished();
  }
  std::optional<ProgressReporter> progress;
  if (control_.terminal) {
    progress.emplace(label, "swings");
    progress->setShowRate(true);
    progress->setResumedFrom(static_cast<int>(resumed));
    if (resumed > 0)
      progress->note("resuming from " + path + ": " + std::to_string(resumed) + " of " + std::to_string(sliceSwings) +
                     " swings" +
                     (file.sharded ? std::string()  // a shard holds parts of samples
                                   : " and " + std::to_string(countFinishedSamples(plan, times)) + " of " +
                                         std::to_string(plan.options.samples) + " samples") +
                     " done by an earlier run");
  }
  UncertaintyRunControl control;
  control.stopFlag = control_.stop;
  control.stopAfterSwings = control_.stopAfterSwings;
  control.progress = [&](int done, int) {
    if (control_.poll) control_.poll();
    if (progress) progress->update(static_cast<int>(resumed) + done, static_cast<int>(sliceSwings));
  };
  const bool complete = runUncertaintySwings(plan, file.first, file.last, times, jobs_, control);

  file.times = UncertaintySwingTimes::makeEmpty(sliceSwings);
  for (std::size_t k = 0; k < sliceSwings; ++k) {
    file.times.swingTimes[k] = times.swingTimes[file.first + k];
    file.times.finished[k] = times.finished[file.first + k];
  }
  // A shard holds parts of samples: only a whole run counts them.
  file.samplesFinished = file.sharded ? 0 : countFinishedSamples(plan, times);
  // Interrupted just as the last swing ended: the swings are kept all the same, since the
  // caller writes nothing else.
  if ((!complete || control_.stopped()) && !path.empty()) {
    writeFileAtomic(path, formatUncertaintySwingsJson(file));
    std::fprintf(stderr,
                 "swingsim: interrupted; %zu of %zu swings%s (seed %llu) are kept in %s (\"partial\": %s); run the "
                 "same command again to resume\n",
                 file.times.countFinished(), sliceSwings,
                 file.sharded ? ""
                              : (" and " + std::to_string(file.samplesFinished) + " of " +
                                 std::to_string(plan.options.samples) + " Monte Carlo samples")
                                    .c_str(),
                 static_cast<unsigned long long>(plan.options.seed), path.c_str(), file.isPartial() ? "true" : "false");
  }
  return complete && !control_.stopped();
}

int SweepRun::runToOutputs(const std::string& out, const std::optional<std::string>& json) {
  sweep();
  if (merged_ && control_.stopped()) {
    std::fprintf(stderr, "swingsim: interrupted during the plain sweep; nothing in %s was written\n", out.c_str());
    return 1;
  }
  if (control_.terminal) std::printf("%s", formatSweepTables(study_, results_).c_str());
  if (plan_ && !control_.stopped()) {
    if (merged_) {
      uncertainty_ = assembleUncertaintyResults(study_, *plan_, *merged_);
    } else if (!runUncertainty()) {
      // The sweep itself finished, but a report without the analysis asked for would look complete.
      std::fprintf(stderr, "swingsim: no report, CSV or JSON in %s was written\n", out.c_str());
      return 1;
    }
    if (control_.terminal) std::printf("%s", formatUncertaintyTables(*uncertainty_).c_str());
  }
  if (control_.stopped()) {
    writePartialRows(out);
    return 1;
  }
  return writeOutputs(out, json);
}

void SweepRun::writePartialRows(const std::string& out) const {
  // Keep what finished, readable, under a name that cannot be mistaken for a result.
  writeFileAtomic(out + "/sweep.partial.csv", formatSweepCsv(results_));
  std::string missing;
  char point[96];
  for (const auto& ps : results_.participants) {
    for (const auto* list : {&ps.points, &ps.massPoints}) {
      for (const auto& pt : *list) {
        if (pt.ran) continue;
        if (pt.added.mass > 0)
          std::snprintf(point, sizeof point, " %s@%.3f+%gkg@%.2fm", ps.name.c_str(), pt.lowering, pt.added.mass,
                        pt.added.distanceBelowKnee);
        else
          std::snprintf(point, sizeof point, " %s@%.3f", ps.name.c_str(), pt.lowering);
        missing += point;
      }
    }
  }
  std::fprintf(stderr, "swingsim: interrupted; finished rows are in %s/sweep.partial.csv; not run:%s\n", out.c_str(),
               missing.c_str());
}

int SweepRun::writeOutputs(const std::string& out, const std::optional<std::string>& json) {
  // The write phase: every file is staged inside --out and moved into place at the end, so a
  // run stopped here (or failing) leaves the folder as it was, with no temporary files.
  StagedOutput staged(out, OutputSetKind::kWholeRun);
  for (const auto& [name, contents] : makeSweepReport(study_, results_, uncertainty())) {
    if (control_.stopped()) break;
    staged.add(name, contents);
  }
  if (json && !control_.stopped()) staged.addBeside(*json, formatJson());
  if (control_.stopped()) {
    staged.discard();
    std::fprintf(stderr, "swingsim: interrupted while writing the report; nothing in %s was changed\n", out.c_str());
    return 1;
  }
  // Partial results of an earlier, interrupted run are out of date now (an interrupted
  // analysis only if this run did the analysis).
  std::vector<std::string> stale = {"sweep.partial.csv"};
  if (uncertainty_) stale.push_back(uncertaintyPartialFileName());
  staged.commit(stale);
  if (control_.terminal) std::printf("\nreport: %s/report.md\n", out.c_str());
  return 0;
}

std::string SweepRun::formatJson() const { return formatSweepJson(results_, uncertainty()); }

}  // namespace swingsim
