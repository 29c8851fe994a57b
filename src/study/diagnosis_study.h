#pragma once
// Study YAML for `swingsim compare` and `swingsim diagnose`, one reader for both plants:
//   kind: cylinder-diagnosis | swing-diagnosis | sweep-diagnosis
//   name, description (optional), base_model (knee model YAML), train, validate (record CSV
//   lists, relative to the study), candidates (optional; default the plant's whole library,
//   identify/effect_table.h), acceptance: {alpha, min_validation_improvement, max_effects,
//   whiteness_lags, measurement_noise (unit of the data; default: estimated from each
//   record), explained_noise_ratio (1.2)} (optional; frozen here before the run).
//   cylinder-diagnosis only: fit_switches (false), plot_seconds (2).
//   swing-diagnosis only: participant (participant YAML); motion_columns (required when a
//   train/validate file is an OpenSim .mot/.sto: io/motion_file.h, MotionColumns); drive
//   (hip_moment, the default: each record's hip moment drives it; thigh_kinematics: each
//   record's hip angle is prescribed: docs/winter.md). A swing study's train/validate item is a
//   file name, or a map {name, file, toe_off_s, heel_contact_s | swing, inverse_dynamics}
//   (StudyRecord; docs/measured-data.md) so that several swings of one file are records.
//   sweep-diagnosis: sweep (a sweep study YAML: its participants, knee models and swing
//   options are the model) and measured (CSV participant,lowering_m,swing_time_s[,sd_s,n]:
//   io/sweep_times_csv.h) instead of base_model/train/validate; held-out data are the
//   participants, one at a time (identify/sweep_plant.h).
// loadDiagnosisPlant reads the records and models a study names and builds its plant.
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/output_paths.h"
#include "identify/diagnosis_engine.h"
#include "identify/user_swing_effect.h"
#include "io/motion_file.h"
#include "io/swing_events.h"
#include "model/leg_parameters.h"
#include "study/diagnosis_size.h"

namespace swingsim {

class YamlMap;

/// One train/validate entry: a file name, or (swing) a map naming one swing of a file.
struct StudyRecord {
  std::string name;  ///< unique in the study; default the file's stem
  std::string path;  ///< resolved record file (CSV, or .mot/.sto for a swing)
  /// s, file time: this swing's cut, overriding motion_columns' toe_off_s/heel_contact_s.
  std::optional<double> toeOffTime, heelContactTime;
  /// The K-th swing (1-based) found in the file, instead of the two times (resolveRecordTimes).
  std::optional<int> swing;
  std::string inverseDynamicsPath;  ///< resolved OpenSim ID .sto giving the knee moment ("" = none)
  /// The entry's name: `name`, or the file's stem.
  std::string displayName() const;
};
bool operator==(const StudyRecord& a, const StudyRecord& b);

struct DiagnosisStudy {
  PlantKind plant = PlantKind::kCylinder;
  std::string path, name, description;
  std::string baseModelPath;                   ///< resolved knee model YAML
  std::string participantPath;                 ///< resolved participant YAML (swing)
  std::string sweepStudyPath;                  ///< resolved sweep study YAML (sweep: the model)
  std::string measuredPath;                    ///< resolved measured swing times CSV (sweep)
  std::vector<StudyRecord> train;              ///< training records
  std::vector<StudyRecord> validate;           ///< held-out records
  std::optional<MotionColumns> motionColumns;  ///< swing: how .mot/.sto records are read
  /// swing: the GRF .mot whose vertical force gives `swing: K` records their events (`grf:`
  /// {file, vertical_force, threshold_N}); without it, or past its end, the kinematics do.
  std::optional<GrfSettings> grf;
  /// swing: the gait of the `swing: K` records (`gait:` walking or running), which picks the
  /// kinematic event rules; nullopt: detected from each file's stride (io/swing_events.h).
  std::optional<Gait> gait;
  /// swing, thigh drive: a record with pelvis columns moves the hip along the measured pelvis
  /// (`moving_hip`, default true); false pins the hip in space as Burkett did.
  bool movingHip = true;
  EffectSelectionSettings settings;
  /// swing and cylinder: the users' effects among `candidates:` (an expression each, registered when the
  /// study is read; settings.candidates names them in the list's order).
  std::vector<UserEffect> userEffects;
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

/// The motion columns that cut `record` from its file `table`: the study's, with the
/// entry's toe-off and heel-contact times, or those of its `swing: K` (events checked as
/// listSwings does, at `gait` or the one detected). Notes about the events (a force file that
/// gave way to the kinematics) go to `notes` when given. Throws InputError.
MotionColumns resolveRecordTimes(const StudyRecord& record, const MotionColumns& columns, const MotionTable& table,
                                 const std::optional<GrfSettings>& grf = std::nullopt,
                                 std::optional<Gait> gait = std::nullopt, std::vector<std::string>* notes = nullptr);

/// One swing record of a swing study: a CSV, or cut from an OpenSim file by the study's
/// motion_columns and the entry's times, with the knee moment of the entry's
/// inverse_dynamics; its stem is the entry's name. Appends warnings about the data (each
/// naming the key that fixes it) to `notes`. Throws InputError.
SwingRecord readStudyRecord(const DiagnosisStudy& study, const StudyRecord& entry, std::vector<std::string>& notes);

/// Reads the study's base model, participant and records and builds its plant. Each
/// training record needs at least `extraTrainRows` rows more than the model has linear
/// coefficients (cylinder). With `limit`, the rows read are counted, printed with an estimate
/// and held to the limit (announceDiagnosisSize) before the plant is built. Throws InputError.
std::unique_ptr<DiagnosisPlant> loadDiagnosisPlant(const DiagnosisStudy& study, std::size_t extraTrainRows,
                                                   const DiagnosisRowLimit* limit = nullptr);

/// Every file the study reads, each named by the key that names it ("STUDY.yaml: base_model",
/// "STUDY.yaml: train record NAME", ...), for checkOutputsAreNotInputs.
std::vector<CommandFile> listDiagnosisStudyFiles(const DiagnosisStudy& study);

}  // namespace swingsim
