// swingsim fit STUDY.yaml [--out DIR] [--json FILE]: fit Mauch cylinder models to bench
// data and validate them on held-out conditions (Chien 2014 procedure). All inputs are read
// and checked before anything is written.
#include <cstdio>
#include <optional>
#include <string>

#include "io/bench_csv.h"
#include "cli/command.h"
#include "identify/bench_data.h"
#include "identify/cylinder_fit.h"
#include "study/cylinder_study.h"
#include "core/input_error.h"
#include "io/knee_model_loader.h"
#include "core/output_files.h"
#include "core/progress_reporter.h"
#include "io/yaml_reader.h"
#include "report/cylinder_fit_report.h"

namespace swingsim::cli {

namespace {

/// What `swingsim fit` was given; nullopt: not given (the default applies).
struct FitArguments {
  std::string study;
  std::optional<std::string> out, json;
};

int runFit(const FitArguments& args, const std::string& command) {
  YamlMap yaml = YamlMap::loadFile(args.study);
  if (!yaml.has("kind")) yaml.getString("kind");
  yaml.getChoice("kind", {"cylinder-fit"}, "");
  const CylinderFitStudy study = readCylinderFitStudy(yaml);
  yaml.finish();

  std::vector<std::string> names;
  std::vector<MauchCylinderParams> models;
  std::size_t maxCoefficients = 0;
  for (const auto& path : study.models) {
    models.push_back(loadMauchCylinder(path));
    YamlMap m = YamlMap::loadFile(path);
    names.push_back(m.getString("name", fileStem(path)));
    maxCoefficients = std::max(maxCoefficients, static_cast<std::size_t>(3 * models.back().phases));
  }
  // Each training file alone must hold more samples than the largest model has coefficients.
  std::vector<BenchData> train, validate;
  for (const auto& p : study.train) train.push_back(readBenchCsv(p, maxCoefficients + 1));
  for (const auto& p : study.validate) validate.push_back(readBenchCsv(p, 3));

  std::vector<ModelEvaluation> results;
  for (std::size_t i = 0; i < models.size(); ++i) {
    CylinderFitOptions options;
    options.fitSwitches = study.fitSwitches;
    ProgressReporter progress(names[i] + ": fitting switch constants", "starts");
    options.progress = [&](int done, int total) { progress.update(done, total); };
    ModelEvaluation e;
    e.name = names[i];
    e.fit = fitCylinder(models[i], train, options);
    results.push_back(std::move(e));
  }
  for (auto& r : results) r.files = evaluateFiles(MauchCylinder(r.fit.params), train, validate);

  std::printf("%s", formatFitTable(results).c_str());
  for (const auto& r : results)
    for (const auto& w : r.fit.warnings) std::fprintf(stderr, "swingsim fit: warning: %s: %s\n", r.name.c_str(), w.c_str());

  const std::string outDir = args.out.value_or("out/" + makeSafeFileStem(study.name));
  writeFitReport(outDir, study.name, command, results, study.plotSeconds);
  if (args.json) writeFileAtomic(*args.json, formatFitJson(results));
  std::printf("report: %s/report.md\n", outDir.c_str());
  return 0;
}

}  // namespace

Command addFitCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("fit", "fit Mauch cylinder models to bench data and validate them on held-out files");
  auto a = std::make_shared<FitArguments>();
  sub->add_option("STUDY.yaml", a->study, "study of kind cylinder-fit")->required()->type_name("");
  addStudyOutOption(sub, a->out);
  addJsonOption(sub, a->json);
  return {sub, [a, sub] { return runFit(*a, formatCommandLine(*sub)); }};
}

}  // namespace swingsim::cli
