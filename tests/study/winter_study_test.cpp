// The demonstration on published gait data (docs/winter.md): studies/winter-swing.yaml,
// Winter's two measured swings with the measured thigh prescribed and a passive knee.
// The assertions are on what the study measured (docs/winter.md), and on the data's sign
// convention, checked here by an inverse dynamics of the test's own.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "core/units.h"
#include "identify/comparison.h"
#include "identify/diagnosis_engine.h"
#include "io/participant_loader.h"
#include "io/swing_record_csv.h"
#include "model/leg_parameters.h"
#include "numerics/metrics.h"
#include "study/diagnosis_study.h"

namespace swingsim {
namespace {

const std::string kSource = SWINGSIM_SOURCE_DIR;

TEST(WinterStudy, KneeMomentColumnHasSwingsimsSign) {
  // Winter's knee moment is copied into the swing CSVs with swingsim's sign (+ = flexion;
  // scripts/winter-swing-data.py). Check it with physics written here: the knee moment the
  // shank + foot of participants/winter.yaml need to follow Winter's measured hip and knee
  // angles, rates and accelerations (the second Lagrange equation of the thigh-shank chain
  // with the foot welded at 90 deg; the formula is this test's own). A wrong sign would
  // correlate negatively; segment-parameter assumptions only scale it.
  const Participant p = loadParticipant(kSource + "/participants/winter.yaml");
  const LegGeometry g = calcLegGeometry(p, 0.0);
  const double m2 = g.shankMass + g.footMass;
  const double mx = g.footMass * g.footComForward, my = g.shankMass * g.shankCom + g.footMass * g.shankLength;
  const double r2 = std::hypot(mx, my) / m2, gamma = std::atan2(mx, my);
  const double j2 = g.shankInertia + g.shankMass * g.shankCom * g.shankCom + g.footInertia +
                    g.footMass * (g.footComForward * g.footComForward + g.shankLength * g.shankLength);
  std::ifstream in(kSource + "/studies/data/winter-natural-cadence.csv");
  std::string line;
  std::getline(in, line);
  std::vector<double> ours, winters;
  for (int frame = 1; frame <= 27 && std::getline(in, line); ++frame) {  // toe-off to just before heel contact
    std::vector<double> v;
    std::stringstream row(line);
    std::string cell;
    while (std::getline(row, cell, ',')) v.push_back(cell.empty() ? 0.0 : std::atof(cell.c_str()));
    const double phi = v[9] * kDegToRad, theta = v[6] * kDegToRad;
    const double phiDot = v[10], thetaDot = v[7], phiDDot = v[11], thetaDDot = v[8];
    const double beta = phi - theta + gamma, betaDDot = phiDDot - thetaDDot;
    const double m12 = m2 * g.thighLength * r2 * std::cos(phi - beta);
    ours.push_back(-(m12 * phiDDot + j2 * betaDDot - m2 * g.thighLength * r2 * std::sin(phi - beta) * phiDot * phiDot +
                     m2 * r2 * kGravity * std::sin(beta)));
    (void)thetaDot;
    winters.push_back(v[12]);
  }
  const SwingRecord swing1 = readSwingRecord(kSource + "/studies/data/winter-swing/swing1.csv");
  ASSERT_EQ(swing1.kneeMoment.size(), 28u);
  for (std::size_t i = 0; i < winters.size(); ++i) EXPECT_DOUBLE_EQ(swing1.kneeMoment[i], winters[i]);
  const double r = calcCorrelation(ours, winters);
  std::printf("inverse dynamics of Winter's swing with participants/winter.yaml vs Winter's knee moment: r = %.2f\n",
              r);
  EXPECT_GT(r, 0.5);
}

TEST(WinterStudy, PassiveKneeDoesNotExplainAMuscleDrivenSwing) {
  const DiagnosisStudy study = loadDiagnosisStudy(kSource + "/studies/winter-swing.yaml");
  ASSERT_EQ(study.drive, SwingDrive::kThighKinematics);
  const auto plant = loadDiagnosisPlant(study, 8);
  const Diagnosis dg = runDiagnosis(*plant, study.settings);
  const double noise = dg.recordNoise.front();
  std::printf(
      "Winter: noise %.2f deg; base train %.2f deg, held out %.2f deg; final held out %.2f deg; %zu accepted; %s\n",
      noise, dg.baseline.trainRmse, dg.baseline.validationRmse.front(), dg.final.validationRmse.front(),
      dg.accepted.size(), dg.verdict.c_str());
  // The measured thigh and a passive hinge already follow the knee within a few degrees
  // (Winter's knee swings through 67 deg)...
  EXPECT_LT(dg.baseline.trainRmse, 3.0);
  EXPECT_LT(dg.baseline.validationRmse.front(), 3.0);
  // ...but an able-bodied knee is driven by muscles: no passive effect of the library brings
  // the held-out error near the noise, and the tool says so instead of claiming one.
  EXPECT_FALSE(dg.explained);
  EXPECT_GT(dg.final.validationRmse.front(), 1.2 * noise);
  EXPECT_NE(dg.verdict.find("NOT explained"), std::string::npos);
  // The Simbody chain (prescribed motion) agrees with the reference integrator of the refits.
  const std::string check = plant->verify(*dg.final.model);
  const double simbodyDiff = std::atof(check.substr(check.rfind("difference ") + 11).c_str());
  EXPECT_LT(simbodyDiff, 0.05) << check;
  // The knee moment the model applies, against Winter's (never fitted): both records, with
  // the same sign pattern (braking flexion early, braking extension late).
  const auto held = plant->compareHeldBack(*dg.final.model);
  ASSERT_TRUE(held.has_value());
  ASSERT_EQ(held->records.size(), 2u);
  EXPECT_TRUE(held->records[0].training);
  EXPECT_FALSE(held->records[1].training);
  EXPECT_TRUE(std::isfinite(held->rmse));
  EXPECT_GT(held->correlation, 0.0);
  std::printf("knee moment vs Winter: RMSE %.1f N m, r %.2f\n", held->rmse, held->correlation);
}

}  // namespace
}  // namespace swingsim

namespace swingsim {
namespace {

// A study in the temp folder naming the bundled files by absolute path ("S/" = the source).
std::string writeStudy(const std::string& name, std::string body) {
  for (std::size_t at = 0; (at = body.find("S/", at)) != std::string::npos; at += kSource.size() + 1)
    body.replace(at, 2, kSource + "/");
  const std::string path = (std::filesystem::temp_directory_path() / ("swingsim-" + name)).string();
  std::ofstream(path) << body;
  return path;
}

TEST(SwingStudyDrive, HipMomentDriveNeedsAHipMomentAndSaysWhatElseWorks) {
  const std::string path = writeStudy(
      "test-winter-hip-drive.yaml",
      "kind: swing-diagnosis\nparticipant: S/participants/winter.yaml\n"
      "base_model: S/models/passive-knee.yaml\n"
      "train: [S/studies/data/winter-swing/swing1.csv]\nvalidate: [S/studies/data/winter-swing/swing2.csv]\n");
  try {
    const DiagnosisStudy study = loadDiagnosisStudy(path);
    loadDiagnosisPlant(study, 8);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("swing1.csv"), std::string::npos) << what;
    EXPECT_NE(what.find("hip_moment_Nm"), std::string::npos) << what;
    EXPECT_NE(what.find("drive: thigh_kinematics"), std::string::npos) << what;
  }
  std::remove(path.c_str());
  const std::string bad = writeStudy(
      "test-winter-bad-drive.yaml",
      "kind: swing-diagnosis\nparticipant: S/participants/winter.yaml\n"
      "base_model: S/models/passive-knee.yaml\ndrive: thigh\n"
      "train: [S/studies/data/winter-swing/swing1.csv]\nvalidate: [S/studies/data/winter-swing/swing2.csv]\n");
  try {
    loadDiagnosisStudy(bad);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("drive"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("thigh_kinematics"), std::string::npos) << e.what();
  }
  std::remove(bad.c_str());
}

TEST(SwingStudyDrive, SeveralTrainingTrialsShareOneModelAndWholeTrialsAreHeldOut) {
  // Two training trials fit one set of model parameters (each keeps only
  // its own toe-off state); the held-out trial is judged whole.
  const std::string path =
      writeStudy("test-two-trials.yaml",
                 "kind: swing-diagnosis\nparticipant: S/participants/p1.yaml\n"
                 "base_model: S/models/damping-table-default.yaml\n"
                 "train: [S/studies/data/diagnose-demo-swing/normal.csv, S/studies/data/diagnose-demo-swing/slow.csv]\n"
                 "validate: [S/studies/data/diagnose-demo-swing/fast.csv]\n");
  const DiagnosisStudy study = loadDiagnosisStudy(path);
  std::remove(path.c_str());
  const auto plant = loadDiagnosisPlant(study, 8);
  const PlantFit both = plant->fit(*plant->baseModel());
  ASSERT_EQ(both.trainResidual.size(), 2u);
  ASSERT_EQ(both.validationRmse.size(), 1u);
  ASSERT_EQ(both.baseParameters.size(), 1u);  // one knee_model_scale for both trials
  EXPECT_EQ(both.baseParameters.front().name, "knee_model_scale");
  EXPECT_EQ(plant->validationStems(), std::vector<std::string>{"fast"});
  // Each trial's residual is its own length: the fit saw every sample of both.
  const SwingRecord normal = readSwingRecord(kSource + "/studies/data/diagnose-demo-swing/normal.csv");
  const SwingRecord slow = readSwingRecord(kSource + "/studies/data/diagnose-demo-swing/slow.csv");
  EXPECT_EQ(both.trainResidual[0].size(), normal.time.size());
  EXPECT_EQ(both.trainResidual[1].size(), slow.time.size());
  std::printf("two training trials: knee RMSE %.3f deg, held-out fast %.3f deg\n", both.trainRmse,
              both.validationRmse[0]);
  // The Simbody check runs along every trial, to its end (a hip-moment swing that has not
  // settled when its record ends is still compared).
  const std::string check = plant->verify(*both.model);
  ASSERT_NE(check.find("max knee difference "), std::string::npos) << check;
  EXPECT_LT(std::atof(check.substr(check.rfind("difference ") + 11).c_str()), 0.05) << check;
}

}  // namespace
}  // namespace swingsim
