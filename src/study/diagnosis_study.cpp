#include "study/diagnosis_study.h"

#include <algorithm>

#include "core/output_files.h"
#include "identify/cylinder_plant.h"
#include "identify/sweep_plant.h"
#include "identify/swing_plant.h"
#include "identify/user_cylinder_effect.h"
#include "io/bench_csv.h"
#include "io/knee_model_loader.h"
#include "io/moment_units_check.h"
#include "io/motion_columns_yaml.h"
#include "io/motion_file.h"
#include "io/participant_loader.h"
#include "io/sweep_times_csv.h"
#include "io/swing_record_csv.h"
#include "io/yaml_archive.h"
#include "io/yaml_reader.h"
#include "study/diagnosis_objects.h"
#include "study/sweep_study.h"

#include <cmath>
#include <cstdio>

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
  a.optionalNumber("max_effects", maxEffects,
                   [](double v) { return v == std::floor(v) ? inRange(v, 1, 6, "must be 1 to 6") : "must be 1 to 6"; });
  a.optionalNumber("whiteness_lags", lags, [](double v) {
    return v == std::floor(v) ? inRange(v, 1, 1000, "must be 1 to 1000") : "must be 1 to 1000";
  });
  st.maxEffects = static_cast<int>(maxEffects);
  st.whitenessLags = static_cast<int>(lags);
  // 0 is the internal "not set" (estimate it), not written; in a file it would mean no
  // noise, which makes the likelihood singular.
  if (A::kReading || st.measurementNoise > 0)
    a.optionalNumber("measurement_noise", st.measurementNoise, [](double v) {
      return v > 0 ? std::string()
                   : "expected a positive noise: 0 noise makes the likelihood singular; leave measurement_noise out to "
                     "estimate it from the data";
    });
  a.optionalNumber("explained_noise_ratio", st.explainedNoiseRatio,
                   [](double v) { return inRange(v, 1, 10, "must be in [1, 10]"); });
}

std::string StudyRecord::displayName() const { return name.empty() ? fileStem(path) : name; }

bool operator==(const StudyRecord& a, const StudyRecord& b) {
  return a.name == b.name && a.path == b.path && a.toeOffTime == b.toeOffTime &&
         a.heelContactTime == b.heelContactTime && a.swing == b.swing && a.inverseDynamicsPath == b.inverseDynamicsPath;
}

namespace {

/// A train/validate entry written as a plain file name (nothing else set).
bool isPlainRecord(const StudyRecord& r) {
  return r.name.empty() && !r.toeOffTime && !r.heelContactTime && !r.swing && r.inverseDynamicsPath.empty();
}

}  // namespace

/// One train/validate entry in its map form: {name, file, toe_off_s, heel_contact_s | swing, inverse_dynamics}.
template <class A>
void serialize(A& a, StudyRecord& r) {
  a.optionalText("name", r.name);
  a.path("file", r.path);
  if constexpr (A::kReading)
    a.require(isMotionFile(r.path) ||
                  (!a.has("toe_off_s") && !a.has("heel_contact_s") && !a.has("swing") && !a.has("inverse_dynamics")),
              "file",
              "toe_off_s, heel_contact_s, swing and inverse_dynamics cut an OpenSim .mot/.sto, not a CSV record",
              [&] { return r.path; });
  optionalSeconds(a, "toe_off_s", r.toeOffTime, {});
  optionalSeconds(a, "heel_contact_s", r.heelContactTime, {});
  if (r.toeOffTime && r.heelContactTime)
    a.require(*r.heelContactTime > *r.toeOffTime, "heel_contact_s",
              "must be after toe_off_s (" + formatNumber(*r.toeOffTime) + " s)",
              [&] { return formatNumber(*r.heelContactTime); });
  std::optional<double> swing;
  if (r.swing) swing = *r.swing;
  optionalSeconds(a, "swing", swing, mustBeSwingNumber);
  if (swing) r.swing = static_cast<int>(*swing);
  a.require(!r.swing || (!r.toeOffTime && !r.heelContactTime), "swing",
            "either swing (the K-th swing found in the file) or toe_off_s and heel_contact_s, not both",
            [&] { return std::to_string(r.swing.value_or(0)) + " with times"; });
  bool hasId = !r.inverseDynamicsPath.empty();
  if constexpr (A::kReading) hasId = a.has("inverse_dynamics");
  if (hasId) a.path("inverse_dynamics", r.inverseDynamicsPath);
}

template <class A>
void serialize(A& a, GrfSettings& g) {
  a.path("file", g.path);
  a.optionalText("vertical_force", g.verticalForce);
  a.optionalNumber("threshold_N", g.thresholdN,
                   [](double v) { return v > 0 && v < 1e4 ? "" : "must be in (0, 10000) N"; });
  if (A::kReading || g.fallbackToKinematics) a.optionalFlag("fallback_to_kinematics", g.fallbackToKinematics);
}

template <class A>
void serializeRecordStudy(A& a, DiagnosisStudy& s);
template <class A>
void serializeCandidates(A& a, DiagnosisStudy& s);

template <class A>
void serialize(A& a, DiagnosisStudy& s) {
  a.choice("kind", s.plant,
           {{"cylinder-diagnosis", PlantKind::kCylinder},
            {"swing-diagnosis", PlantKind::kSwing},
            {"sweep-diagnosis", PlantKind::kSweep}});
  if (s.plant == PlantKind::kSweep) {
    // The model is a sweep study's sweep; the measurement a table of swing times.
    a.path("sweep", s.sweepStudyPath);
    a.path("measured", s.measuredPath);
    a.optionalText("name", s.name);
    a.optionalText("description", s.description);
  } else {
    serializeRecordStudy(a, s);
  }
  serializeCandidates(a, s);
}

template <class A>
void serializeRecordStudy(A& a, DiagnosisStudy& s) {
  if (s.plant == PlantKind::kSwing) a.path("participant", s.participantPath);
  a.path("base_model", s.baseModelPath);
  a.optionalText("name", s.name);
  a.optionalText("description", s.description);
  a.pathOrMapList("train", s.train, &StudyRecord::path, isPlainRecord);
  a.pathOrMapList("validate", s.validate, &StudyRecord::path, isPlainRecord);
  a.require(!s.train.empty(), "train", "expected at least one CSV", [] { return std::string("an empty list"); });
  a.require(!s.validate.empty(), "validate", "expected at least one CSV (the acceptance rule needs held-out data)",
            [] { return std::string("an empty list"); });
  if (s.plant == PlantKind::kSwing) {
    if (A::kReading || s.drive != SwingDrive::kHipMoment)
      a.choice("drive", s.drive,
               {{"hip_moment", SwingDrive::kHipMoment}, {"thigh_kinematics", SwingDrive::kThighKinematics}}, true);
    bool hasMotionColumns = s.motionColumns.has_value();
    MotionColumns motion = s.motionColumns.value_or(MotionColumns{});
    a.optionalMap("motion_columns", motion, hasMotionColumns);
    if (hasMotionColumns) s.motionColumns = motion;
    bool hasGrf = s.grf.has_value();
    GrfSettings grf = s.grf.value_or(GrfSettings{});
    a.optionalMap("grf", grf, hasGrf);
    if (hasGrf) s.grf = grf;
    bool statesGait = s.gait.has_value();
    if constexpr (A::kReading) statesGait = a.has("gait");
    if (statesGait) {
      Gait gait = s.gait.value_or(Gait::kWalking);
      a.choice("gait", gait, {{"walking", Gait::kWalking}, {"running", Gait::kRunning}});
      s.gait = gait;
    }
    if (A::kReading || !s.movingHip) a.optionalFlag("moving_hip", s.movingHip);
    for (const auto& [key, list] : {std::pair{"train", &s.train}, std::pair{"validate", &s.validate}})
      for (const auto& r : *list) {
        const std::string& p = r.path;
        if (!isMotionFile(p)) continue;
        a.require(
            hasMotionColumns, key,
            "an OpenSim motion file needs the study's motion_columns map ({hip: NAME, knee: NAME, hip_moment: NAME}; "
            "docs/measured-data.md, \"Motion files and their columns\")",
            [&] { return p; });
        a.require(s.drive == SwingDrive::kThighKinematics || !motion.hipMoment.empty(), "motion_columns",
                  "hip_moment: expected the label of the hip moment column (N m), the drive the swing diagnosis needs",
                  [] { return std::string("no hip_moment key"); });
      }
  }
  std::vector<std::string> names;
  for (const auto& [key, list] : {std::pair{"train", &s.train}, std::pair{"validate", &s.validate}})
    for (const auto& r : *list) {
      a.require(s.plant == PlantKind::kSwing || isPlainRecord(r), key, "a cylinder study's records are file names",
                [&] { return "a map for " + r.path; });
      for (const auto& other : names)
        a.require(
            other != r.displayName(), key,
            "two records share the name '" + other + "' (results are keyed by name; give each entry a unique name:)",
            [&] { return r.path; });
      names.push_back(r.displayName());
    }
}

template <class A>
void serialize(A& a, UserEffectParameter& q) {
  a.optionalText("unit", q.unit);
  a.number("min", q.min);
  a.number("max", q.max);
  a.number("start", q.start);
}

// A user's effect among the candidates: a knee moment (identify/user_swing_effect.h) or a
// cylinder force (identify/user_cylinder_effect.h), checked and registered as it is read, so
// an error names its line.
template <class A>
void serialize(A& a, UserEffect& u) {
  a.text("name", u.name);
  if constexpr (A::kReading) {
    u.plant = a.has("cylinder_force_N") ? PlantKind::kCylinder : PlantKind::kSwing;
    a.require(!a.has("cylinder_force_N") || !a.has("knee_moment_Nm"), "cylinder_force_N",
              "expected one expression: knee_moment_Nm (a swing study) or cylinder_force_N (a cylinder study)",
              [] { return std::string("both"); });
  }
  const char* key = u.plant == PlantKind::kCylinder ? "cylinder_force_N" : "knee_moment_Nm";
  a.text(key, u.expression);
  a.namedMaps("parameters", u.parameters, &UserEffectParameter::name);
  if constexpr (A::kReading) {
    try {
      if (u.plant == PlantKind::kCylinder) {
        registerUserCylinderEffect(u);
      } else {
        registerUserSwingEffect(u);
      }
    } catch (const KneeExpressionError& e) {
      a.require(false, key, describeKneeExpressionError(u.expression, e), [&] { return u.expression; });
    } catch (const std::invalid_argument& e) {
      a.require(false, "parameters", e.what(), [&] { return u.name; });
    }
  }
}

// The candidates as written: library names as text, users' effects as maps.
template <class A>
void serializeCandidateList(A& a, DiagnosisStudy& s) {
  std::vector<UserEffect> entries;
  if constexpr (!A::kReading)
    for (const auto& n : s.settings.candidates) {
      auto user =
          std::find_if(s.userEffects.begin(), s.userEffects.end(), [&](const UserEffect& u) { return u.name == n; });
      entries.push_back(user != s.userEffects.end() ? *user : UserEffect{n, "", {}});
    }
  a.textOrMapList(
      "candidates", entries, &UserEffect::name, +[](const UserEffect& u) { return u.expression.empty(); },
      "an effect's name");
  if constexpr (A::kReading) {
    s.settings.candidates.clear();
    s.userEffects.clear();
    for (const auto& e : entries) {
      a.require(
          std::find(s.settings.candidates.begin(), s.settings.candidates.end(), e.name) == s.settings.candidates.end(),
          "candidates", "an effect named twice", [&] { return e.name; });
      a.require(e.expression.empty() || e.plant == s.plant, "candidates",
                s.plant == PlantKind::kSweep
                    ? "a sweep study names library effects (a user's expression is a swing's knee_moment_Nm or a "
                      "cylinder's cylinder_force_N)"
                    : "a " + plantName(s.plant) + " study's own effect is " +
                          (s.plant == PlantKind::kSwing ? "a knee moment (knee_moment_Nm)"
                                                        : "a cylinder force (cylinder_force_N)"),
                [&] { return e.name; });
      s.settings.candidates.push_back(e.name);
      if (!e.expression.empty()) s.userEffects.push_back(e);
    }
  }
}

template <class A>
void serializeCandidates(A& a, DiagnosisStudy& s) {
  // Candidates: all of the plant's effects unless the study names some.
  bool namesCandidates = !s.settings.candidates.empty();
  if constexpr (A::kReading) namesCandidates = a.has("candidates");
  if (namesCandidates) {
    serializeCandidateList(a, s);
    a.require(!s.settings.candidates.empty(), "candidates", "expected at least one effect",
              [] { return std::string("an empty list"); });
    std::string all;
    for (const auto& k : effectNames(s.plant)) all += (all.empty() ? "" : ", ") + k;
    for (const auto& c : s.settings.candidates)
      a.require(findEffect(s.plant, c) != nullptr, "candidates",
                "unknown " + plantName(s.plant) + " effect (known: " + all + ")" +
                    (s.plant == PlantKind::kSwing
                         ? "; or write your own as {name: NAME, knee_moment_Nm: EXPRESSION, "
                           "parameters: {P: {unit: U, min: A, max: B, start: C}}} (docs/diagnosis.md)"
                         : ""),
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
  return study.drive == SwingDrive::kThighKinematics
             ? "drive: each record's measured thigh angle, prescribed (thigh_kinematics)"
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

MotionColumns resolveRecordTimes(const StudyRecord& record, const MotionColumns& columns, const MotionTable& table,
                                 const std::optional<GrfSettings>& grf, std::optional<Gait> gait,
                                 std::vector<std::string>* notes) {
  MotionColumns out = columns;
  if (record.toeOffTime) out.toeOffTime = record.toeOffTime;
  if (record.heelContactTime) out.heelContactTime = record.heelContactTime;
  if (!record.swing) return out;
  // The K-th complete swing of the file: events from the GRF where it covers them, else
  // from the kinematics (io/swing_events.h).
  const SwingList list = listSwings(table, columns, grf, gait);
  if (notes)
    for (const std::string& n : list.notes) notes->push_back(record.displayName() + ": " + n);
  const FoundSwing swing = selectSwing(list, table, columns.knee, *record.swing);
  out.toeOffTime = swing.toeOff;
  out.heelContactTime = swing.heelContact;
  return out;
}

SwingRecord readStudyRecord(const DiagnosisStudy& study, const StudyRecord& entry, std::vector<std::string>& notes) {
  SwingRecord r;
  if (isMotionFile(entry.path)) {
    const MotionTable table = readMotionTable(entry.path);
    requireNamedColumns(table, *study.motionColumns, study.path + ": motion_columns");
    const MotionColumns columns = resolveRecordTimes(entry, *study.motionColumns, table, study.grf, study.gait, &notes);
    std::optional<MotionTable> id;
    if (!entry.inverseDynamicsPath.empty()) id = readMotionTable(entry.inverseDynamicsPath);
    r = makeSwingRecord(table, columns, id ? &*id : nullptr);
    for (auto& w : checkMotionRecord(r, table, columns)) notes.push_back(entry.displayName() + ": " + w);
  } else {
    r = readSwingRecord(entry.path);
  }
  r.stem = entry.displayName();
  return r;
}

std::unique_ptr<DiagnosisPlant> loadDiagnosisPlant(const DiagnosisStudy& study, std::size_t extraTrainRows,
                                                   const DiagnosisRowLimit* limit) {
  const auto announce = [&](std::uint64_t rows, std::size_t records) {
    if (limit) announceDiagnosisSize(study.name, study.path, study.plant, rows, records, *limit);
  };
  if (study.plant == PlantKind::kCylinder) {
    const MauchCylinderParams base = loadMauchCylinder(study.baseModelPath);
    const auto minRows = static_cast<std::size_t>(MauchCylinder(base).numCoefficients()) + extraTrainRows;
    std::vector<BenchData> train, validate;
    for (const auto& r : study.train) train.push_back(readBenchCsv(r.path, minRows));
    for (const auto& r : study.validate) validate.push_back(readBenchCsv(r.path, 3));
    std::uint64_t rows = 0;
    for (const auto* records : {&train, &validate})
      for (const auto& b : *records) rows += b.time.size();
    announce(rows, train.size() + validate.size());
    return std::make_unique<CylinderPlant>(base, std::move(train), std::move(validate), study.fitSwitches,
                                           study.plotSeconds);
  }
  if (study.plant == PlantKind::kSweep) {
    const SweepStudy sweep = loadSweepStudy(study.sweepStudyPath);
    std::vector<MeasuredSwingTime> measured = readSweepTimesCsv(study.measuredPath);
    announce(measured.size(), 1);
    // measurement_noise (ms) stands for the standard error of a row without sd_s.
    return std::make_unique<SweepPlant>(sweep, std::move(measured), study.measuredPath,
                                        study.settings.measurementNoise / 1000.0);
  }
  return makeSwingDiagnosisPlant(study, {}, limit);
}

std::vector<CommandFile> listDiagnosisStudyFiles(const DiagnosisStudy& study) {
  std::vector<CommandFile> files = {{"STUDY.yaml", study.path}};
  const auto add = [&](const std::string& key, const std::string& path) {
    if (!path.empty()) files.push_back({"STUDY.yaml: " + key, path});
  };
  add("base_model", study.baseModelPath);
  add("participant", study.participantPath);
  add("sweep", study.sweepStudyPath);
  add("measured", study.measuredPath);
  if (study.grf) add("grf", study.grf->path);
  for (const auto* set : {&study.train, &study.validate})
    for (const StudyRecord& r : *set) {
      const std::string which = (set == &study.train ? "train record " : "validate record ") + r.displayName();
      add(which, r.path);
      add(which + ": inverse_dynamics", r.inverseDynamicsPath);
    }
  return files;
}

}  // namespace swingsim
