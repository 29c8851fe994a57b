// swingsim compare STUDY.yaml [--out DIR] [--json FILE]: model vs measurement. The base
// model's coefficients are refitted on the training files (as diagnose's baseline), then
// metrics overall and per phase and residual plots show where and when it fails.
#include <cstdio>

#include "io/bench_csv.h"
#include "cli/command_registry.h"
#include "cli/swing_diagnosis_cli.h"
#include "identify/cylinder_diagnosis.h"
#include "study/diagnosis_study.h"
#include "io/knee_model_loader.h"
#include "core/output_files.h"
#include "io/yaml_reader.h"
#include "report/diagnosis_report.h"

namespace swingsim::cli {

namespace {

int runCompare(const std::vector<std::string>& argv) {
  const Arguments args(argv, {"--out", "--json"});
  if (args.positional().size() != 1) throw UsageError("expected one STUDY.yaml");
  YamlMap yaml = YamlMap::loadFile(args.positional()[0]);
  if (!yaml.has("kind")) yaml.getString("kind");
  if (yaml.getChoice("kind", {"cylinder-diagnosis", "swing-diagnosis"}, "") == "swing-diagnosis")
    return runSwingCompare(yaml, args);
  const CylinderDiagnosisStudy study = readCylinderDiagnosisStudy(yaml);
  yaml.finish();
  const MauchCylinderParams base = loadMauchCylinder(study.baseModelPath);
  std::vector<BenchData> train, validate;
  for (const auto& p : study.train)
    train.push_back(readBenchCsv(p, static_cast<std::size_t>(MauchCylinder(base).numCoefficients()) + 1));
  for (const auto& p : study.validate) validate.push_back(readBenchCsv(p, 3));

  CylinderFitOptions options;
  options.fitSwitches = study.settings.fitSwitches;
  const CylinderFit fit = fitCylinder(base, train, options);
  for (const auto& w : fit.warnings) std::fprintf(stderr, "swingsim compare: warning: %s\n", w.c_str());
  const CylinderComparison cmp = compareCylinder(fit.params, train, validate);
  std::printf("%s: %s refitted on %zu training file(s)\n", study.name.c_str(), fileStem(study.baseModelPath).c_str(),
              train.size());
  std::printf("%s", formatComparisonTable(cmp).c_str());
  ResidualSegments seg;
  for (const auto& r : cmp.records)
    if (r.training) seg.push_back(r.residual);
  const WhitenessTest wt = calcWhitenessTest(seg, study.settings.whitenessLags);
  std::printf("training residual: Ljung-Box Q = %.1f over %d lags (p = %.3g), %d lags outside the 99 %% band: %s\n",
              wt.q, wt.lags, wt.pValue, wt.lagsOutsideBand,
              wt.pValue < study.settings.alpha ? "structure left (not white)" : "consistent with white noise");
  const std::string outDir = args.get("--out", "out/" + study.name);
  for (const auto& p : writeResidualPlots(outDir, "compare", cmp, study.plotSeconds)) std::printf("plot: %s\n", p.c_str());
  if (args.has("--json")) writeFileAtomic(args.get("--json"), formatComparisonJson(fileStem(study.baseModelPath), cmp));
  return 0;
}

static Registrar reg("compare", {"compare STUDY.yaml [--out DIR] [--json FILE]",
                                 "model vs measurement: metrics overall and per phase, residual plots",
                                 runCompare});

}  // namespace

}  // namespace swingsim::cli
