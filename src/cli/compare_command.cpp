// swingsim compare STUDY.yaml [--out DIR] [--json FILE]: model vs measurement, for either
// plant (cylinder-diagnosis, swing-diagnosis). The base model's free parameters are refitted
// on the training files (as diagnose's baseline), then metrics overall and per phase and
// residual plots show where and when it fails.
#include <cstdio>
#include <optional>
#include <string>

#include "cli/command.h"
#include "core/output_files.h"
#include "report/diagnosis_report.h"
#include "study/diagnosis_study.h"

namespace swingsim::cli {

namespace {

/// What `swingsim compare` was given; nullopt: not given (the default applies).
struct CompareArguments {
  std::string study;
  std::optional<std::string> out, json;
};

// The work: read the study, refit the base model, print and write the comparison.
int runCompare(const CompareArguments& args) {
  const DiagnosisStudy study = loadDiagnosisStudy(args.study);
  const std::string outDir = chooseStudyOutputFolder(args.out, study.name, study.path);
  std::vector<CommandFile> outputs = listRunOutputs(outDir, {"report.md"}, args.json);
  checkOutputsAreNotInputs(listDiagnosisStudyFiles(study), outputs);
  const auto plant = loadDiagnosisPlant(study, 1);
  const BaselineComparison b = compareBaseline(*plant, study.settings.whitenessLags);
  for (const auto& w : plant->warnings()) std::fprintf(stderr, "swingsim compare: warning: %s\n", w.c_str());
  const std::string drive = describeStudyDrive(study);
  std::printf("%s: %s refitted on %zu training file(s)%s\n", study.name.c_str(), fileStem(study.baseModelPath).c_str(),
              study.train.size(), drive.empty() ? "" : ("; " + drive).c_str());
  for (const auto& p : b.parameters) std::printf("%s", formatBaseParameter("base model: ", " refitted to", p).c_str());
  std::printf("%s", formatComparisonTable(b.comparison).c_str());
  const WhitenessTest& wt = b.whiteness;
  if (wt.computed)
    std::printf(
        "training residual: Ljung-Box Q = %.1f over %d lags (p = %.3g; white when p >= %.3g, the acceptance "
        "rule's alpha), %d lags outside the 99 %% band: %s\n",
        wt.q, wt.lags, wt.pValue, study.settings.alpha, wt.lagsOutsideBand,
        judgeWhiteness(wt, study.settings.alpha) == Whiteness::kWhite ? "consistent with white noise"
                                                                      : "structure left (not white)");
  else
    std::printf("training residual: Ljung-Box test cannot tell (%s)\n", wt.note.c_str());
  if (wt.computed && !wt.note.empty()) std::printf("  (%s)\n", wt.note.c_str());
  // The knee moment against the measured one, when the records have it (never fitted).
  const std::optional<HeldBackComparison> moment = plant->compareHeldBack(*b.fit.model);
  for (const auto& p : writeResidualPlots(outDir, "compare", b.comparison, moment ? &*moment : nullptr))
    std::printf("plot: %s\n", p.c_str());
  if (args.json) {
    Json j = makeComparisonJson(fileStem(study.baseModelPath), b.comparison);
    j["warnings"] = plant->warnings();
    writeJsonFile(*args.json, j);
  }
  return 0;
}

}  // namespace

// The command line (CLI11): the positional and the options, bound to CompareArguments.
Command addCompareCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("compare", "model vs measurement: metrics overall and per phase, residual plots");
  auto a = std::make_shared<CompareArguments>();
  sub->add_option("STUDY.yaml", a->study, "study of kind cylinder-diagnosis or swing-diagnosis")
      ->required()
      ->type_name("");
  addStudyOutOption(sub, a->out);
  addJsonOption(sub, a->json);
  return {sub, [a] { return runCompare(*a); }};
}

}  // namespace swingsim::cli
