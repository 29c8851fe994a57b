#include "study/cylinder_fit_run.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/progress_reporter.h"
#include "io/bench_csv.h"
#include "io/knee_model_loader.h"
#include "io/yaml_reader.h"

namespace swingsim {

namespace {

// A fitted constant or an error metric that is not finite is never reported as a result:
// the fit failed on these data (the loaders' plausible ranges catch absurd inputs first).
void checkFitFinite(const ModelEvaluation& r) {
  for (const auto& c : r.fit.constants)
    if (!std::isfinite(c.value))
      throw RunError(r.name + ": the fit gave a non-finite " + c.name + " (" + formatNumber(c.value) +
                     "): the training files do not determine the model");
  for (const auto& f : r.files)
    if (!std::isfinite(f.metrics.rmse) || !std::isfinite(f.metrics.maxError))
      throw RunError(r.name + ": " + (f.data ? f.data->path : std::string("a bench file")) +
                     ": the fitted model's force error is not finite (RMSE " + formatNumber(f.metrics.rmse) + " N)");
}

}  // namespace

CylinderFitRun runCylinderFits(const std::vector<std::string>& modelPaths, const std::vector<std::string>& trainPaths,
                               const std::vector<std::string>& validatePaths, bool fitSwitches) {
  std::vector<std::string> names;
  std::vector<MauchCylinderParams> models;
  std::size_t maxCoefficients = 0;
  for (const auto& path : modelPaths) {
    models.push_back(loadMauchCylinder(path));
    YamlMap m = YamlMap::loadFile(path);
    names.push_back(m.getString("name", fileStem(path)));
    maxCoefficients = std::max(maxCoefficients, static_cast<std::size_t>(3 * models.back().phases));
  }
  // Each training file alone must hold more samples than the largest model has coefficients.
  CylinderFitRun run;
  for (const auto& p : trainPaths) run.train.push_back(readBenchCsv(p, maxCoefficients + 1));
  for (const auto& p : validatePaths) run.validate.push_back(readBenchCsv(p, 3));

  for (std::size_t i = 0; i < models.size(); ++i) {
    CylinderFitOptions options;
    options.fitSwitches = fitSwitches;
    ProgressReporter progress(names[i] + ": fitting switch constants", "starts");
    options.progress = [&](int done, int total) { progress.update(done, total); };
    ModelEvaluation e;
    e.name = names[i];
    e.fit = fitCylinder(models[i], run.train, options);
    run.models.push_back(std::move(e));
  }
  for (auto& r : run.models) {
    r.files = evaluateFiles(MauchCylinder(r.fit.params), run.train, run.validate);
    checkFitFinite(r);
  }
  return run;
}

}  // namespace swingsim
