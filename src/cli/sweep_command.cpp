// swingsim sweep STUDY.yaml [--out DIR] [--json FILE] [--jobs N] [--add-mass KG@METRES]
//                          [--uncertainty N [--seed S]]

#include <csignal>
#include <cstdio>
#include <optional>
#include <string>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "core/input_error.h"
#include "core/output_files.h"
#include "core/progress_reporter.h"
#include "report/sweep_report.h"
#include "study/sweep_study.h"
#include "swing/sweep.h"
#include "swing/measured_validation.h"
#include "swing/sweep_uncertainty.h"
#include "swing/terminal_impact.h"

namespace swingsim::cli {
namespace {

// Set by SIGINT or SIGTERM: the sweep stops starting swings; in the write phase the staged
// files are discarded rather than left half-written.
volatile bool gInterrupted = false;
extern "C" void onInterrupt(int) { gInterrupted = true; }

void catchInterrupts() {
  std::signal(SIGINT, onInterrupt);
  std::signal(SIGTERM, onInterrupt);
}

void restoreInterrupts() {
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}

/// What `swingsim sweep` was given; nullopt: not given (the default applies).
struct SweepArguments {
  std::string study;
  std::optional<std::string> out, json;
  int jobs = 0;  ///< worker threads, 0 = all cores
  std::optional<AddedMass> added;
  std::optional<int> uncertaintySamples, seed;  ///< override the study's `uncertainty:` map
};

int runSweepCommand(const SweepArguments& a) {
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
  const std::string out = a.out.value_or(study.outputDir.empty() ? "out/" + makeSafeFileStem(study.name) : study.outputDir);

  std::vector<ParticipantCalibration> calibrations;
  if (study.calibrateTo != CalibrationTarget::kStored) {
    std::fprintf(stderr, "sweep %s: calibrating the hip time scales to Burkett Table 3 (%s)\n", study.name.c_str(),
                 calibrationTargetKey(study.calibrateTo));
    calibrations = calibrateSweepParticipants(study);
    for (const auto& c : calibrations)
      std::fprintf(stderr, "sweep %s: %s: %s\n", study.name.c_str(), c.participant.c_str(),
                   c.ok ? ("time scale " + formatNumber(c.timeScale) + " for " + formatNumber(c.targetTime) + " s").c_str()
                        : c.failure.c_str());
  }

  catchInterrupts();
  SweepResults results = [&] {
    // Scoped: an interrupted run's bar is ended before the message below.
    ProgressReporter progress("sweep " + study.name, "swings");
    progress.note(std::to_string(study.participants.size()) + " participants (" + study.path + ")");
    return runSweep(study, a.jobs, [&](int done, int total) { progress.update(done, total); }, &gInterrupted);
  }();

  if (!gInterrupted) {
    // Burkett's bounce and interior optimum, checked (report section "Terminal impact").
    std::fprintf(stderr, "sweep %s: terminal impact check: impact bookkeeping and a friction-free sweep per participant\n",
                 study.name.c_str());
    checkTerminalImpact(study, results, a.jobs);
    results.calibratedTo = study.calibrateTo;
    results.calibrations = calibrations;
    validateOnTable4(study, results);
  }
  std::printf("%s", formatSweepTables(study, results).c_str());
  // How sure is the optimum: after the plain sweep, over all its swings with one bar.
  std::optional<UncertaintyResults> uncertainty;
  if (study.uncertaintySamples > 0 && !gInterrupted) {
    UncertaintyOptions options;
    options.samples = study.uncertaintySamples;
    options.seed = static_cast<std::uint64_t>(study.uncertaintySeed);
    uncertainty = [&] {
      ProgressReporter progress("uncertainty " + study.name, "swings");
      progress.setShowRate(true);
      progress.note(std::to_string(options.samples) + " samples, seed " + std::to_string(study.uncertaintySeed) +
                    ", and each assumption at both ends of its range (docs/uncertainty.md)");
      return runSweepUncertainty(study, options, a.jobs, [&](int done, int total) { progress.update(done, total); },
                                 &gInterrupted);
    }();
    if (gInterrupted) {
      // The sweep itself finished, but a report without the analysis asked for would look complete.
      std::fprintf(stderr, "swingsim: interrupted during the uncertainty analysis; nothing in %s was written\n",
                   out.c_str());
      restoreInterrupts();
      return 1;
    }
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
  // The write phase: every file is staged inside --out and moved into place at the end, so a
  // run stopped here (or failing) leaves the folder as it was, with no temporary files.
  {
    StagedOutput staged(out);
    const UncertaintyResults* u = uncertainty ? &*uncertainty : nullptr;
    for (const auto& [name, contents] : makeSweepReport(study, results, u)) {
      if (gInterrupted) break;
      staged.add(name, contents);
    }
    if (a.json && !gInterrupted) staged.addBeside(*a.json, formatSweepJson(results, u));
    if (gInterrupted) {
      staged.discard();
      std::fprintf(stderr, "swingsim: interrupted while writing the report; nothing in %s was changed\n", out.c_str());
      restoreInterrupts();
      return 1;
    }
    // A partial CSV of an earlier, interrupted run is out of date now.
    staged.commit({"sweep.partial.csv"});
  }
  restoreInterrupts();
  std::printf("\nreport: %s/report.md\n", out.c_str());
  return 0;
}

}  // namespace

Command addSweepCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("sweep", "knee-axis lowering sweep per participant: tables, report with figures, JSON");
  auto a = std::make_shared<SweepArguments>();
  sub->add_option("STUDY.yaml", a->study, "study of kind knee-axis-sweep")->required()->type_name("");
  addTextOption(sub, "--out", a->out, "output folder (default: the study's output_dir, else out/<study name>/)", "DIR");
  addJsonOption(sub, a->json);
  sub->add_option("--jobs", a->jobs, "worker threads, 0 = all cores (default 0)")
      ->type_name("N")
      ->check(wholeNumberFrom(0, "expected 0 (all cores) or a positive whole number"));
  sub->add_option_function<std::string>("--add-mass", [a](const std::string& v) { a->added = readAddedMass(v); },
                                        "also sweep with this added shank mass, KG@METRES below the knee (default: the study's)")
      ->type_name("KG@M")
      ->check(addedMassSpec());
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
  return {sub, [a] { return runSweepCommand(*a); }};
}

}  // namespace swingsim::cli
