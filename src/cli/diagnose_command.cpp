// swingsim diagnose STUDY.yaml [--out DIR] [--json FILE] [--save-model FILE]: compare, rank
// candidate missing physical effects, add the accepted ones, refit, and report the error
// before and after (issue 5, docs/diagnosis.md). All inputs are read before any output.
#include <cstdio>

#include "io/bench_csv.h"
#include "cli/command_registry.h"
#include "cli/swing_diagnosis_cli.h"
#include "identify/cylinder_diagnosis.h"
#include "study/diagnosis_study.h"
#include "io/knee_model_loader.h"
#include "io/knee_model_writer.h"
#include "core/output_files.h"
#include "io/yaml_reader.h"
#include "report/diagnosis_report.h"

namespace swingsim::cli {

namespace {

int runDiagnose(const std::vector<std::string>& argv) {
  const Arguments args(argv, {"--out", "--json", "--save-model"});
  if (args.positional().size() != 1) throw UsageError("expected one STUDY.yaml");
  YamlMap yaml = YamlMap::loadFile(args.positional()[0]);
  if (!yaml.has("kind")) yaml.getString("kind");
  if (yaml.getChoice("kind", {"cylinder-diagnosis", "swing-diagnosis"}, "") == "swing-diagnosis")
    return runSwingDiagnose(yaml, args, argv);
  const CylinderDiagnosisStudy study = readCylinderDiagnosisStudy(yaml);
  yaml.finish();
  const MauchCylinderParams base = loadMauchCylinder(study.baseModelPath);
  MauchModelText text;
  {
    YamlMap m = YamlMap::loadFile(study.baseModelPath);
    text.name = m.getString("name", fileStem(study.baseModelPath)) + "-diagnosed";
    text.flexionDial = m.getDouble("flexion_dial_deg");
    text.extensionDial = m.getDouble("extension_dial_deg");
    text.stop = readHyperextensionStop(m);
  }
  std::vector<BenchData> train, validate;
  for (const auto& p : study.train)
    train.push_back(readBenchCsv(p, static_cast<std::size_t>(MauchCylinder(base).numCoefficients()) + 8));
  for (const auto& p : study.validate) validate.push_back(readBenchCsv(p, 3));

  const CylinderDiagnosis dg = diagnoseCylinder(base, train, validate, study.settings);
  for (const auto& w : dg.warnings) std::fprintf(stderr, "swingsim diagnose: warning: %s\n", w.c_str());
  const CylinderComparison before = compareCylinder(dg.baseline, train, validate);
  const CylinderComparison after = compareCylinder(dg.final, train, validate);
  const std::string report = formatDiagnosisText(dg, before, after);
  std::printf("%s: %s, base model refitted on %zu training file(s)\n", study.name.c_str(),
              fileStem(study.baseModelPath).c_str(), train.size());
  std::printf("where the base model fails (before):\n%s\n%s", formatComparisonTable(before).c_str(), report.c_str());

  const std::string outDir = args.get("--out", "out/" + study.name);
  std::string md = "# swingsim diagnose: " + study.name + "\n\nCommand: `swingsim diagnose";
  for (const auto& a : argv) md += " " + a;
  md += "`\n\n## Before\n\n```\n" + formatComparisonTable(before) + "```\n\n## Ranking and result\n\n```\n" + report +
        "```\n\n## After\n\n```\n" + formatComparisonTable(after) + "```\n\n## Residual plots\n\n";
  for (const auto& p : writeResidualPlots(outDir, "before", before, study.plotSeconds))
    md += "- before: [" + fileStem(p) + "](" + fileStem(p) + ".svg)\n";
  for (const auto& p : writeResidualPlots(outDir, "after", after, study.plotSeconds))
    md += "- after: [" + fileStem(p) + "](" + fileStem(p) + ".svg)\n";
  writeFileAtomic(outDir + "/report.md", md);
  std::printf("report: %s/report.md (residual plots before-*.svg, after-*.svg)\n", outDir.c_str());
  if (args.has("--json")) writeFileAtomic(args.get("--json"), formatDiagnosisJson(dg, before, after));
  if (args.has("--save-model")) {
    std::string accepted;
    for (const auto& a : dg.accepted) accepted += (accepted.empty() ? "" : ", ") + a;
    text.description = "Augmented by swingsim diagnose (" + study.name + "): " + (accepted.empty() ? "no effect" : accepted);
    text.header = "Written by swingsim diagnose " + args.positional()[0] + "\nbase model: " + study.baseModelPath +
                  "\naccepted effects: " + (accepted.empty() ? "none" : accepted) +
                  "\ncoefficients refitted on the study's training files";
    writeFileAtomic(args.get("--save-model"), formatMauchModelYaml(dg.final, text));
    std::printf("model: %s\n", args.get("--save-model").c_str());
  }
  return 0;
}

static Registrar reg("diagnose", {"diagnose STUDY.yaml [--out DIR] [--json FILE] [--save-model FILE]",
                                  "rank candidate missing physical effects, add the accepted ones, report the error before and after",
                                  runDiagnose});

}  // namespace

}  // namespace swingsim::cli
