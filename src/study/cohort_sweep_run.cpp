#include "study/cohort_sweep_run.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <tuple>

#include "core/output_files.h"
#include "core/progress_reporter.h"
#include "report/cohort_report.h"
#include "study/cohort_results_file.h"
#include "study/cohort_study.h"
#include "study/run_estimate.h"
#include "sweep/cohort_run.h"

namespace swingsim {

namespace {

/// Takes the results an earlier interrupted run of the same slice left at `path`; one of
/// another run or slice is an InputError (file, key, expected, found). Returns how many.
std::size_t resumeFrom(const std::string& path, CohortResultsFile& file) {
  if (!std::filesystem::exists(path)) return 0;
  const CohortResultsFile earlier = readCohortResultsFile(path);
  checkSameCohortRun(file.run, earlier, "this run");
  checkSameShard(file, earlier, path);
  file.results = earlier.results;
  return earlier.countFinished();
}

/// Runs the participants of `file`'s slice that have not run; false if interrupted (then
/// the finished ones are written to `path`, marked partial).
bool runSlice(const Cohort& cohort, CohortResultsFile& file, const std::string& path, const std::string& label,
              int jobs, const SweepRunControl& run) {
  const std::size_t resumed = resumeFrom(path, file);
  const std::size_t slice = file.last - file.first;
  std::vector<CohortParticipantResult> results(static_cast<std::size_t>(cohort.count));
  std::copy(file.results.begin(), file.results.end(), results.begin() + static_cast<std::ptrdiff_t>(file.first));
  bool complete = false;
  {
    ProgressReporter progress(label, "participants");
    progress.setShowRate(true);
    progress.setResumedFrom(static_cast<int>(resumed));
    if (resumed > 0)
      progress.note("resuming from " + path + ": " + std::to_string(resumed) + " of " + std::to_string(slice) +
                    " participants done by an earlier run");
    CohortRunControl control;
    control.stopFlag = run.stop;
    control.stopAfterParticipants = run.stopAfterSwings;
    control.progress = [&](int done, int) {
      progress.update(static_cast<int>(resumed) + done, static_cast<int>(slice));
    };
    complete = runCohortParticipants(cohort, file.first, file.last, results, jobs, control);
  }
  std::copy(results.begin() + static_cast<std::ptrdiff_t>(file.first),
            results.begin() + static_cast<std::ptrdiff_t>(file.last), file.results.begin());
  if (complete && !run.stopped()) return true;
  writeFileAtomic(path, formatCohortResultsJson(file));
  std::fprintf(stderr,
               "swingsim: interrupted; %zu of %zu participants are kept in %s; run the same command again to resume\n",
               file.countFinished(), slice, path.c_str());
  return false;
}

/// Participants [first, last) of `cohort` that this run (or shard) computes.
std::pair<std::size_t, std::size_t> calcSlice(const Cohort& cohort, const CohortSweepArguments& a) {
  const auto count = static_cast<std::size_t>(cohort.count);
  return a.sharded ? calcShardSwings(count, a.shardIndex, a.shardCount) : std::make_pair(std::size_t{0}, count);
}

/// Prints the swings of this run's participants and a time for them, before any is drawn;
/// InputError above --max-swings.
void announceCohortRun(const Cohort& cohort, const CohortSweepArguments& a) {
  // A calibration simulates its scan (CalibrationOptions::scanPoints, 14) and a few
  // refinements: about 20 swings; then one swing per lowering of the grid (fewer where a
  // drawn shank caps it).
  constexpr std::uint64_t kCalibrationSwings = 20;
  const auto lowerings =
      static_cast<std::uint64_t>(std::floor(cohort.study.loweringMax / cohort.study.loweringStep + 1e-9)) + 1;
  const auto [first, last] = calcSlice(cohort, a);
  const std::uint64_t people = last - first;
  announceRunSize({"cohort " + cohort.study.name, "the cohort run", people * (kCalibrationSwings + lowerings), "swings",
                   std::to_string(people) + (people == 1 ? " participant" : " participants") + " x (about " +
                       std::to_string(kCalibrationSwings) + " calibration swings + up to " + std::to_string(lowerings) +
                       " lowerings)",
                   kSecondsPerSwingEstimate, a.jobs},
                  a.maxSwings, cohort.study.path + ": participants",
                  "draw fewer participants, run it in shards (--shard K/N) or coarsen the lowering grid",
                  "--max-swings");
}

/// The report, cohort.csv, figures and --json, staged and moved into `out` together.
int writeCohortOutputs(const Cohort& cohort, const std::vector<CohortParticipantResult>& results,
                       const std::string& out, const std::optional<std::string>& json, const SweepRunControl& control) {
  const CohortSummary summary = summarizeCohort(cohort, results);
  std::printf("%s", formatCohortSummary(cohort, summary).c_str());
  StagedOutput staged(out, OutputSetKind::kWholeRun);
  for (const auto& [name, contents] : makeCohortReport(cohort, results, summary)) staged.add(name, contents);
  if (json) staged.addBeside(*json, formatCohortJson(cohort, results, summary));
  if (control.stopped()) {
    staged.discard();
    std::fprintf(stderr, "swingsim: interrupted while writing the report; nothing in %s was changed\n", out.c_str());
    return 1;
  }
  staged.commit({cohortPartialFileName()});
  std::printf("\nreport: %s/report.md\n", out.c_str());
  return 0;
}

}  // namespace

int runCohortSweep(const CohortSweepArguments& a, const SweepRunControl& control) {
  const Cohort cohort =
      loadCohortStudy(a.study, [&a](const Cohort& c) { announceCohortRun(c, a); });  // before any work
  const std::string out = chooseSweepOutputFolder(cohort.study, a.out);
  CohortResultsFile file;
  file.run = makeCohortRunIdentity(cohort, SWINGSIM_VERSION);
  file.sharded = a.sharded;
  file.shardIndex = a.shardIndex;
  file.shardCount = a.shardCount;
  std::tie(file.first, file.last) = calcSlice(cohort, a);
  file.results.resize(file.last - file.first);
  const std::string path =
      out + "/" + (a.sharded ? cohortShardFileName(a.shardIndex, a.shardCount) : cohortPartialFileName());
  std::string label = "cohort " + cohort.study.name;
  if (a.sharded) label += " shard " + std::to_string(a.shardIndex) + "/" + std::to_string(a.shardCount);
  std::fprintf(stderr,
               "%s: participants %zu to %zu of %d (seed %llu): calibration to each drawn swing time, then the "
               "lowering sweep\n",
               label.c_str(), file.first + 1, file.last, cohort.count, static_cast<unsigned long long>(cohort.seed));
  makeDirectories(out);
  if (!runSlice(cohort, file, path, label, a.jobs, control)) return 1;
  if (a.sharded) {
    writeFileAtomic(path, formatCohortResultsJson(file));
    std::printf(
        "shard %d/%d of %s: %zu participants -> %s\n(when all %d have run: swingsim merge "
        "%s/cohort-shard-*-of-%d.json)\n",
        a.shardIndex, a.shardCount, cohort.study.name.c_str(), file.last - file.first, path.c_str(), a.shardCount,
        out.c_str(), a.shardCount);
    return 0;
  }
  return writeCohortOutputs(cohort, file.results, out, a.json, control);
}

int runCohortMerge(const std::vector<std::string>& shardFiles, const std::optional<std::string>& out,
                   const std::optional<std::string>& json, const SweepRunControl& control) {
  // Every shard is read and checked before anything is written.
  std::vector<CohortResultsFile> shards;
  for (const auto& path : shardFiles) shards.push_back(readCohortResultsFile(path));
  const std::vector<CohortParticipantResult> results = mergeCohortShards(shards);
  const CohortResultsFile& head = shards.front();
  const Cohort cohort = loadCohortStudy(head.run.studyPath);
  const CohortRunIdentity now = makeCohortRunIdentity(cohort, SWINGSIM_VERSION);
  for (const auto& s : shards) checkSameCohortRun(now, s, "the study " + cohort.study.path + " as it is now");
  std::fprintf(stderr, "merge %s: %zu shards, %d participants, seed %llu\n", cohort.study.name.c_str(), shards.size(),
               cohort.count, static_cast<unsigned long long>(cohort.seed));
  return writeCohortOutputs(cohort, results, chooseSweepOutputFolder(cohort.study, out), json, control);
}

}  // namespace swingsim
