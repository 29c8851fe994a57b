// `swingsim export-osim --side` and `--add-mass`, with `simulate --side`: the left leg's model
// plays simulate's left .sto and a lab's IK file, import-osim --side l gives it back, an added
// mass is a welded body whose mass the model's total carries, and bad options write nothing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "io/motion_file.h"
#include "io/osim_model.h"
#include "io/participant_loader.h"
#include "model/leg_parameters.h"
#include "run_swingsim.h"

namespace swingsim::testing {
namespace {

using ::testing::Contains;
using ::testing::HasSubstr;

const std::string kP1 = std::string(SWINGSIM_SOURCE_DIR) + "/participants/p1.yaml";
const std::string kLabIk = std::string(SWINGSIM_SOURCE_DIR) + "/tests/data/opensim-gait10dof/subject01_walk_IK.mot";
// import-osim writes numbers in full; its arithmetic adds a few ulps of 1 m (or of 100 kg).
constexpr double kRoundTrip = 1e-12;
constexpr double kMassSum = 1e-10;

TEST(ExportOsimSideCli, LeftModelPlaysSimulatesLeftStoAndTheLabsIkAndImportsBack) {
  const auto dir = freshTempDir("ExportOsimSideCli", "left");
  const CliRun exported = runSwingsim("export-osim " + kP1 + " --side l --lowering 0.01 --out " + dir.string());
  ASSERT_EQ(exported.code, 0) << exported.output;
  EXPECT_THAT(exported.output, HasSubstr("left leg"));
  const CliRun simulated = runSwingsim("simulate " + kP1 + " --side l --lowering 0.01 --out " + dir.string());
  ASSERT_EQ(simulated.code, 0) << simulated.output;
  const OsimModel model = loadOsimModel((dir / "P1-lower010mm.osim").string());
  const MotionTable sto = readMotionTable((dir / "P1-lower010mm.sto").string());
  const MotionTable lab = readMotionTable(kLabIk);
  int coordinates = 0;
  for (const auto& j : model.joints)
    for (const auto& c : j.coordinates) {
      ++coordinates;
      EXPECT_THAT(sto.labels, Contains(c.name));
      EXPECT_THAT(lab.labels, Contains(c.name));
    }
  EXPECT_EQ(coordinates, 2);
  EXPECT_EQ(model.getJointTo("tibia_l").coordinates.at(0).name, "knee_angle_l");
  EXPECT_EQ(model.getJointTo("femur_l").coordinates.at(0).name, "hip_flexion_l");
  // The simulated knee bends negative, as the lab's and the model's knee_angle_l.
  const auto& knee = sto.column("knee_angle_l");
  EXPECT_LT(*std::min_element(knee.begin(), knee.end()), -60);

  const auto yaml = dir / "back.yaml";
  const CliRun imported =
      runSwingsim("import-osim " + (dir / "P1-lower010mm.osim").string() + " --side l --out " + yaml.string());
  ASSERT_EQ(imported.code, 0) << imported.output;
  const LegGeometry g = calcLegGeometry(loadParticipant(kP1), 0.01),
                    h = calcLegGeometry(loadParticipant(yaml.string()), 0);
  EXPECT_NEAR(h.thighLength, g.thighLength, kRoundTrip);
  EXPECT_NEAR(h.shankLength, g.shankLength, kRoundTrip);
  EXPECT_NEAR(h.shankCom, g.shankCom, kRoundTrip);
  EXPECT_NEAR(h.footInertia, g.footInertia, kRoundTrip);
}

TEST(ExportOsimSideCli, AddedMassIsAWeldedBodyTheTotalMassCarries) {
  const auto dir = freshTempDir("ExportOsimSideCli", "mass");
  const CliRun run = runSwingsim("export-osim " + kP1 + " --add-mass 0.6@0.15 --out " + dir.string());
  ASSERT_EQ(run.code, 0) << run.output;
  EXPECT_THAT(run.output, HasSubstr("added mass 0.6 kg"));
  const OsimModel model = loadOsimModel((dir / "P1-lower000mm.osim").string());
  const Participant p1 = loadParticipant(kP1);
  EXPECT_NEAR(model.calcTotalMass(), p1.bodyMass + 0.6, kMassSum);
  EXPECT_EQ(model.getBody("added_mass_r").mass, 0.6);
  const OsimJoint& weld = model.getJointTo("added_mass_r");
  EXPECT_EQ(weld.type, "WeldJoint");
  EXPECT_EQ(weld.parentBody, "tibia_r");
  EXPECT_NEAR(weld.calcCentreInParent().y(), -0.15, kRoundTrip);
}

TEST(ExportOsimSideCli, BadSideOrMassOffTheShankWritesNothing) {
  const auto dir = freshTempDir("ExportOsimSideCli", "bad");
  const CliRun side = runSwingsim("export-osim " + kP1 + " --side x --out " + dir.string());
  EXPECT_EQ(side.code, 2) << side.output;
  EXPECT_THAT(side.output, HasSubstr("--side"));
  const CliRun offShank = runSwingsim("export-osim " + kP1 + " --add-mass 0.5@0.9 --out " + dir.string());
  EXPECT_EQ(offShank.code, 1) << offShank.output;
  EXPECT_THAT(offShank.output, HasSubstr("added mass"));
  const CliRun badSpec = runSwingsim("export-osim " + kP1 + " --add-mass 0.5kg --out " + dir.string());
  EXPECT_EQ(badSpec.code, 2) << badSpec.output;
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace swingsim::testing
