// swingsim diagnose STUDY.yaml [--out DIR] [--json FILE] [--save-model FILE]: compare, rank
// candidate missing physical effects, add the accepted ones, refit, and report the error
// before and after, for either plant (docs/diagnosis.md). All inputs are read before any output.
#include <cstdio>

#include "cli/command_registry.h"
#include "core/input_error.h"
#include "core/output_files.h"
#include "report/diagnosis_report.h"
#include "study/diagnosed_model_writer.h"
#include "study/diagnosis_study.h"

namespace swingsim::cli {

namespace {

int runDiagnose(const Arguments& args) {
  if (args.positional().size() != 1) throw UsageError("expected one STUDY.yaml");
  const DiagnosisStudy study = loadDiagnosisStudy(args.positional()[0]);
  const auto plant = loadDiagnosisPlant(study, 8);

  const Diagnosis dg = runDiagnosis(*plant, study.settings);
  for (const auto& w : dg.warnings) std::fprintf(stderr, "swingsim diagnose: warning: %s\n", w.c_str());
  const Comparison before = plant->compare(*dg.baseline.model);
  const Comparison after = plant->compare(*dg.final.model);
  const std::string report = formatDiagnosisText(dg, before, after);
  const std::string check = plant->verify(*dg.final.model);
  std::printf("%s: %s, %zu training file(s)\n", study.name.c_str(), fileStem(study.baseModelPath).c_str(),
              study.train.size());
  std::printf("where the base model fails (before):\n%s\n%s", formatComparisonTable(before).c_str(), report.c_str());
  if (!check.empty()) std::printf("%s\n", check.c_str());

  const std::string command = args.commandLine("diagnose");
  const std::string outDir = args.get("--out", "out/" + study.name);
  std::string md = "# swingsim diagnose: " + study.name + "\n\nCommand: `" + command + "`\n\n## Before\n\n```\n" +
                   formatComparisonTable(before) + "```\n\n## Ranking and result\n\n```\n" + report +
                   (check.empty() ? "" : check + "\n") + "```\n\n## After\n\n```\n" + formatComparisonTable(after) +
                   "```\n\n## Residual plots\n\n";
  for (const auto& p : writeResidualPlots(outDir, "before", before))
    md += "- before: [" + fileStem(p) + "](" + fileStem(p) + ".svg)\n";
  for (const auto& p : writeResidualPlots(outDir, "after", after))
    md += "- after: [" + fileStem(p) + "](" + fileStem(p) + ".svg)\n";
  writeFileAtomic(outDir + "/report.md", md);
  std::printf("report: %s/report.md (residual plots before-*.svg, after-*.svg)\n", outDir.c_str());
  if (args.has("--json")) writeJsonFile(args.get("--json"), makeDiagnosisJson(dg, before, after));
  if (args.has("--save-model") && !dg.explained)
    throw RunError("diagnose: --save-model: not saved: the diagnosed model does not explain the data (" + dg.verdict + ")");
  if (args.has("--save-model")) {
    const auto written = saveDiagnosedModel(study, *plant, dg, args.get("--save-model"), command);
    for (const auto& p : written) std::printf("model: %s\n", p.c_str());
  }
  return 0;
}

static Registrar reg("diagnose", {"rank candidate missing physical effects, add the accepted ones, report the error before and after",
                                  "STUDY.yaml", "study of kind cylinder-diagnosis or swing-diagnosis",
                                  {{"--out", "output folder (default out/<study name>/)"}, {"--json", "also write the machine-readable result to this JSON file"},
                                   {"--save-model", "write the diagnosed model here (knee model YAML; the swing also writes "
                                                    "FILE-participant.yaml); only when the data are explained"}},
                                  runDiagnose});

}  // namespace

}  // namespace swingsim::cli
