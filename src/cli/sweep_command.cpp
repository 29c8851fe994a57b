// swingsim sweep STUDY.yaml [--out DIR] [--json FILE] [--jobs N] [--add-mass KG@METRES]
//                          [--uncertainty N [--seed S] [--shard K/N]]

#include <cstdio>
#include <optional>
#include <string>
#include <tuple>

#include "cli/cohort_steps.h"
#include "cli/command.h"
#include "cli/option_checks.h"
#include "cli/sweep_steps.h"
#include "core/input_error.h"
#include "core/output_files.h"
#include "core/progress_reporter.h"
#include "report/sweep_report.h"
#include "study/cohort_study.h"
#include "study/sweep_study.h"
#include "study/uncertainty_swings_file.h"
#include "sweep/sweep.h"
#include "sweep/sweep_uncertainty.h"

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

/// `--shard K/N`: this shard's slice of the uncertainty swings only, into its shard file.
int runShard(const SweepStudy& study, const ShardSpec& shard, const std::string& out, int jobs) {
  const UncertaintyPlan plan = planSweepUncertainty(study, makeUncertaintyOptions(study));
  UncertaintySwingsFile file;
  file.run = makeUncertaintyRunIdentity(study, plan, SWINGSIM_VERSION);
  file.sharded = true;
  file.shardIndex = shard.index;
  file.shardCount = shard.count;
  std::tie(file.first, file.last) = calcShardSwings(plan.swingCount, shard.index, shard.count);
  const std::string path = out + "/" + uncertaintyShardFileName(shard.index, shard.count);
  const std::string label = "uncertainty " + study.name + " shard " + std::to_string(shard.index) + "/" +
                            std::to_string(shard.count);
  std::fprintf(stderr, "%s: %zu swings, %zu to %zu of the %zu (%d samples, seed %d, and each assumption at both ends)\n",
               label.c_str(), file.last - file.first, file.first, file.last - 1, plan.swingCount, study.uncertaintySamples,
               study.uncertaintySeed);
  readResumableSlice(file, path);  // another analysis's file there: refused before any swing
  catchInterrupts();
  const bool complete = runUncertaintySlice(plan, file, path, label, jobs);
  restoreInterrupts();
  if (!complete) return 1;
  writeFileAtomic(path, formatUncertaintySwingsJson(file));
  std::printf("shard %d/%d of %s: %zu swings -> %s\n(when all %d have run: swingsim merge %s/uncertainty-shard-*-of-%d.json)\n",
              shard.index, shard.count, study.name.c_str(), file.last - file.first, path.c_str(), shard.count,
              out.c_str(), shard.count);
  return 0;
}

int runSweepCommand(const SweepArguments& a) {
  if (isCohortStudyFile(a.study)) {
    // A cohort study: drawn participants, each calibrated and swept (docs/cohort.md).
    if (a.added || a.uncertaintySamples || a.seed)
      throw InputError(a.study + ": kind: cohort-sweep: expected no --add-mass, --uncertainty or --seed (the study's "
                       "seed draws its participants), found " + (a.added ? "--add-mass" : a.seed ? "--seed" : "--uncertainty"));
    return runCohortSweep({a.study, a.out, a.json, a.jobs, a.shard.has_value(), a.shard ? a.shard->index : 0,
                           a.shard ? a.shard->count : 1});
  }
  SweepStudy study = loadSweepStudy(a.study);
  if (a.added) {
    study.addedMasses = {0.0, a.added->mass};
    study.addedMassDistances = {a.added->distanceBelowKnee};
  }
  if (a.uncertaintySamples) study.uncertaintySamples = *a.uncertaintySamples;
  if (a.seed) {
    if (study.uncertaintySamples == 0)
      throw InputError("--seed: sets the seed of the uncertainty analysis, which needs --uncertainty N or an "
                       "`uncertainty:` map in " + study.path + " (got --seed " + std::to_string(*a.seed) + " alone)");
    study.uncertaintySeed = *a.seed;
  }
  if (a.shard && study.uncertaintySamples == 0)
    throw InputError("--shard: shards the uncertainty analysis, which needs --uncertainty N or an `uncertainty:` map in " +
                     study.path + " (got --shard " + std::to_string(a.shard->index) + "/" +
                     std::to_string(a.shard->count) + " alone)");
  const std::string out = chooseSweepOutputFolder(study, a.out);
  if (!a.shard) announceSweepGrid(study, static_cast<std::uint64_t>(a.maxSwings), a.jobs);  // before any work
  const std::vector<ParticipantCalibration> calibrations = calibrateForSweep(study);
  if (a.shard) return runShard(study, *a.shard, out, a.jobs);

  // How sure is the optimum: after the plain sweep, over all its swings with one bar; an
  // interrupted analysis keeps its finished swings in uncertainty.partial.json, and the same
  // command resumes from there. A partial file of another analysis is refused before anything runs.
  std::optional<UncertaintyPlan> plan;
  UncertaintySwingsFile file;
  const std::string partialPath = out + "/" + uncertaintyPartialFileName();
  if (study.uncertaintySamples > 0) {
    plan = planSweepUncertainty(study, makeUncertaintyOptions(study));
    file.run = makeUncertaintyRunIdentity(study, *plan, SWINGSIM_VERSION);
    file.first = 0;
    file.last = plan->swingCount;
    readResumableSlice(file, partialPath);
  }

  catchInterrupts();
  const SweepResults results = runPlainSweep(study, calibrations, a.jobs);
  std::printf("%s", formatSweepTables(study, results).c_str());
  std::optional<UncertaintyResults> uncertainty;
  if (plan && !gInterrupted) {
    std::fprintf(stderr, "uncertainty %s: %d samples, seed %d, and each assumption at both ends of its range "
                 "(docs/uncertainty.md)\n", study.name.c_str(), study.uncertaintySamples, study.uncertaintySeed);
    if (!runUncertaintySlice(*plan, file, partialPath, "uncertainty " + study.name, a.jobs)) {
      // The sweep itself finished, but a report without the analysis asked for would look complete.
      std::fprintf(stderr, "swingsim: no report, CSV or JSON in %s was written\n", out.c_str());
      restoreInterrupts();
      return 1;
    }
    UncertaintySwingTimes times = UncertaintySwingTimes::makeEmpty(plan->swingCount);
    copyFinishedSwings(file, times);
    uncertainty = assembleUncertaintyResults(study, *plan, times);
    std::printf("%s", formatUncertaintyTables(*uncertainty).c_str());
  }
  if (gInterrupted) {
    // Keep what finished, readable, under a name that cannot be mistaken for a result.
    writeFileAtomic(out + "/sweep.partial.csv", formatSweepCsv(results));
    std::string missing;
    char point[96];
    for (const auto& ps : results.participants) {
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
    restoreInterrupts();
    return 1;
  }
  const int code = writeSweepOutputs(study, results, uncertainty ? &*uncertainty : nullptr, out, a.json);
  restoreInterrupts();
  return code;
}

}  // namespace

Command addSweepCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("sweep", "knee-axis lowering sweep per participant: tables, report with figures, JSON");
  auto a = std::make_shared<SweepArguments>();
  sub->add_option("STUDY.yaml", a->study, "study of kind knee-axis-sweep or cohort-sweep (docs/cohort.md)")->required()->type_name("");
  addTextOption(sub, "--out", a->out, "output folder (default: the study's output_dir, else out/<study name>/)", "DIR");
  addJsonOption(sub, a->json);
  sub->add_option("--jobs", a->jobs, "worker threads, 0 = all cores (default 0)")
      ->type_name("N")
      ->check(wholeNumberFrom(0, "expected 0 (all cores) or a positive whole number"));
  sub->add_option_function<std::string>("--add-mass", [a](const std::string& v) { a->added = readAddedMass(v); },
                                        "also sweep with this added shank mass, KG@METRES below the knee (default: the study's)")
      ->type_name("KG@M")
      ->check(addedMassSpec());
  addMaxSwingsOption(sub, a->maxSwings);
  sub->add_option("--uncertainty", a->uncertaintySamples,
                  "after the sweep, how sure the fastest lowering is: N Monte Carlo samples over the unpublished "
                  "assumptions and each at both ends of its range (docs/uncertainty.md; default: the study's "
                  "uncertainty: map, else none)")
      ->type_name("N")
      ->check(wholeNumberFrom(1, "expected a whole number of samples from 1 to " + std::to_string(kMaxUncertaintySamples),
                              kMaxUncertaintySamples));
  sub->add_option("--seed", a->seed, "seed of the uncertainty analysis's draws (std::mt19937_64; default: the study's, else 1)")
      ->type_name("S")
      ->check(wholeNumberFrom(0, "expected a whole number from 0"));
  CLI::Option* shard =
      sub->add_option_function<std::string>("--shard", [a](const std::string& v) {
           ShardSpec spec;
           checkShardSpec(v, &spec);
           a->shard = spec;
         },
         "compute only shard K of N (K from 0 to N - 1) of the uncertainty analysis's swings and write them to "
         "OUT/uncertainty-shard-K-of-N.json (a cohort study: its participants, to OUT/cohort-shard-K-of-N.json), "
         "without the plain sweep or a report; `swingsim merge` combines the N "
         "shard files into the report and JSON of one run (README, Population studies across machines)")
          ->type_name("K/N")
          ->check(CLI::Validator([](std::string& v) { return checkShardSpec(v); }, "K/N", "shard"));
  // The shard file is the result: the JSON and the added-mass sweep come from the merge.
  shard->excludes(sub->get_option("--json"));
  shard->excludes(sub->get_option("--add-mass"));
  return {sub, [a] { return runSweepCommand(*a); }};
}

}  // namespace swingsim::cli
