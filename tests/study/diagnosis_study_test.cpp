#include "study/diagnosis_study.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "../io/opensim_trials.h"
#include "core/input_error.h"
#include "core/units.h"
#include "io/yaml_reader.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;

DiagnosisStudy parse(const std::string& text, const std::string& path) {
  YamlMap yaml = YamlMap::loadString(text, path);
  DiagnosisStudy s = readDiagnosisStudy(yaml);
  yaml.finish();
  return s;
}

// Round trip: both demo studies and one with every optional key load -> write -> load to
// the same study, and writing again gives the same text.
TEST(DiagnosisStudyFormat, LoadWriteLoadGivesTheSameStudy) {
  std::vector<DiagnosisStudy> studies = {loadDiagnosisStudy(kRoot + "/studies/diagnose-demo-cylinder.yaml"),
                                         loadDiagnosisStudy(kRoot + "/studies/diagnose-demo-swing.yaml")};
  DiagnosisStudy custom = studies.front();
  custom.description = "every optional key";
  custom.settings.candidates = {"inertia", "switch_delay"};
  custom.settings.alpha = 0.05;
  custom.settings.maxEffects = 2;
  custom.settings.measurementNoise = 25;
  custom.settings.explainedNoiseRatio = 1.5;
  custom.fitSwitches = true;
  custom.plotSeconds = 1.25;
  studies.push_back(custom);
  const std::string dir = kRoot + "/studies";
  for (const DiagnosisStudy& s : studies) {
    const std::string text = formatDiagnosisStudyYaml(s, dir);
    const DiagnosisStudy back = parse(text, dir + "/roundtrip.yaml");
    EXPECT_EQ(formatDiagnosisStudyYaml(back, dir), text) << s.name;
    EXPECT_EQ(back.plant, s.plant);
    EXPECT_EQ(back.name, s.name);
    EXPECT_EQ(back.train, s.train);
    EXPECT_EQ(back.validate, s.validate);
    EXPECT_EQ(back.baseModelPath, s.baseModelPath);
    EXPECT_EQ(back.participantPath, s.participantPath);
    EXPECT_EQ(back.settings.candidates, s.settings.candidates);
    EXPECT_EQ(back.settings.alpha, s.settings.alpha);
    EXPECT_EQ(back.settings.maxEffects, s.settings.maxEffects);
    EXPECT_EQ(back.settings.measurementNoise, s.settings.measurementNoise);
    EXPECT_EQ(back.settings.explainedNoiseRatio, s.settings.explainedNoiseRatio);
    EXPECT_EQ(back.fitSwitches, s.fitSwitches);
    EXPECT_EQ(back.plotSeconds, s.plotSeconds);
  }
}

TEST(DiagnosisStudyFormat, UnknownCandidateNamesThePlantsEffects) {
  const std::string text =
      "kind: swing-diagnosis\nparticipant: ../participants/p1.yaml\n"
      "base_model: ../models/damping-table-default.yaml\ntrain: [a.csv]\nvalidate: [b.csv]\n"
      "candidates: [coulomb_friction]\n";
  try {
    parse(text, kRoot + "/studies/bad.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.yaml:6: candidates: unknown swing effect (known: knee_coulomb_friction"),
              std::string::npos)
        << e.what();
  }
}

// ---- OpenSim motion files in a swing diagnosis (motion_columns) ---------------------------

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// A swing as OpenSim writes it: knee_angle_r negative in flexion, 100 Hz, 0.6 s trial.
double trialHipDeg(double t) { return -15 + 35 * (1 - std::cos(kPi * t / 0.6)) / 2; }
double trialKneeFlexionDeg(double t) { return 5 + 60 * std::sin(kPi * t / 0.6); }

std::string trialSto() {
  std::string text =
      "trial\nversion=1\nnRows=61\nnColumns=4\ninDegrees=yes\nendheader\n"
      "time\thip_flexion_r\tknee_angle_r\thip_moment\n";
  char row[160];
  for (int k = 0; k <= 60; ++k) {
    const double t = k * 0.01;
    std::snprintf(row, sizeof row, "%.17g\t%.17g\t%.17g\t%.17g\n", t, trialHipDeg(t), -trialKneeFlexionDeg(t),
                  20 * std::cos(2 * kPi * t / 0.6));
    text += row;
  }
  return text;
}

/// A fresh folder holding train.sto and val.mot, and `study` as study.yaml; returns its path.
std::string writeMotionStudy(const std::string& name, const std::string& study) {
  const fs::path dir = fs::temp_directory_path() / ("swingsim_motion_study_" + std::to_string(::getpid())) / name;
  fs::create_directories(dir);
  std::ofstream(dir / "train.sto") << trialSto();
  std::ofstream(dir / "val.mot") << trialSto();
  std::ofstream(dir / "study.yaml") << study;
  return (dir / "study.yaml").string();
}

std::string motionStudyHead() {
  return "kind: swing-diagnosis\nparticipant: " + kRoot + "/participants/p1.yaml\nbase_model: " + kRoot +
         "/models/damping-table-default.yaml\ntrain: [train.sto]\nvalidate: [val.mot]\n";
}

std::string errorOfStudy(const std::string& name, const std::string& study) {
  try {
    loadDiagnosisStudy(writeMotionStudy(name, study));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MotionColumnsStudy, StudyListingMotionFilesLoadsAndRoundTrips) {
  const std::string path = writeMotionStudy(
      "good", motionStudyHead() +
                  "motion_columns: {hip: hip_flexion_r, knee: knee_angle_r, hip_moment: hip_moment, knee_sign: -1,\n"
                  "                 knee_offset_deg: 2, toe_off_s: 0.05, heel_contact_s: 0.55, resample_s: 0.005}\n");
  const DiagnosisStudy study = loadDiagnosisStudy(path);
  ASSERT_TRUE(study.motionColumns.has_value());
  const MotionColumns& c = *study.motionColumns;
  EXPECT_EQ(c.knee, "knee_angle_r");
  EXPECT_EQ(c.kneeSign, -1);
  EXPECT_EQ(c.hipSign, 1);
  EXPECT_DOUBLE_EQ(c.kneeOffset, 2 * kDegToRad);
  EXPECT_EQ(c.toeOffTime, 0.05);
  EXPECT_EQ(c.heelContactTime, 0.55);
  EXPECT_EQ(c.resampleInterval, 0.005);

  // The records as the diagnosis reads them: flexion positive, offset added, cut, resampled.
  const SwingRecord r = readSwingRecordFile(study.train.front().path, study.motionColumns);
  ASSERT_EQ(r.time.size(), 101u);  // 0 to 0.5 s every 5 ms
  // Linear interpolation between rows 10 ms apart errs by at most h^2/8 max|f''|; the knee's
  // 60 deg sine over 0.6 s curves most.
  const double kInterpolationTol = 0.01 * 0.01 / 8 * 60 * (kPi / 0.6) * (kPi / 0.6);  // deg
  for (std::size_t i = 0; i < r.time.size(); ++i) {
    const double t = 0.05 + r.time[i];
    EXPECT_NEAR(r.kneeFlexion[i] * kRadToDeg, trialKneeFlexionDeg(t) + 2, kInterpolationTol) << i;
    EXPECT_NEAR(r.hipFlexion[i] * kRadToDeg, trialHipDeg(t), kInterpolationTol) << i;
  }
  const auto plant = loadDiagnosisPlant(study, 0);
  EXPECT_EQ(plant->kind(), PlantKind::kSwing);
  EXPECT_EQ(plant->validationStems(), std::vector<std::string>{"val"});

  const std::string dir = fs::path(path).parent_path().string();
  const std::string text = formatDiagnosisStudyYaml(study, dir);
  const DiagnosisStudy back = parse(text, path);
  EXPECT_EQ(formatDiagnosisStudyYaml(back, dir), text);
  ASSERT_TRUE(back.motionColumns.has_value());
  EXPECT_EQ(back.motionColumns->hip, c.hip);
  EXPECT_EQ(back.motionColumns->hipMoment, c.hipMoment);
  EXPECT_EQ(back.motionColumns->kneeSign, c.kneeSign);
  EXPECT_EQ(back.motionColumns->kneeOffset, c.kneeOffset);
  EXPECT_EQ(back.motionColumns->toeOffTime, c.toeOffTime);
  EXPECT_EQ(back.motionColumns->heelContactTime, c.heelContactTime);
  EXPECT_EQ(back.motionColumns->resampleInterval, c.resampleInterval);
  EXPECT_EQ(back.train, study.train);
}

TEST(MotionColumnsStudy, MotionFileWithoutMotionColumnsIsRefused) {
  const std::string message = errorOfStudy("missing", motionStudyHead());
  EXPECT_THAT(message, HasSubstr("study.yaml:4: train: an OpenSim motion file needs the study's motion_columns map"));
  EXPECT_THAT(message, HasSubstr("train.sto)"));
}

TEST(MotionColumnsStudy, BadMotionColumnsNameTheKey) {
  const std::string head = motionStudyHead();
  const std::string cols = "motion_columns:\n  hip: hip_flexion_r\n  knee: knee_angle_r\n  hip_moment: hip_moment\n";
  EXPECT_THAT(errorOfStudy("unknown", head + cols + "  knee_sing: -1\n"),
              HasSubstr("study.yaml:10: motion_columns.knee_sing: unknown key"));
  EXPECT_THAT(errorOfStudy("noknee", head + "motion_columns: {hip: hip_flexion_r, hip_moment: hip_moment}\n"),
              HasSubstr("motion_columns.knee: required key is missing"));
  EXPECT_THAT(errorOfStudy("nomoment", head + "motion_columns: {hip: hip_flexion_r, knee: knee_angle_r}\n"),
              HasSubstr("study.yaml:6: motion_columns: hip_moment: expected the label of the hip moment column (N m)"));
  EXPECT_THAT(errorOfStudy("sign", head + cols + "  hip_sign: 2\n"),
              HasSubstr("study.yaml:10: motion_columns.hip_sign: must be 1 or -1"));
  EXPECT_THAT(errorOfStudy("cut", head + cols + "  toe_off_s: 0.3\n  heel_contact_s: 0.2\n"),
              HasSubstr("study.yaml:11: motion_columns.heel_contact_s: must be after toe_off_s (0.3 s) (got 0.2)"));
  EXPECT_THAT(errorOfStudy("resample", head + cols + "  resample_s: 0\n"),
              HasSubstr("study.yaml:10: motion_columns.resample_s: must be in [1e-5, 0.1] s"));
  // The cylinder plant has no motion files: the key is unknown there.
  EXPECT_THAT(errorOfStudy("cylinder", "kind: cylinder-diagnosis\nbase_model: " + kRoot +
                                           "/models/mauch-4phase.yaml\ntrain: [a.csv]\nvalidate: [b.csv]\n" + cols),
              HasSubstr("study.yaml:5: motion_columns: unknown key"));
  // A column the file does not have is named when the records are read, with the ones it has.
  const DiagnosisStudy study = loadDiagnosisStudy(writeMotionStudy(
      "column", head + "motion_columns: {hip: hip_flexion_l, knee: knee_angle_r, hip_moment: hip_moment}\n"));
  try {
    loadDiagnosisPlant(study, 0);
    FAIL() << "a missing column was not noticed";
  } catch (const InputError& e) {
    // The study key that named it, and the file's label line.
    EXPECT_THAT(e.what(), HasSubstr("study.yaml: motion_columns.hip: expected a column of "));
    EXPECT_THAT(e.what(),
                HasSubstr("train.sto:7 (got 'hip_flexion_l', which it does not have; available: time, hip_flexion_r, "
                          "knee_angle_r, hip_moment)"));
  }
}

// ---- Record entries: several swings of one OpenSim file, with inverse dynamics -------------

const std::string kGait10Ik = kRoot + "/tests/data/opensim-gait10dof/subject01_walk_IK.mot";
const std::string kGait10Id = kRoot + "/tests/data/opensim-gait10dof/subject01_walk_ID.sto";

/// A thigh-driven study of Winter's participant over the Gait10dof walk, with `records`
/// (the train: and validate: lines) and `columns` (the motion_columns line).
std::string entryStudy(
    const std::string& records,
    const std::string& columns =
        "motion_columns: {hip: hip_flexion_r, knee: knee_angle_r, knee_sign: -1, pelvis_tilt: pelvis_tilt}\n") {
  return "kind: swing-diagnosis\nparticipant: " + kRoot + "/participants/winter.yaml\nbase_model: " + kRoot +
         "/models/passive-knee.yaml\ndrive: thigh_kinematics\n" + columns + records;
}

const std::string kTwoSwings = "train:\n  - {name: right1, file: " + kGait10Ik +
                               ", toe_off_s: 0.25, heel_contact_s: 0.7, inverse_dynamics: " + kGait10Id +
                               "}\nvalidate:\n  - {name: right2, file: " + kGait10Ik +
                               ", toe_off_s: 1.35, heel_contact_s: 1.8}\n";

/// Whether two entry lists say the same (paths compared as files: the writer may write an
/// absolute path outside the study's folder as a relative one).
bool sameEntries(const std::vector<StudyRecord>& a, const std::vector<StudyRecord>& b) {
  if (a.size() != b.size()) return false;
  const auto same = [](const std::string& x, const std::string& y) {
    return x.empty() ? y.empty() : fs::weakly_canonical(x) == fs::weakly_canonical(y);
  };
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].name != b[i].name || !same(a[i].path, b[i].path) || a[i].toeOffTime != b[i].toeOffTime ||
        a[i].heelContactTime != b[i].heelContactTime || a[i].swing != b[i].swing ||
        !same(a[i].inverseDynamicsPath, b[i].inverseDynamicsPath))
      return false;
  return true;
}

TEST(StudyRecordEntries, TwoSwingsOfOneFileAreTwoRecordsAndRoundTrip) {
  const std::string path = writeMotionStudy("entries", entryStudy(kTwoSwings));
  const DiagnosisStudy study = loadDiagnosisStudy(path);
  ASSERT_EQ(study.train.size(), 1u);
  const StudyRecord& first = study.train.front();
  EXPECT_EQ(first.name, "right1");
  EXPECT_EQ(first.toeOffTime, 0.25);
  EXPECT_EQ(first.inverseDynamicsPath, kGait10Id);
  EXPECT_EQ(study.validate.front().heelContactTime, 1.8);

  std::vector<std::string> notes;
  const SwingRecord r = readStudyRecord(study, first, notes);
  EXPECT_EQ(r.stem, "right1");
  EXPECT_DOUBLE_EQ(r.time.back(), 0.7 - 0.25);  // the entry's times, not the whole file
  ASSERT_EQ(r.kneeMoment.size(), r.time.size());
  // The knee moment, sign flipped, of the ID row nearest the record's second sample (the
  // ID's times lag the IK's by up to 1.5 us; the moment changes by under 0.01 N m in that).
  const MotionTable id = readMotionTable(kGait10Id);
  const auto& idTime = id.column("time");
  const auto near =
      std::find_if(idTime.begin(), idTime.end(), [&](double t) { return std::abs(t - (0.25 + r.time[1])) < 2e-6; });
  ASSERT_NE(near, idTime.end());
  constexpr double kSkewTol = 0.01;  // N m
  EXPECT_NEAR(r.kneeMoment[1], -id.column("knee_angle_r_moment")[static_cast<std::size_t>(near - idTime.begin())],
              kSkewTol);
  EXPECT_FALSE(std::isnan(r.kneeMoment.front()));
  EXPECT_TRUE(notes.empty()) << notes.front();
  const auto plant = loadDiagnosisPlant(study, 0);
  EXPECT_EQ(plant->validationStems(), std::vector<std::string>{"right2"});

  const std::string dir = fs::path(path).parent_path().string();
  const std::string text = formatDiagnosisStudyYaml(study, dir);
  const DiagnosisStudy back = parse(text, path);
  EXPECT_EQ(formatDiagnosisStudyYaml(back, dir), text);
  EXPECT_TRUE(sameEntries(back.train, study.train));
  EXPECT_TRUE(sameEntries(back.validate, study.validate));
  EXPECT_EQ(back.motionColumns->pelvisTilt, "pelvis_tilt");

  // Plain entries stay plain; `swing: K` is kept for the swing finder; the name defaults to the stem.
  const DiagnosisStudy mixed = parse(
      entryStudy("train: [" + kGait10Ik + "]\nvalidate:\n  - {file: " + kGait10Ik + ", swing: 2, name: second}\n"),
      path);
  EXPECT_EQ(mixed.train.front().displayName(), "subject01_walk_IK");
  EXPECT_EQ(mixed.validate.front().swing, 2);
  const std::string mixedText = formatDiagnosisStudyYaml(mixed, dir);
  EXPECT_THAT(mixedText, HasSubstr("train:\n  - "));
  EXPECT_THAT(mixedText, HasSubstr("subject01_walk_IK.mot\nvalidate:\n  - {name: second, file: "));
  EXPECT_THAT(mixedText, HasSubstr("swing: 2"));
  EXPECT_TRUE(sameEntries(parse(mixedText, path).validate, mixed.validate));
}

TEST(StudyRecordEntries, WarningsNameTheKeyThatFixesThem) {
  // knee_sign forgotten, pelvis tilt not read: both said, each naming its key.
  const DiagnosisStudy study = loadDiagnosisStudy(writeMotionStudy(
      "warnings", entryStudy(kTwoSwings, "motion_columns: {hip: hip_flexion_r, knee: knee_angle_r}\n")));
  const auto plant = loadDiagnosisPlant(study, 0);
  std::string all;
  for (const auto& w : plant->warnings()) all += w + "\n";
  EXPECT_THAT(all, HasSubstr("right1: "));
  EXPECT_THAT(all, HasSubstr("motion_columns: knee_sign: -1"));
  EXPECT_THAT(all, HasSubstr("motion_columns: pelvis_tilt: pelvis_tilt"));
}

TEST(StudyRecordEntries, BadEntriesNameFileKeyExpectedAndFound) {
  const std::string entry = "{name: a, file: " + kGait10Ik + ", toe_off_s: 0.25, heel_contact_s: 0.7}";
  EXPECT_THAT(errorOfStudy("duplicate", entryStudy("train:\n  - " + entry + "\nvalidate:\n  - " + entry + "\n")),
              HasSubstr("study.yaml:8: validate: two records share the name 'a'"));
  EXPECT_THAT(errorOfStudy("stems", entryStudy("train: [" + kGait10Ik + "]\nvalidate: [" + kGait10Ik + "]\n")),
              HasSubstr("two records share the name 'subject01_walk_IK'"));
  EXPECT_THAT(errorOfStudy("both", entryStudy("train:\n  - {file: " + kGait10Ik +
                                              ", swing: 1, toe_off_s: 0.2}\nvalidate: [x.mot]\n")),
              HasSubstr("study.yaml:7: train[0].swing: either swing (the K-th swing found in the file) or toe_off_s"));
  EXPECT_THAT(
      errorOfStudy("swing0", entryStudy("train:\n  - {file: " + kGait10Ik + ", swing: 0}\nvalidate: [x.mot]\n")),
      HasSubstr("train[0].swing: expected a whole number from 1"));
  EXPECT_THAT(
      errorOfStudy("csv", entryStudy("train:\n  - {file: a.csv, toe_off_s: 0.2}\nvalidate: [x.mot]\n")),
      HasSubstr("train[0].file: toe_off_s, heel_contact_s, swing and inverse_dynamics cut an OpenSim .mot/.sto"));
  EXPECT_THAT(
      errorOfStudy("unknown", entryStudy("train:\n  - {file: " + kGait10Ik + ", tow_off_s: 0.2}\nvalidate: [x.mot]\n")),
      HasSubstr("train[0].tow_off_s: unknown key"));

  // At reading the records: times outside the file; an ID without the knee moment's label.
  const auto loadError = [](const std::string& name, const std::string& text) {
    try {
      loadDiagnosisPlant(loadDiagnosisStudy(writeMotionStudy(name, text)), 0);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_THAT(
      loadError("outside", entryStudy("train:\n  - {file: " + kGait10Ik +
                                      ", toe_off_s: 2.2, heel_contact_s: 2.9}\n"
                                      "validate:\n  - " +
                                      entry + "\n")),
      HasSubstr("subject01_walk_IK.mot: heel_contact_s: expected a time after toe-off (2.2 s) and within the file; the "
                "file's time runs from 0 to 2.5 s (got 2.9 s)"));
  EXPECT_THAT(
      loadError("nolabel", entryStudy("train:\n  - {file: " + kGait10Ik +
                                      ", toe_off_s: 0.2, heel_contact_s: 0.7, "
                                      "inverse_dynamics: " +
                                      kGait10Ik + "}\nvalidate:\n  - " + entry + "\n")),
      HasSubstr("subject01_walk_IK.mot:11: knee_angle_r_moment: column is missing (available: time, pelvis_tilt"));
}

}  // namespace
}  // namespace swingsim

namespace swingsim {
namespace {

// `swing: K` on the demo's IK file: the K-th complete swing, its events from the GRF file
// where it covers them (swing 1) and from the kinematics past its end (swing 2), as
// `swingsim swings` lists them; a K beyond the swings found is an error naming the range.
const std::string kDemoData = std::string(SWINGSIM_SOURCE_DIR) + "/studies/data/opensim-subject01/";

TEST(StudyRecordSwingNumber, ResolvesToTheSwingsFoundAndRefusesOneThatDoesNotExist) {
  const MotionTable ik = readMotionTable(kDemoData + "gait2392_subject01_walk1_ik.mot");
  const MotionColumns columns = openSimLegColumns(ik, "r");  // hip_flexion_r, knee_angle_r x -1, pelvis_tilt
  GrfSettings grf;
  grf.path = kDemoData + "subject01_walk1_grf.mot";
  const std::vector<FoundSwing> swings = findSwings(ik, columns, grf);
  ASSERT_EQ(swings.size(), 2u);
  StudyRecord entry;
  entry.path = ik.path;
  for (int k = 1; k <= 2; ++k) {
    entry.swing = k;
    const MotionColumns cut = resolveRecordTimes(entry, columns, ik, grf);
    EXPECT_EQ(cut.toeOffTime, swings[static_cast<std::size_t>(k - 1)].toeOff);
    EXPECT_EQ(cut.heelContactTime, swings[static_cast<std::size_t>(k - 1)].heelContact);
  }
  EXPECT_EQ(swings[0].toeOffSource, "grf");
  EXPECT_EQ(swings[1].heelContactSource, "kinematics");
  entry.swing = 3;
  try {
    resolveRecordTimes(entry, columns, ik, grf);
    ADD_FAILURE() << "swing 3 of 2 was accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("gait2392_subject01_walk1_ik.mot: swing: expected a swing number from 1 to 2"));
    EXPECT_THAT(e.what(), HasSubstr("(the complete swings found: 1: 1.4086-1.8522 s, 2: "));  // 0.1 ms, not 16 digits
    EXPECT_THAT(e.what(), HasSubstr("(got 3)"));
  }
}

TEST(StudyRecordSwingNumber, AForceFileThatFailsItsChecksIsBlamedNotTheKinematics) {
  // The other foot's column in a study: the message names the force file and column, and the
  // leg it matches, not "swing: expected a swing number from 1 to 0" on the IK file.
  const MotionTable ik = readMotionTable(kDemoData + "gait2392_subject01_walk1_ik.mot");
  const MotionColumns columns = openSimLegColumns(ik, "r");  // hip_flexion_r, knee_angle_r x -1, pelvis_tilt
  GrfSettings grf;
  grf.path = kDemoData + "subject01_walk1_grf.mot";
  grf.verticalForce = "1_ground_force_vy";
  StudyRecord entry;
  entry.path = ik.path;
  entry.swing = 1;
  EXPECT_THAT(
      swingsim::testing::inputErrorOf([&] { resolveRecordTimes(entry, columns, ik, grf); }),
      HasSubstr("subject01_walk1_grf.mot: 1_ground_force_vy: expected the force's stance and swing to match the leg's "
                "kinematics"));
  // Asked for, the kinematics give the events and the study's notes say so.
  grf.fallbackToKinematics = true;
  std::vector<std::string> notes;
  const MotionColumns cut = resolveRecordTimes(entry, columns, ik, grf, std::nullopt, &notes);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_THAT(
      notes[0],
      HasSubstr("gait2392_subject01_walk1_ik: events from the kinematics, not the force (fallback_to_kinematics)"));
  EXPECT_EQ(cut.toeOffTime, findSwings(ik, columns, std::nullopt).front().toeOff);
  // A stance-only cut of the file holds no swing: said as such, with the rules used.
  MotionTable stance = ik;
  for (auto& column : stance.columns) column.resize(20);  // 0.5-0.82 s: the right leg in stance
  stance.rowLines.resize(20);
  EXPECT_THAT(swingsim::testing::inputErrorOf([&] { resolveRecordTimes(entry, columns, stance, std::nullopt); }),
              HasSubstr("swing: 1: the file holds no complete swing of knee_angle_r"));
}

TEST(StudyRecordSwingNumber, AStudyStatesTheGaitAndTheFallbackAndTheyRoundTrip) {
  const std::string grf =
      "grf: {file: " + kDemoData + "subject01_walk1_grf.mot, fallback_to_kinematics: true}\ngait: running\n";
  const std::string path = writeMotionStudy("gait", entryStudy(kTwoSwings,
                                                               "motion_columns: {hip: hip_flexion_r, knee: "
                                                               "knee_angle_r, knee_sign: -1}\n" +
                                                                   grf));
  const DiagnosisStudy study = loadDiagnosisStudy(path);
  ASSERT_TRUE(study.gait.has_value());
  EXPECT_EQ(*study.gait, Gait::kRunning);
  ASSERT_TRUE(study.grf.has_value());
  EXPECT_TRUE(study.grf->fallbackToKinematics);
  const std::string yaml = formatDiagnosisStudyYaml(study, fs::path(path).parent_path().string());
  EXPECT_THAT(yaml, HasSubstr("gait: running"));
  EXPECT_THAT(yaml, HasSubstr("fallback_to_kinematics: true"));
  EXPECT_THAT(
      errorOfStudy("gait",
                   entryStudy(kTwoSwings, "motion_columns: {hip: hip_flexion_r, knee: knee_angle_r}\ngait: jogging\n")),
      HasSubstr("study.yaml:6: gait: expected one of: walking, running (got 'jogging')"));
}

}  // namespace
}  // namespace swingsim
