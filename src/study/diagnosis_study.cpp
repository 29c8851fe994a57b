#include "study/diagnosis_study.h"

#include "core/output_files.h"
#include "identify/cylinder_plant.h"
#include "identify/swing_plant.h"
#include "io/bench_csv.h"
#include "io/knee_model_loader.h"
#include "io/motion_file.h"
#include "io/participant_loader.h"
#include "io/yaml_archive.h"
#include "io/yaml_reader.h"

#include <cmath>

namespace swingsim {

// ---- The diagnosis study format, described once -------------------------------------------

namespace {

std::string inRange(double v, double lo, double hi, const char* what) { return v >= lo && v <= hi ? "" : what; }

}  // namespace

template <class A>
void serialize(A& a, EffectSelectionSettings& st) {
  a.optionalNumber("alpha", st.alpha, [](double v) { return v > 0 && v < 0.5 ? "" : "must be in (0, 0.5)"; });
  a.optionalNumber("min_validation_improvement", st.minValidationImprovement,
                   [](double v) { return v >= 0 && v < 1 ? "" : "must be in [0, 1)"; });
  double maxEffects = st.maxEffects, lags = st.whitenessLags;
  a.optionalNumber("max_effects", maxEffects, [](double v) { return v == std::floor(v) ? inRange(v, 1, 6, "must be 1 to 6") : "must be 1 to 6"; });
  a.optionalNumber("whiteness_lags", lags, [](double v) { return v == std::floor(v) ? inRange(v, 1, 1000, "must be 1 to 1000") : "must be 1 to 1000"; });
  st.maxEffects = static_cast<int>(maxEffects);
  st.whitenessLags = static_cast<int>(lags);
  a.optionalNumber("measurement_noise", st.measurementNoise, mustBeNonNegative);
  a.optionalNumber("explained_noise_ratio", st.explainedNoiseRatio, [](double v) { return inRange(v, 1, 10, "must be in [1, 10]"); });
}

namespace {

/// An optional number that is written only when set (no default stands for "absent").
template <class A>
void optionalSeconds(A& a, const char* key, std::optional<double>& v, const ValueCheck& check) {
  bool present = v.has_value();
  if constexpr (A::kReading) present = a.has(key);
  if (!present) return;
  double x = v.value_or(0);
  a.optionalNumber(key, x, check);
  v = x;
}

std::string mustBeSign(double v) { return v == 1 || v == -1 ? "" : "must be 1 or -1"; }
std::string mustBeOffset(double deg) { return inRange(deg, -180, 180, "must be in [-180, 180] deg"); }

}  // namespace

/// The motion_columns map: which columns of a .mot/.sto file make a swing record.
template <class A>
void serialize(A& a, MotionColumns& c) {
  a.text("hip", c.hip);
  a.text("knee", c.knee);
  a.optionalText("hip_moment", c.hipMoment);
  a.optionalNumber("hip_sign", c.hipSign, mustBeSign);
  a.optionalNumber("knee_sign", c.kneeSign, mustBeSign);
  a.optionalAngle("hip_offset_deg", c.hipOffset, mustBeOffset);
  a.optionalAngle("knee_offset_deg", c.kneeOffset, mustBeOffset);
  optionalSeconds(a, "toe_off_s", c.toeOffTime, {});
  optionalSeconds(a, "heel_contact_s", c.heelContactTime, {});
  if (c.toeOffTime && c.heelContactTime)
    a.require(*c.heelContactTime > *c.toeOffTime, "heel_contact_s",
              "must be after toe_off_s (" + formatNumber(*c.toeOffTime) + " s)", [&] { return formatNumber(*c.heelContactTime); });
  // 10 us to 100 ms: a bench's 100 kHz at most, and a swing of 0.4 s still gets 5 samples.
  optionalSeconds(a, "resample_s", c.resampleInterval, [](double v) { return inRange(v, 1e-5, 0.1, "must be in [1e-5, 0.1] s"); });
}

template <class A>
void serialize(A& a, DiagnosisStudy& s) {
  a.choice("kind", s.plant, {{"cylinder-diagnosis", PlantKind::kCylinder}, {"swing-diagnosis", PlantKind::kSwing}});
  if (s.plant == PlantKind::kSwing) a.path("participant", s.participantPath);
  a.path("base_model", s.baseModelPath);
  a.optionalText("name", s.name);
  a.optionalText("description", s.description);
  a.paths("train", s.train);
  a.paths("validate", s.validate);
  a.require(!s.train.empty(), "train", "expected at least one CSV", [] { return std::string("an empty list"); });
  a.require(!s.validate.empty(), "validate", "expected at least one CSV (the acceptance rule needs held-out data)",
            [] { return std::string("an empty list"); });
  if (s.plant == PlantKind::kSwing) {
    if (A::kReading || s.drive != SwingDrive::kHipMoment)
      a.choice("drive", s.drive, {{"hip_moment", SwingDrive::kHipMoment}, {"thigh_kinematics", SwingDrive::kThighKinematics}},
               true);
    bool hasMotionColumns = s.motionColumns.has_value();
    MotionColumns motion = s.motionColumns.value_or(MotionColumns{});
    a.optionalMap("motion_columns", motion, hasMotionColumns);
    if (hasMotionColumns) s.motionColumns = motion;
    for (const auto& [key, list] : {std::pair{"train", &s.train}, std::pair{"validate", &s.validate}})
      for (const auto& p : *list) {
        if (!isMotionFile(p)) continue;
        a.require(hasMotionColumns, key,
                  "an OpenSim motion file needs the study's motion_columns map ({hip: NAME, knee: NAME, hip_moment: NAME}; "
                  "README \"File formats\")", [&] { return p; });
        a.require(s.drive == SwingDrive::kThighKinematics || !motion.hipMoment.empty(), "motion_columns",
                  "hip_moment: expected the label of the hip moment column (N m), the drive the swing diagnosis needs",
                  [] { return std::string("no hip_moment key"); });
      }
  }
  std::vector<std::string> stems;
  for (const auto* list : {&s.train, &s.validate})
    for (const auto& p : *list) {
      for (const auto& other : stems)
        a.require(other != fileStem(p), "validate", "two files share the stem '" + other + "' (results are keyed by stem)",
                  [&] { return p; });
      stems.push_back(fileStem(p));
    }
  // Candidates: all of the plant's effects unless the study names some.
  bool namesCandidates = !s.settings.candidates.empty();
  if constexpr (A::kReading) namesCandidates = a.has("candidates");
  if (namesCandidates) {
    a.texts("candidates", s.settings.candidates);
    a.require(!s.settings.candidates.empty(), "candidates", "expected at least one effect", [] { return std::string("an empty list"); });
    std::string all;
    for (const auto& k : effectNames(s.plant)) all += (all.empty() ? "" : ", ") + k;
    for (const auto& c : s.settings.candidates)
      a.require(findEffect(s.plant, c) != nullptr, "candidates", "unknown " + plantName(s.plant) + " effect (known: " + all + ")",
                [&] { return c; });
  }
  bool acceptance = true;
  a.optionalMap("acceptance", s.settings, acceptance);
  if (s.plant == PlantKind::kCylinder) {
    a.optionalFlag("fit_switches", s.fitSwitches);
    a.optionalNumber("plot_seconds", s.plotSeconds, mustBePositive);
  }
}

std::string describeStudyDrive(const DiagnosisStudy& study) {
  if (study.plant != PlantKind::kSwing) return "";
  return study.drive == SwingDrive::kThighKinematics ? "drive: each record's measured thigh angle, prescribed (thigh_kinematics)"
                                                     : "drive: each record's measured hip moment (hip_moment)";
}

DiagnosisStudy readDiagnosisStudy(YamlMap& yaml) {
  DiagnosisStudy s;
  s.path = yaml.path();
  YamlReadArchive a(yaml);
  serialize(a, s);
  if (s.name.empty()) s.name = fileStem(yaml.path());
  return s;
}

std::string formatDiagnosisStudyYaml(const DiagnosisStudy& study, const std::string& baseDir) {
  return writeYamlDocument(study, baseDir, "");
}

DiagnosisStudy loadDiagnosisStudy(const std::string& path) {
  YamlMap yaml = YamlMap::loadFile(path);
  DiagnosisStudy s = readDiagnosisStudy(yaml);
  yaml.finish();
  return s;
}

std::unique_ptr<DiagnosisPlant> loadDiagnosisPlant(const DiagnosisStudy& study, std::size_t extraTrainRows) {
  if (study.plant == PlantKind::kCylinder) {
    const MauchCylinderParams base = loadMauchCylinder(study.baseModelPath);
    const auto minRows = static_cast<std::size_t>(MauchCylinder(base).numCoefficients()) + extraTrainRows;
    std::vector<BenchData> train, validate;
    for (const auto& p : study.train) train.push_back(readBenchCsv(p, minRows));
    for (const auto& p : study.validate) validate.push_back(readBenchCsv(p, 3));
    return std::make_unique<CylinderPlant>(base, std::move(train), std::move(validate), study.fitSwitches,
                                           study.plotSeconds);
  }
  SwingBase base;
  base.participant = loadParticipant(study.participantPath);
  base.knee = loadKneeModel(study.baseModelPath);
  base.drive = study.drive;
  std::vector<SwingRecord> train, validate;
  for (const auto* paths : {&study.train, &study.validate})
    for (const auto& p : *paths) {
      SwingRecord r = readSwingRecordFile(p, study.motionColumns);
      if (study.drive == SwingDrive::kHipMoment && r.hipMoment.empty())
        throw InputError(p + ": no hip moment column (hip_moment_Nm, or motion_columns: hip_moment), which the swing "
                         "diagnosis with drive: hip_moment needs (with only angles measured, set drive: thigh_kinematics)");
      (paths == &study.train ? train : validate).push_back(std::move(r));
    }
  return std::make_unique<SwingPlant>(std::move(base), std::move(train), std::move(validate), study.integratorTolerance);
}

}  // namespace swingsim
