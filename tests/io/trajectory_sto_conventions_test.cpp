// The trajectory .sto in OpenSim's gait-model convention: its columns name the exported
// model's coordinates on the side asked for, the knee negative in flexion; a lab's own IK
// files name the same coordinates with the same sign; and a .sto written by an older simulate
// (hip_flexion, knee_flexion, flexion positive) still reads to the same swing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "core/output_files.h"
#include "core/units.h"
#include "io/motion_file.h"
#include "io/osim_model_writer.h"
#include "io/participant_loader.h"
#include "io/trajectory_writer.h"
#include "opensim_trials.h"

namespace swingsim {
namespace {

using swingsim::testing::kHamnerRunIk;
using swingsim::testing::kRajagopalRunIk;
using swingsim::testing::kRoot;
using swingsim::testing::kWalkIk10dof;
using swingsim::testing::kWalkIk2354;
using swingsim::testing::kWalkIk2392;
using ::testing::Contains;

// The .sto holds %.10g: a relative error of at most 5e-10 in each printed number.
constexpr double kTenDigits = 1e-9;

// A swing-like trajectory: hip -15 -> 25 deg, knee 10 -> 70 -> 0 deg over 0.4 s.
SwingTrajectory makeSwing() {
  SwingTrajectory t;
  constexpr int kSamples = 41;
  for (int i = 0; i < kSamples; ++i) {
    const double s = i / double(kSamples - 1);
    t.time.push_back(0.4 * s);
    t.hipFlexion.push_back((-15 + 40 * s) * kDegToRad);
    t.kneeFlexion.push_back((10 * (1 - s) + 65 * std::sin(kPi * s)) * kDegToRad);
    t.hipFlexionRate.push_back(100 * kDegToRad);
    t.kneeFlexionRate.push_back((-25 + 65 * kPi * std::cos(kPi * s)) * kDegToRad);
    t.hipMoment.push_back(30 * std::cos(kPi * s));
    t.kneeMoment.push_back(-5 * std::sin(kPi * s));
  }
  return t;
}

// The text an older `swingsim simulate` wrote (its formatTrajectorySto, kept here as it was).
std::string formatOldConventionSto(const SwingTrajectory& t) {
  std::string out = "P1-lower000mm\nversion=1\nnRows=" + std::to_string(t.size()) +
                    "\nnColumns=7\ninDegrees=yes\nendheader\n"
                    "time\thip_flexion\tknee_flexion\thip_flexion_speed\tknee_flexion_speed\thip_moment\tknee_moment\n";
  char row[256];
  for (std::size_t i = 0; i < t.size(); ++i) {
    std::snprintf(row, sizeof row, "%.10g\t%.10g\t%.10g\t%.10g\t%.10g\t%.10g\t%.10g\n", t.time[i],
                  t.hipFlexion[i] * kRadToDeg, t.kneeFlexion[i] * kRadToDeg, t.hipFlexionRate[i] * kRadToDeg,
                  t.kneeFlexionRate[i] * kRadToDeg, t.hipMoment[i], t.kneeMoment[i]);
    out += row;
  }
  return out;
}

std::vector<std::string> modelCoordinates(char side) {
  const Participant p = loadParticipant(kRoot + "/participants/p1.yaml");
  OsimLegPlacement place;
  place.side = side;
  place.initial = p.initial;
  place.hipRange = p.hipRange;
  place.kneeMaxFlexion = kPi;
  std::vector<std::string> names;
  for (const auto& j : makeOsimLegModel(calcLegGeometry(p, 0), place).joints)
    for (const auto& c : j.coordinates) names.push_back(c.name);
  return names;
}

TEST(TrajectoryStoConventions, ColumnsNameTheExportedModelsCoordinatesOnEitherSide) {
  const SwingTrajectory t = makeSwing();
  for (const char side : {'r', 'l'}) {
    const MotionTable table = parseMotionTable(formatTrajectorySto(t, "swing", side), "swing.sto");
    const std::vector<std::string> coordinates = modelCoordinates(side);
    ASSERT_EQ(coordinates.size(), 2u);
    for (const auto& c : coordinates) EXPECT_THAT(table.labels, Contains(c)) << side;
    const std::string s(1, side);
    EXPECT_EQ(table.labels, (std::vector<std::string>{"time", "hip_flexion_" + s, "knee_angle_" + s,
                                                      "hip_flexion_" + s + "_speed", "knee_angle_" + s + "_speed",
                                                      "hip_flexion_" + s + "_moment", "knee_angle_" + s + "_moment"}));
    EXPECT_TRUE(table.inDegrees);
    // The knee's angle, rate and moment in knee_angle's sign; the hip's as they are.
    for (std::size_t i = 0; i < t.size(); i += 10) {
      EXPECT_NEAR(table.column("knee_angle_" + s)[i], -t.kneeFlexion[i] * kRadToDeg, kTenDigits * 100) << i;
      EXPECT_NEAR(table.column("knee_angle_" + s + "_speed")[i], -t.kneeFlexionRate[i] * kRadToDeg, kTenDigits * 1e4)
          << i;
      EXPECT_NEAR(table.column("knee_angle_" + s + "_moment")[i], -t.kneeMoment[i], kTenDigits * 10) << i;
      EXPECT_NEAR(table.column("hip_flexion_" + s)[i], t.hipFlexion[i] * kRadToDeg, kTenDigits * 100) << i;
    }
  }
  EXPECT_THROW(formatTrajectorySto(t, "swing", 'x'), std::invalid_argument);
}

// The shipped lab IK files (Gait10dof18musc, Gait2354, Gait2392 walks; Hamner's run) name both
// legs' hip and knee as the exported model's coordinates, and bend the knee negative, as it does.
TEST(TrajectoryStoConventions, LabIkFilesNameTheExportedModelsCoordinatesWithItsKneeSign) {
  for (const std::string& file : {kWalkIk10dof, kWalkIk2354, kWalkIk2392, kHamnerRunIk}) {
    const MotionTable table = readMotionTable(file);
    for (const char side : {'r', 'l'}) {
      for (const auto& c : modelCoordinates(side)) EXPECT_THAT(table.labels, Contains(c)) << file;
      const auto& knee = table.column(makeOsimKneeCoordinate(side));
      EXPECT_LT(*std::min_element(knee.begin(), knee.end()), -40) << file << ": flexion is negative";
      EXPECT_LT(*std::max_element(knee.begin(), knee.end()), 10) << file << ": little hyperextension";
    }
  }
  // The exception docs/export-osim.md names: Rajagopal's model bends knee_angle positive.
  const MotionTable rajagopal = readMotionTable(kRajagopalRunIk);
  const auto& knee = rajagopal.column("knee_angle_r");
  EXPECT_GT(*std::max_element(knee.begin(), knee.end()), 40);
}

TEST(TrajectoryStoConventions, NewStoReadsAsALabFileToTheSwingItWasWrittenFrom) {
  const SwingTrajectory t = makeSwing();
  const MotionTable table = parseMotionTable(formatTrajectorySto(t, "swing"), "swing.sto");
  const SwingRecord r = makeSwingRecord(table, openSimRightLegColumns(table));
  ASSERT_EQ(r.time.size(), t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    EXPECT_NEAR(r.kneeFlexion[i], t.kneeFlexion[i], kTenDigits * 2) << i;
    EXPECT_NEAR(r.hipFlexion[i], t.hipFlexion[i], kTenDigits * 2) << i;
  }
  // As an inverse-dynamics .sto too: knee_angle_r_moment, times knee_sign -1, is the knee moment.
  const SwingRecord withMoment = makeSwingRecord(table, openSimRightLegColumns(table), &table);
  for (std::size_t i = 0; i < t.size(); i += 10)
    EXPECT_NEAR(withMoment.kneeMoment[i], t.kneeMoment[i], kTenDigits * 10) << i;
}

TEST(TrajectoryStoConventions, OldConventionStoStillReadsToTheSameSwing) {
  const SwingTrajectory t = makeSwing();
  const MotionTable oldTable = parseMotionTable(formatOldConventionSto(t), "old.sto");
  const MotionTable newTable = parseMotionTable(formatTrajectorySto(t, "swing"), "new.sto");
  const SwingRecord a = makeSwingRecord(oldTable, openSimRightLegColumns(oldTable), &oldTable);
  const SwingRecord b = makeSwingRecord(newTable, openSimRightLegColumns(newTable), &newTable);
  ASSERT_EQ(a.time.size(), b.time.size());
  for (std::size_t i = 0; i < a.time.size(); ++i) {
    EXPECT_NEAR(a.kneeFlexion[i], b.kneeFlexion[i], kTenDigits * 2) << i;
    EXPECT_NEAR(a.hipFlexion[i], b.hipFlexion[i], kTenDigits * 2) << i;
    EXPECT_NEAR(a.kneeMoment[i], b.kneeMoment[i], kTenDigits * 10) << i;
  }
  EXPECT_GT(*std::max_element(a.kneeFlexion.begin(), a.kneeFlexion.end()), 60 * kDegToRad)
      << "flexion positive, as written";
}

// Where a participant names a plain .sto as its thigh_kinematics, the old and new files give
// the same drive.
TEST(TrajectoryStoConventions, OldAndNewStoDriveAParticipantAlike) {
  const auto dir = std::filesystem::temp_directory_path() / "swingsim-trajectory-sto-conventions";
  std::filesystem::create_directories(dir);
  const SwingTrajectory t = makeSwing();
  writeFileAtomic((dir / "old.sto").string(), formatOldConventionSto(t));
  writeFileAtomic((dir / "new.sto").string(), formatTrajectorySto(t, "swing"));
  const auto participantWith = [&](const std::string& sto) {
    std::string text = readFile(kRoot + "/participants/winter.yaml");
    const std::string key = "thigh_kinematics: ../studies/data/winter-swing/swing1.csv";
    const auto at = text.find(key);
    EXPECT_NE(at, std::string::npos);
    return parseParticipant(text.replace(at, key.size(), "thigh_kinematics: " + (dir / sto).string()),
                            kRoot + "/participants/w.yaml");
  };
  const Participant a = participantWith("old.sto"), b = participantWith("new.sto");
  ASSERT_EQ(a.thighKinematics.time.size(), t.size());
  ASSERT_EQ(b.thighKinematics.time.size(), t.size());
  ASSERT_EQ(a.thighKinematics.kneeFlexion.size(), t.size());
  ASSERT_EQ(b.thighKinematics.kneeFlexion.size(), t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    EXPECT_NEAR(a.thighKinematics.hipFlexion[i], b.thighKinematics.hipFlexion[i], kTenDigits * 2) << i;
    EXPECT_NEAR(a.thighKinematics.kneeFlexion[i], t.kneeFlexion[i], kTenDigits * 2) << i;
    EXPECT_NEAR(b.thighKinematics.kneeFlexion[i], t.kneeFlexion[i], kTenDigits * 2) << i;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace swingsim
