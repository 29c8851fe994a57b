#pragma once
// Study YAML for `swingsim compare` and `swingsim diagnose` (issue 5):
//   kind: cylinder-diagnosis
//   name, description (optional), base_model (knee model YAML), train, validate (bench CSV
//   lists, relative to the study), candidates (optional; default the whole library),
//   fit_switches (optional, false), plot_seconds (optional, 2),
//   acceptance: {alpha, min_validation_improvement, max_effects, whiteness_lags} (optional;
//   the thresholds are frozen here before the run, defaults in CylinderDiagnosisSettings).
#include <string>
#include <vector>

#include "identify/cylinder_diagnosis.h"
#include "identify/swing_diagnosis.h"

namespace swingsim {

class YamlMap;

struct CylinderDiagnosisStudy {
  std::string path;
  std::string name;
  std::string baseModelPath;          ///< resolved
  std::vector<std::string> train;     ///< resolved bench CSV paths
  std::vector<std::string> validate;  ///< resolved bench CSV paths
  CylinderDiagnosisSettings settings;
  double plotSeconds = 2.0;           ///< s of each record shown in residual-vs-time plots
};

/// Reads a cylinder-diagnosis study (`kind` already read). Throws InputError
/// (`file:line: key: ...`), e.g. for an unknown candidate or an empty `validate`.
CylinderDiagnosisStudy readCylinderDiagnosisStudy(YamlMap& yaml);

/// kind: swing-diagnosis (docs/diagnosis.md): name, description, participant (YAML),
/// base_model (knee model YAML), train, validate (swing kinematics CSVs), candidates
/// (default: the swing library), acceptance (as above).
struct SwingDiagnosisStudy {
  std::string path, name, participantPath, baseModelPath;
  std::vector<std::string> train, validate;
  SwingDiagnosisSettings settings;
};
SwingDiagnosisStudy readSwingDiagnosisStudy(YamlMap& yaml);

}  // namespace swingsim
