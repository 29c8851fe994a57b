#pragma once
// The run of a cylinder fit study (`swingsim fit`, Python `swingsim.fit`): each Mauch model
// fitted to the training bench files and evaluated on the training and validation files.
#include <string>
#include <vector>

#include "report/cylinder_fit_report.h"

namespace swingsim {

/// The bench files of a fit study and each model fitted and evaluated on them. The
/// evaluations point into `train` and `validate` (FileEvaluation::data): a run can be
/// moved (a vector's move keeps its elements where they are) but not copied.
struct CylinderFitRun {
  std::vector<BenchData> train, validate;
  std::vector<ModelEvaluation> models;

  CylinderFitRun() = default;
  CylinderFitRun(CylinderFitRun&&) = default;
  CylinderFitRun& operator=(CylinderFitRun&&) = default;
  CylinderFitRun(const CylinderFitRun&) = delete;
  CylinderFitRun& operator=(const CylinderFitRun&) = delete;
};

/// Loads the models and bench files (paths resolved), fits each model with
/// `fitSwitches` as the study says, and evaluates it on every file. Each training file
/// must hold more samples than the largest model has coefficients. A progress bar per model
/// on stderr while its switch constants are fitted. Throws InputError for a bad file.
CylinderFitRun runCylinderFits(const std::vector<std::string>& modelPaths, const std::vector<std::string>& trainPaths,
                               const std::vector<std::string>& validatePaths, bool fitSwitches);

}  // namespace swingsim
