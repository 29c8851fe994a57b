#include "study/diagnosis_study.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

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
  const std::string text = "kind: swing-diagnosis\nparticipant: ../participants/p1.yaml\n"
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
  std::string text = "trial\nversion=1\nnRows=61\nnColumns=4\ninDegrees=yes\nendheader\n"
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
  const SwingRecord r = readSwingRecordFile(study.train.front(), study.motionColumns);
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
    EXPECT_THAT(e.what(), HasSubstr("train.sto:7: hip_flexion_l: column is missing (available: time, hip_flexion_r, "
                                    "knee_angle_r, hip_moment)"));
  }
}

}  // namespace
}  // namespace swingsim
