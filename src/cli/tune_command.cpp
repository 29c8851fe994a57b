// swingsim tune STUDY.yaml [--out DIR] [--json FILE] [--jobs N]: tune a knee (several knobs
// at once) to a person's targets (a `kind: knee-tuning` study; docs/tuning.md). All inputs
// are read and checked before any swing runs; the outputs are written as one staged set.
#include <cstdio>
#include <optional>
#include <string>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "cli/sweep_steps.h"
#include "core/output_files.h"
#include "report/tuning_report.h"
#include "study/run_arguments.h"
#include "study/tuning_run.h"

namespace swingsim::cli {
namespace {

/// What `swingsim tune` was given; nullopt: not given (the default applies).
struct TuneArguments {
  std::string study;
  std::optional<std::string> out, json;
  int jobs = 0;  ///< worker threads, 0 = all cores
};

int runTune(const TuneArguments& a, const std::string& command) {
  const TuningStudy study = loadTuningStudy(a.study);
  const std::string out = chooseStudyOutputFolder(a.out, study.name, study.path);
  checkOutputsAreNotInputs({{"STUDY.yaml", a.study},
                            {"STUDY.yaml: participant", study.participantPath},
                            {"STUDY.yaml: knee_model", study.kneeModelPath}},
                           listRunOutputs(out, kTuningOutputFiles, a.json));
  InterruptScope interrupts;
  SweepRunControl control = makeTerminalControl();
  const TuningRun run = runTuningStudy(study, a.jobs, control);
  if (run.result.interrupted) {
    std::fprintf(stderr, "swingsim: interrupted after %zu swings; nothing in %s was written\nbest so far: %s\n",
                 run.result.startSet.size() + run.result.polished.size(), out.c_str(),
                 formatTuningPoint(run.result.knobs, run.result.best).c_str());
    return 1;
  }
  const std::string kneeFile = out + "/tuned-knee.yaml";
  std::printf("%s", formatTuningSummary(makeTuningReportInputs(run, kneeFile)).c_str());
  writeTuningOutputs(run, out, a.json, command);
  std::printf("report: %s/tuning.md; tuned knee model: %s\n", out.c_str(), kneeFile.c_str());
  return 0;
}

}  // namespace

Command addTuneCommand(CLI::App& app) {
  CLI::App* sub =
      app.add_subcommand("tune", "tune knee settings (knobs) to a person's swing targets: a knee-tuning study");
  auto a = std::make_shared<TuneArguments>();
  sub->add_option("STUDY.yaml", a->study, "study of kind knee-tuning")->required()->type_name("");
  addStudyOutOption(sub, a->out);
  addJsonOption(sub, a->json);
  sub->add_option("--jobs", a->jobs, "worker threads for the start set and the sensitivity, 0 = all cores (default 0)")
      ->type_name("N")
      ->check(wholeNumberIn(jobsRange()));
  return {sub, [a, sub] { return runTune(*a, formatCommandLine(*sub)); }};
}

}  // namespace swingsim::cli
