#pragma once
// Reports of `swingsim fit`: the Table-2-like text table, the --json result, and the report
// directory (Markdown, coefficient CSV, SVG plots of force over time with phases shaded and
// switch traces below, as Chien 2014 Figs. 5-6, and force-position loops).
#include <string>
#include <vector>

#include "identify/bench_data.h"
#include "identify/cylinder_fit.h"
#include "numerics/metrics.h"

namespace swingsim {

/// One bench file evaluated with one fitted model.
struct FileEvaluation {
  const BenchData* data = nullptr;
  bool training = false;
  CylinderTrace trace;   ///< predicted force and switches
  ErrorMetrics metrics;  ///< measured vs predicted force
};

/// One model of a fit study, fitted and evaluated.
struct ModelEvaluation {
  std::string name;  ///< model name (YAML `name:` or file stem)
  CylinderFit fit;
  std::vector<FileEvaluation> files;
};

/// Evaluates a fitted model on bench files.
std::vector<FileEvaluation> evaluateFiles(const MauchCylinder& cylinder, const std::vector<BenchData>& train,
                                          const std::vector<BenchData>& validate);

/// The printed summary: coefficients with standard errors, then ME / RMSE / R^2 (%) per
/// model and file, laid out like Chien 2014 Table 2.
std::string formatFitTable(const std::vector<ModelEvaluation>& models);

/// `{"models": [{"model", "coefficients": [{"phase", "f_N", "k_N_per_m", "c_Ns_per_m"}],
/// "metrics": {"<stem>": {"me_N", "rmse_N", "r2"}}}]}` with r2 a fraction.
std::string formatFitJson(const std::vector<ModelEvaluation>& models);

/// Writes report.md, coefficients.csv and per model and file `<model>-<stem>-force.svg`
/// and `<model>-<stem>-loop.svg` into `outDir` (atomically, file by file).
void writeFitReport(const std::string& outDir, const std::string& studyName, const std::string& command,
                    const std::vector<ModelEvaluation>& models, double plotSeconds);

}  // namespace swingsim
