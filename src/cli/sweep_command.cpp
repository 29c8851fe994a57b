// swingsim sweep STUDY.yaml [--out DIR] [--json FILE] [--jobs N] [--add-mass KG@METRES]
//                          [--uncertainty N [--seed S] [--shard K/N]]

#include <cstdint>
#include <optional>
#include <string>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "cli/sweep_steps.h"
#include "core/input_error.h"
#include "study/cohort_study.h"
#include "study/cohort_sweep_run.h"
#include "study/run_arguments.h"
#include "study/sweep_run.h"
#include "study/sweep_study.h"
#include "study/uncertainty_swings_file.h"

namespace swingsim::cli {
namespace {

/// `--shard K/N`: shard K (0 <= K < N) of N.
struct ShardSpec {
  int index = 0, count = 1;
};

/// Reads "K/N"; a message for CLI11 if it is not two whole numbers with 0 <= K < N.
std::string checkShardSpec(const std::string& text, ShardSpec* spec = nullptr) {
  const auto slash = text.find('/');
  auto whole = [](const std::string& t, long long& v) {
    if (t.empty() || t.size() > 9 || t.find_first_not_of("0123456789") != std::string::npos) return false;
    v = std::stoll(t);
    return true;
  };
  long long k = 0, n = 0;
  if (slash == std::string::npos || !whole(text.substr(0, slash), k) || !whole(text.substr(slash + 1), n))
    return "expected K/N, two whole numbers (shard K of N, K from 0 to N - 1), found \"" + text + "\"";
  if (n < 1) return "expected N of at least 1, found \"" + text + "\"";
  if (k >= n) return "expected K from 0 to N - 1 = " + std::to_string(n - 1) + ", found \"" + text + "\"";
  if (spec) *spec = {static_cast<int>(k), static_cast<int>(n)};
  return "";
}

/// What `swingsim sweep` was given; nullopt: not given (the default applies).
struct SweepArguments {
  std::string study;
  std::optional<std::string> out, json;
  int jobs = 0;  ///< worker threads, 0 = all cores
  std::optional<AddedMass> added;
  std::optional<int> uncertaintySamples, seed;  ///< override the study's `uncertainty:` map
  std::optional<ShardSpec> shard;
  long long maxSwings = static_cast<long long>(kDefaultMaxSweepSwings);  ///< --max-swings
};

// The files a loaded sweep study reads (its participants and knee models) against what the
// run writes into `out` (also the default folder) and --json: refused before any swing.
void checkOutputsAreNotStudyFiles(const SweepStudy& study, const std::string& out,
                                  const std::optional<std::string>& json) {
  std::vector<CommandFile> inputs = {{"STUDY.yaml", study.path}};
  for (const Participant& p : study.participants)
    if (!p.path.empty()) inputs.push_back({"STUDY.yaml: participant " + p.name, p.path});
  for (const auto& [path, model] : study.kneeModels) inputs.push_back({"STUDY.yaml: a knee model", path});
  checkOutputsAreNotInputs(inputs, listRunOutputs(out, kSweepReportFiles, json));
}

int runSweepCommand(const SweepArguments& a) {
  if (isCohortStudyFile(a.study)) {
    // A cohort study: drawn participants, each calibrated and swept (docs/cohort.md).
    checkOutputsAreNotInputs({{"STUDY.yaml", a.study}}, listRunOutputs(a.out.value_or(""), kSweepReportFiles, a.json));
    if (a.added || a.uncertaintySamples || a.seed)
      throw InputError(a.study +
                       ": kind: cohort-sweep: expected no --add-mass, --uncertainty or --seed (the study's "
                       "seed draws its participants), found " +
                       (a.added  ? "--add-mass"
                        : a.seed ? "--seed"
                                 : "--uncertainty"));
    InterruptScope interrupts;
    return runCohortSweep({a.study, a.out, a.json, a.jobs, a.shard.has_value(), a.shard ? a.shard->index : 0,
                           a.shard ? a.shard->count : 1, static_cast<std::uint64_t>(a.maxSwings)},
                          makeTerminalControl());
  }
  SweepStudy study = loadSweepStudy(a.study);
  if (a.added) {
    study.addedMasses = {0.0, a.added->mass};
    study.addedMassDistances = {a.added->distanceBelowKnee};
  }
  applyUncertaintyArguments(study, a.uncertaintySamples, a.seed,
                            {"--seed", "--uncertainty N", "--seed " + std::to_string(a.seed.value_or(0))});
  if (a.shard && study.uncertaintySamples == 0)
    throw InputError(
        "--shard: shards the uncertainty analysis, which needs --uncertainty N or an `uncertainty:` map in " +
        study.path + " (got --shard " + std::to_string(a.shard->index) + "/" + std::to_string(a.shard->count) +
        " alone)");
  const std::string out = chooseSweepOutputFolder(study, a.out);
  checkOutputsAreNotStudyFiles(study, out, a.json);
  if (!a.shard) announceSweepGrid(study, static_cast<std::uint64_t>(a.maxSwings), a.jobs);  // before any work
  SweepRun run(std::move(study), a.jobs, makeTerminalControl());
  run.calibrate();
  // An interrupted run keeps its finished swings (a shard: in its shard file; the analysis: in
  // uncertainty.partial.json), and the same command resumes from there.
  InterruptScope interrupts;
  if (a.shard) return run.runShard(a.shard->index, a.shard->count, out);
  // A partial file of another analysis is refused before anything runs.
  run.planUncertainty(out + "/" + uncertaintyPartialFileName());
  return run.runToOutputs(out, a.json);
}

}  // namespace

Command addSweepCommand(CLI::App& app) {
  CLI::App* sub =
      app.add_subcommand("sweep", "knee-axis lowering sweep per participant: tables, report with figures, JSON");
  auto a = std::make_shared<SweepArguments>();
  sub->add_option("STUDY.yaml", a->study, "study of kind knee-axis-sweep or cohort-sweep (docs/cohort.md)")
      ->required()
      ->type_name("");
  addTextOption(sub, "--out", a->out, "output folder (default: the study's output_dir, else out/<study name>/)", "DIR");
  addJsonOption(sub, a->json);
  sub->add_option("--jobs", a->jobs, "worker threads, 0 = all cores (default 0)")
      ->type_name("N")
      ->check(wholeNumberIn(jobsRange()));
  sub->add_option_function<std::string>(
         "--add-mass", [a](const std::string& v) { a->added = readAddedMass(v); },
         "also sweep with this added shank mass, KG@METRES below the knee (default: the study's)")
      ->type_name("KG@M")
      ->check(addedMassSpec());
  addMaxSwingsOption(sub, a->maxSwings);
  sub->add_option("--uncertainty", a->uncertaintySamples,
                  "after the sweep, how sure the fastest lowering is: N Monte Carlo samples over the unpublished "
                  "assumptions and each at both ends of its range (docs/uncertainty.md; default: the study's "
                  "uncertainty: map, else none)")
      ->type_name("N")
      ->check(wholeNumberIn(uncertaintySamplesRange()));
  sub->add_option("--seed", a->seed,
                  "seed of the uncertainty analysis's draws (std::mt19937_64; default: the study's, else 1)")
      ->type_name("S")
      ->check(wholeNumberIn(seedRange()));
  CLI::Option* shard =
      sub->add_option_function<std::string>(
             "--shard",
             [a](const std::string& v) {
               ShardSpec spec;
               checkShardSpec(v, &spec);
               a->shard = spec;
             },
             "compute only shard K of N (K from 0 to N - 1) of the uncertainty analysis's swings and write them to "
             "OUT/uncertainty-shard-K-of-N.json (a cohort study: its participants, to OUT/cohort-shard-K-of-N.json), "
             "without the plain sweep or a report; `swingsim merge` combines the N "
             "shard files into the report and JSON of one run (docs/clusters.md)")
          ->type_name("K/N")
          ->check(CLI::Validator([](std::string& v) { return checkShardSpec(v); }, "K/N", "shard"));
  // The shard file is the result: the JSON and the added-mass sweep come from the merge.
  shard->excludes(sub->get_option("--json"));
  shard->excludes(sub->get_option("--add-mass"));
  return {sub, [a] { return runSweepCommand(*a); }};
}

}  // namespace swingsim::cli
