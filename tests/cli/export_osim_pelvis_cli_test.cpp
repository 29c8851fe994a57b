// `swingsim export-osim` of a participant driven by a lab's IK file with the pelvis: the pelvis
// moves in the plane on a PlanarJoint whose coordinates are the lab file's pelvis columns, and
// every coordinate starts where the lab file is at toe-off; import-osim still reads the leg.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/output_files.h"
#include "core/units.h"
#include "io/motion_file.h"
#include "io/osim_model.h"
#include "io/participant_loader.h"
#include "run_swingsim.h"

namespace swingsim::testing {
namespace {

using ::testing::Contains;

const std::string kRoot = SWINGSIM_SOURCE_DIR;
const std::string kLabIk = kRoot + "/tests/data/opensim-gait10dof/subject01_walk_IK.mot";
constexpr double kToeOff = 1.41;  // s, between two rows of the lab file (its first swing starts here)
// The record interpolates linearly between rows and converts to rad; the file holds rad in full.
constexpr double kInterpolation = 1e-12;

// Winter's participant, driven by the lab file from kToeOff with its pelvis, paths absolute.
std::string writeLabDrivenParticipant(const std::filesystem::path& dir) {
  std::string text = readFile(kRoot + "/participants/winter.yaml");
  const auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  };
  replace("knee_model: ../models/passive-knee.yaml", "knee_model: " + kRoot + "/models/passive-knee.yaml");
  replace("thigh_kinematics: ../studies/data/winter-swing/swing1.csv",
          "thigh_kinematics: {file: " + kLabIk +
              ", hip: hip_flexion_r, knee: knee_angle_r, knee_sign: -1, pelvis_tilt: pelvis_tilt, "
              "pelvis_tx: pelvis_tx, pelvis_ty: pelvis_ty, toe_off_s: 1.41, heel_contact_s: 1.85}");
  const std::string path = (dir / "lab.yaml").string();
  writeFileAtomic(path, text);
  return path;
}

// The lab file's column at kToeOff, linearly between its rows.
double labAtToeOff(const MotionTable& lab, const std::string& label) {
  const auto& time = lab.column("time");
  const auto& v = lab.column(label);
  std::size_t i = 0;
  while (time[i + 1] < kToeOff) ++i;
  const double s = (kToeOff - time[i]) / (time[i + 1] - time[i]);
  return v[i] + s * (v[i + 1] - v[i]);
}

TEST(ExportOsimPelvisCli, MeasuredPelvisMovesOnTheLabsCoordinatesFromToeOff) {
  const auto dir = freshTempDir("ExportOsimPelvisCli", "lab");
  const std::string participant = writeLabDrivenParticipant(dir);
  const CliRun run = runSwingsim("export-osim " + participant + " --out " + dir.string());
  ASSERT_EQ(run.code, 0) << run.output;
  const auto osim = dir / "winter-lower000mm.osim";
  const OsimModel model = loadOsimModel(osim.string());
  const OsimJoint& ground = model.getJointTo("pelvis");
  EXPECT_EQ(ground.type, "PlanarJoint");
  EXPECT_EQ(ground.parentBody, "ground");
  ASSERT_EQ(ground.coordinates.size(), 3u);
  EXPECT_EQ(ground.coordinates[0].name, "pelvis_tilt");  // PlanarJoint's order: rz, tx, ty
  EXPECT_EQ(ground.coordinates[1].name, "pelvis_tx");
  EXPECT_EQ(ground.coordinates[2].name, "pelvis_ty");

  // Every coordinate of the model is a column of the lab file and starts at its toe-off value.
  const MotionTable lab = readMotionTable(kLabIk);
  const double tilt = labAtToeOff(lab, "pelvis_tilt") * kDegToRad;
  EXPECT_NEAR(ground.coordinates[0].defaultValue, tilt, kInterpolation);
  EXPECT_NEAR(ground.coordinates[1].defaultValue, labAtToeOff(lab, "pelvis_tx"), kInterpolation);
  EXPECT_NEAR(ground.coordinates[2].defaultValue, labAtToeOff(lab, "pelvis_ty"), kInterpolation);
  const OsimCoordinate& hip = model.getJointTo("femur_r").coordinates.at(0);
  const OsimCoordinate& knee = model.getJointTo("tibia_r").coordinates.at(0);
  EXPECT_NEAR(hip.defaultValue, labAtToeOff(lab, "hip_flexion_r") * kDegToRad, kInterpolation)
      << "in the pelvis, not in space";
  EXPECT_NEAR(knee.defaultValue, labAtToeOff(lab, "knee_angle_r") * kDegToRad, kInterpolation);
  int coordinates = 0;
  for (const auto& j : model.joints)
    for (const auto& c : j.coordinates) {
      ++coordinates;
      EXPECT_THAT(lab.labels, Contains(c.name));
    }
  EXPECT_EQ(coordinates, 5);

  // The leg still imports: the ground joint is not part of the leg's chain.
  const CliRun imported = runSwingsim("import-osim " + osim.string() + " --out " + (dir / "back.yaml").string());
  ASSERT_EQ(imported.code, 0) << imported.output;
  EXPECT_NEAR(loadParticipant((dir / "back.yaml").string()).thigh.length, loadParticipant(participant).thigh.length,
              1e-12);
}

TEST(ExportOsimPelvisCli, HipMomentDriveKeepsTheWeldedPelvis) {
  const auto dir = freshTempDir("ExportOsimPelvisCli", "welded");
  const CliRun run = runSwingsim("export-osim " + kRoot + "/participants/p1.yaml --out " + dir.string());
  ASSERT_EQ(run.code, 0) << run.output;
  const OsimModel model = loadOsimModel((dir / "P1-lower000mm.osim").string());
  EXPECT_EQ(model.getJointTo("pelvis").type, "WeldJoint");
  EXPECT_TRUE(model.getJointTo("pelvis").coordinates.empty());
}

}  // namespace
}  // namespace swingsim::testing
