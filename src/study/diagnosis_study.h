#pragma once
// Study YAML for `swingsim compare` and `swingsim diagnose`, one reader for both plants:
//   kind: cylinder-diagnosis | swing-diagnosis
//   name, description (optional), base_model (knee model YAML), train, validate (record CSV
//   lists, relative to the study), candidates (optional; default the plant's whole library,
//   model/effect_table.h), acceptance: {alpha, min_validation_improvement, max_effects,
//   whiteness_lags, measurement_noise (unit of the data; default: estimated from each
//   record), explained_noise_ratio (1.2)} (optional; frozen here before the run).
//   cylinder-diagnosis only: fit_switches (false), plot_seconds (2).
//   swing-diagnosis only: participant (participant YAML); motion_columns (required when a
//   train/validate file is an OpenSim .mot/.sto: io/motion_file.h, MotionColumns); drive
//   (hip_moment, the default: each record's hip moment drives it; thigh_kinematics: each
//   record's hip angle is prescribed: docs/winter.md).
// loadDiagnosisPlant reads the records and models a study names and builds its plant.
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "identify/diagnosis_engine.h"
#include "io/motion_file.h"
#include "model/leg_parameters.h"

namespace swingsim {

class YamlMap;

struct DiagnosisStudy {
  PlantKind plant = PlantKind::kCylinder;
  std::string path, name, description;
  std::string baseModelPath;          ///< resolved knee model YAML
  std::string participantPath;        ///< resolved participant YAML (swing)
  std::vector<std::string> train;     ///< resolved record paths (CSV, or .mot/.sto for a swing)
  std::vector<std::string> validate;  ///< resolved record paths (CSV, or .mot/.sto for a swing)
  std::optional<MotionColumns> motionColumns;  ///< swing: how .mot/.sto records are read
  EffectSelectionSettings settings;
  bool fitSwitches = false;           ///< cylinder: refit switch widths and xhy before the baseline
  double plotSeconds = 2.0;           ///< cylinder: s of each record shown in residual-vs-time plots
  double integratorTolerance = 1e-8;  ///< swing: reference integrator tolerance in every refit
  /// swing: `drive:` hip_moment (each record's measured hip moment drives the leg; the
  /// default) or thigh_kinematics (each record's measured hip angle is prescribed).
  SwingDrive drive = SwingDrive::kHipMoment;
};

/// What drives a swing study's model, for reports ("" for a cylinder study): "drive: each
/// record's measured hip moment" or "drive: each record's measured thigh angle, prescribed".
std::string describeStudyDrive(const DiagnosisStudy& study);

/// Reads a study of either kind (the `kind:` key decides). Throws InputError.
DiagnosisStudy readDiagnosisStudy(YamlMap& yaml);
/// Loads and reads a study file, rejecting unknown keys.
DiagnosisStudy loadDiagnosisStudy(const std::string& path);
/// The YAML text of a study as a file in folder `baseDir` (paths written relative to it).
std::string formatDiagnosisStudyYaml(const DiagnosisStudy& study, const std::string& baseDir);

/// Reads the study's base model, participant and records and builds its plant. Each
/// training record needs at least `extraTrainRows` rows more than the model has linear
/// coefficients (cylinder). Throws InputError.
std::unique_ptr<DiagnosisPlant> loadDiagnosisPlant(const DiagnosisStudy& study, std::size_t extraTrainRows);

}  // namespace swingsim
