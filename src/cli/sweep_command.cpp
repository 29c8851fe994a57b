// swingsim sweep STUDY.yaml [--out DIR] [--json FILE] [--jobs N] [--add-mass KG@METRES]

#include <csignal>
#include <cstdio>

#include "cli/command_registry.h"
#include "core/output_files.h"
#include "core/progress_reporter.h"
#include "report/sweep_report.h"
#include "report/swing_json.h"
#include "study/sweep_study.h"
#include "swing/sweep.h"

namespace swingsim::cli {
namespace {

volatile bool gInterrupted = false;
extern "C" void onInterrupt(int) { gInterrupted = true; }

int runSweepCommand(const Arguments& a) {
  if (a.positional().size() != 1) throw UsageError("expected one study YAML file");
  SweepStudy study = loadSweepStudy(a.positional()[0]);
  if (a.has("--add-mass")) {
    const AddedMass m = parseAddedMass(a.get("--add-mass"));
    study.addedMasses = {0.0, m.mass};
    study.addedMassDistances = {m.distanceBelowKnee};
  }
  const int jobs = a.getInt("--jobs", 0);
  if (jobs < 0) throw UsageError("--jobs: expected 0 (all cores) or a positive number");
  const std::string out = a.get("--out", study.outputDir.empty() ? "out/" + study.name : study.outputDir);

  std::signal(SIGINT, onInterrupt);
  const SweepResults results = [&] {
    // Scoped: an interrupted run's bar is ended before the message below.
    ProgressReporter progress("sweep " + study.name, "swings");
    progress.note(std::to_string(study.participants.size()) + " participants (" + study.path + ")");
    return runSweep(study, jobs, [&](int done, int total) { progress.update(done, total); }, &gInterrupted);
  }();
  std::signal(SIGINT, SIG_DFL);

  std::printf("%s", formatSweepTables(study, results).c_str());
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
    return 1;
  }
  for (const auto& [name, contents] : makeSweepReport(study, results)) writeFileAtomic(out + "/" + name, contents);
  if (a.has("--json")) writeFileAtomic(a.get("--json"), formatSweepJson(results));
  std::printf("\nreport: %s/report.md\n", out.c_str());
  return 0;
}

Registrar reg("sweep", {"knee-axis lowering sweep per participant: tables, report with figures, JSON",
                        "STUDY.yaml", "study of kind knee-axis-sweep",
                        {{"--out", "output folder (default: the study's output_dir, else out/<study name>/)"}, {"--json", "also write the machine-readable result to this JSON file"},
                         {"--jobs", "worker threads, 0 = all cores (default 0)"},
                         {"--add-mass", "also sweep with this added shank mass, KG@METRES below the knee (default: the study's)"}},
                        runSweepCommand});

}  // namespace
}  // namespace swingsim::cli
