// swingsim merge SHARD_FILES... [--out DIR] [--json FILE] [--jobs N]
//
// Combines the shard files of `swingsim sweep STUDY --uncertainty N --seed S --shard K/N`
// (K = 0 .. N-1) into the tables, report and JSON that `swingsim sweep STUDY --uncertainty N
// --seed S` prints and writes. The shards hold the uncertainty analysis's swings; the plain
// sweep (its terminal-impact check and Table 4 validation, seconds for the Burkett study) is
// run here from the study the shards name, after checking that it is the study they ran.

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "cli/sweep_steps.h"
#include "core/input_error.h"
#include "core/output_paths.h"
#include "study/cohort_results_file.h"
#include "study/cohort_sweep_run.h"
#include "study/sweep_run.h"
#include "study/sweep_study.h"
#include "study/uncertainty_swings_file.h"

namespace swingsim::cli {
namespace {

struct MergeArguments {
  std::vector<std::string> shards;
  std::optional<std::string> out, json;
  int jobs = 0;
  long long maxSwings = static_cast<long long>(kDefaultMaxSweepSwings);  ///< --max-swings
};

int runMergeCommand(const MergeArguments& a) {
  std::vector<CommandFile> inputs;
  for (const auto& shard : a.shards) inputs.push_back({"SHARD_FILES", shard});
  checkOutputsAreNotInputs(inputs, listRunOutputs(a.out.value_or(""), kSweepReportFiles, a.json));
  // Shards of a cohort study (docs/cohort.md) hold whole participants' results.
  if (isCohortResultsFile(a.shards.front())) {
    InterruptScope interrupts;
    return runCohortMerge(a.shards, a.out, a.json, makeTerminalControl());
  }
  // Every shard is read and checked (missing, duplicate, partial, another analysis) before any
  // swing runs or any file is written.
  checkDistinctFiles(a.shards, "give each shard file once");
  std::vector<UncertaintySwingsFile> shards;
  for (const auto& path : a.shards) shards.push_back(readUncertaintySwingsFile(path));
  const UncertaintySwingTimes times = mergeUncertaintyShards(shards);
  const UncertaintySwingsFile& head = shards.front();

  constexpr std::uint64_t kMaxSeed = 1000000000;  // what --seed and a study's seed accept
  if (head.run.seed > kMaxSeed)
    throw InputError(head.path + ": seed: expected a seed from 0 to 1000000000 (what sweep --seed accepts), found " +
                     std::to_string(head.run.seed));
  // The shards name the study as their sweep command line gave it, relative to the folder
  // they ran in: from another folder that path may lead nowhere, and the user must know
  // where the path came from.
  std::error_code ec;
  if (!std::filesystem::exists(head.run.studyPath, ec))
    throw InputError(head.path + ": study_path: the shards name the study file \"" + head.run.studyPath +
                     "\" (as their sweep command gave it), which is not there from this folder (" +
                     std::filesystem::current_path(ec).string() +
                     "); run merge from the folder the shards were run in, or put the study there");
  SweepStudy study = loadSweepStudy(head.run.studyPath);
  study.uncertaintySamples = head.run.samples;
  study.uncertaintySeed = static_cast<int>(head.run.seed);
  const std::string out = chooseSweepOutputFolder(study, a.out);
  announceSweepGrid(study, static_cast<std::uint64_t>(a.maxSwings), a.jobs);  // before any work
  SweepRun run(std::move(study), a.jobs, makeTerminalControl());
  run.calibrate();
  run.planUncertainty("");
  const SweepStudy& ran = run.study();
  for (const auto& s : shards)
    checkSameUncertaintyRun(run.uncertaintyRun(), s, "the study " + ran.path + " as it is now");
  std::fprintf(stderr, "merge %s: %zu shards, %zu swings of %d samples, seed %llu\n", ran.name.c_str(), shards.size(),
               run.uncertaintyRun().swingCount, ran.uncertaintySamples, static_cast<unsigned long long>(head.run.seed));
  run.takeUncertaintySwings(times);
  InterruptScope interrupts;
  return run.runToOutputs(out, a.json);
}

}  // namespace

Command addMergeCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("merge",
                                     "combine the shard files of `sweep --uncertainty N --shard K/N` (or of a cohort "
                                     "study's `sweep --shard K/N`) into the report and JSON of one sweep run");
  auto a = std::make_shared<MergeArguments>();
  sub->add_option("SHARD_FILES", a->shards,
                  "every shard file (OUT/uncertainty-shard-K-of-N.json, K = 0 .. N-1) of one analysis")
      ->required()
      ->type_name("");
  addTextOption(sub, "--out", a->out, "output folder (default: the study's output_dir, else out/<study name>/)", "DIR");
  addJsonOption(sub, a->json);
  sub->add_option("--jobs", a->jobs, "worker threads of the plain sweep, 0 = all cores (default 0)")
      ->type_name("N")
      ->check(wholeNumberIn(jobsRange()));
  addMaxSwingsOption(sub, a->maxSwings);
  return {sub, [a] { return runMergeCommand(*a); }};
}

}  // namespace swingsim::cli
