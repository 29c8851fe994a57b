// swingsim diagnose STUDY.yaml [--out DIR] [--json FILE] [--save-model FILE]: compare, rank
// candidate missing physical effects, add the accepted ones, refit, and report the error
// before and after, for any plant (docs/diagnosis.md), with a progress bar per step on stderr. All inputs are read
// before any output.
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "core/input_error.h"
#include "core/output_files.h"
#include "core/progress_reporter.h"
#include "core/staged_writer.h"
#include "report/diagnosis_markdown.h"
#include "report/diagnosis_report.h"
#include "study/diagnosed_model_writer.h"
#include "study/diagnosis_study.h"
#include "study/run_arguments.h"

namespace swingsim::cli {

namespace {

/// What `swingsim diagnose` was given; nullopt: not given (the default applies).
struct DiagnoseArguments {
  std::string study;
  std::optional<std::string> out, json, saveModel;
  long long maxRows = 0;  ///< --max-rows; 0: the plant's default limit
};

// The work: read the study, diagnose, print, write the report, the JSON and the model.
// `command`: the command line, for the report and the saved model.
int runDiagnose(const DiagnoseArguments& args, const std::string& command) {
  const DiagnosisStudy study = loadDiagnosisStudy(args.study);
  const std::string outDir = chooseStudyOutputFolder(args.out, study.name, study.path);
  std::vector<CommandFile> outputs = listRunOutputs(outDir, {"report.md"}, args.json);
  outputs.push_back({"--save-model", args.saveModel.value_or("")});
  checkOutputsAreNotInputs(listDiagnosisStudyFiles(study), outputs);
  const DiagnosisRowLimit limit{static_cast<std::uint64_t>(args.maxRows)};
  const auto plant = loadDiagnosisPlant(study, 8, &limit);  // prints its size, refuses one above the limit

  // A bar per step of the forward selection (candidates scored), on stderr, once the run has
  // taken a second (a bench diagnosis ends before that and prints nothing).
  std::unique_ptr<ProgressReporter> bar;
  int barStep = -1;
  const auto start = std::chrono::steady_clock::now();
  const Diagnosis dg = runDiagnosis(*plant, study.settings, [&](int step, int done, int total) {
    if (!bar && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 1.0) return;
    if (step != barStep) {
      bar = std::make_unique<ProgressReporter>("diagnose " + study.name + ": step " + std::to_string(step + 1),
                                               "candidates scored");
      barStep = step;
    }
    bar->update(done, total);
  });
  bar.reset();
  for (const auto& w : dg.warnings) std::fprintf(stderr, "swingsim diagnose: warning: %s\n", w.c_str());
  const Comparison before = plant->compare(*dg.baseline.model);
  const Comparison after = plant->compare(*dg.final.model);
  const std::string report = formatDiagnosisText(dg, before, after);
  const std::string check = plant->verify(*dg.final.model);
  const std::string drive = describeStudyDrive(study);
  if (study.plant == PlantKind::kSweep)
    std::printf("%s: the sweep of %s against %s, leave one participant out\n", study.name.c_str(),
                study.sweepStudyPath.c_str(), study.measuredPath.c_str());
  else
    std::printf("%s: %s, %zu training file(s)%s\n", study.name.c_str(), fileStem(study.baseModelPath).c_str(),
                study.train.size(), drive.empty() ? "" : ("; " + drive).c_str());
  std::printf("where the base model fails (before):\n%s\n%s", formatComparisonTable(before).c_str(), report.c_str());
  if (!check.empty()) std::printf("%s\n", check.c_str());
  // An independent measurement the fit never saw (the swing's knee moment from inverse
  // dynamics), against what the model applies before and after.
  const std::optional<HeldBackComparison> heldBefore = plant->compareHeldBack(*dg.baseline.model);
  const std::optional<HeldBackComparison> heldAfter = plant->compareHeldBack(*dg.final.model);
  const bool held = heldBefore && heldAfter;
  if (held) std::printf("%s", formatHeldBackText(*heldBefore, *heldAfter).c_str());
  const std::vector<std::string> heldWarnings = held ? checkHeldBackComparison(*heldAfter) : std::vector<std::string>{};
  for (const auto& w : heldWarnings) std::fprintf(stderr, "swingsim diagnose: warning: %s\n", w.c_str());

  // The report, its plots and --json as one set: the folder holds this run or the one before.
  StagedOutput staged(outDir, OutputSetKind::kWholeRun);
  stageFolderWriter(staged, [&](const std::string& folder) {
    writeDiagnosisReport(
        folder, {study.name, command, drive, &dg, &before, &after, check, heldBefore, heldAfter, heldWarnings});
  });
  if (args.json) staged.addBeside(*args.json, formatJson(makeDiagnoseJson(dg, before, after, heldBefore, heldAfter)));
  staged.commit();
  std::printf("report: %s/report.md (residual plots before-*.svg, after-*.svg)\n", outDir.c_str());
  if (args.saveModel && !dg.explained)
    throw RunError("diagnose: --save-model: not saved: the diagnosed model does not explain the data (" + dg.verdict +
                   ")");
  if (args.saveModel) {
    const auto written = saveDiagnosedModel(study, *plant, dg, *args.saveModel, command);
    for (const auto& p : written) std::printf("model: %s\n", p.c_str());
  }
  return 0;
}

}  // namespace

// The command line (CLI11): the positional and the options, bound to DiagnoseArguments.
Command addDiagnoseCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "diagnose", "rank candidate missing physical effects, add the accepted ones, report the error before and after");
  auto a = std::make_shared<DiagnoseArguments>();
  sub->add_option("STUDY.yaml", a->study, "study of kind cylinder-diagnosis, swing-diagnosis or sweep-diagnosis")
      ->required()
      ->type_name("");
  addStudyOutOption(sub, a->out);
  addJsonOption(sub, a->json);
  addTextOption(sub, "--save-model", a->saveModel,
                "write the diagnosed model here (knee model YAML; the swing also writes "
                "FILE-participant.yaml); only when the data are explained (default: not saved)",
                "FILE");
  sub->add_option("--max-rows", a->maxRows,
                  "refuse a diagnosis of more rows of measured data than this (after any resample_s; default " +
                      std::to_string(kDefaultMaxSwingDiagnosisRows) + " for swing records, " +
                      std::to_string(kDefaultMaxSweepDiagnosisRows) + " for a measured sweep table, " +
                      std::to_string(kDefaultMaxCylinderDiagnosisRows) +
                      " for bench records; the count and a time estimate are printed before the fit)")
      ->type_name("N")
      ->check(wholeNumberIn(maxRowsRange()));
  return {sub, [a, sub] { return runDiagnose(*a, formatCommandLine(*sub)); }};
}

}  // namespace swingsim::cli
