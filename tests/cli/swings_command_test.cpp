// End-to-end checks of `swingsim swings` through the real binary: the table and JSON on the
// public OpenSim walk, the left leg's default force column, and bad input that exits 1 or 2
// and writes nothing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/json_file.h"
#include "run_swingsim.h"

namespace {

using swingsim::Json;
using swingsim::testing::CliRun;
using swingsim::testing::runSwingsim;
using swingsim::testing::slurp;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

const std::string kRoot = SWINGSIM_SOURCE_DIR;
const std::string kIk = kRoot + "/studies/data/opensim-subject01/gait2392_subject01_walk1_ik.mot";
const std::string kGrf = kRoot + "/studies/data/opensim-subject01/subject01_walk1_grf.mot";

fs::path scratch(const std::string& name) {
  return swingsim::testing::freshTempDir("swingsim_swings_command_test", name);
}

TEST(SwingsCommand, ListsForceSwingsThenKinematicOnesWithJson) {
  const auto dir = scratch("good");
  const CliRun r = runSwingsim("swings " + kIk + " --grf " + kGrf + " --json " + (dir / "s.json").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("swing  toe-off s  heel contact s  duration s  toe-off from  heel contact from"));
  // The right foot's force falls below 20 N at 1.4086 s and rises above it at 1.8522 s.
  EXPECT_THAT(r.output, HasSubstr("    1     1.4086          1.8522      0.4436  grf           grf"));
  const Json j = Json::parse(slurp(dir / "s.json"));
  EXPECT_EQ(j["side"], "r");
  EXPECT_EQ(j["pelvis_tilt"], "pelvis_tilt");
  EXPECT_EQ(j["grf"]["vertical_force"], "ground_force_vy");
  ASSERT_GE(j["swings"].size(), 2u);
  EXPECT_EQ(j["swings"][0]["swing"], 1);
  EXPECT_EQ(j["swings"][0]["toe_off_source"], "grf");
  EXPECT_EQ(j["swings"][1]["toe_off_source"], "kinematics");
  EXPECT_GT(j["swings"][1]["toe_off_s"].get<double>(), 2.5);  // after the force plates' last row
}

TEST(SwingsCommand, TheLeftLegReadsTheSecondFootsForce) {
  const CliRun r = runSwingsim("swings " + kIk + " --side l --grf " + kGrf);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("left leg (hip_flexion_l, knee_angle_l x -1, + pelvis_tilt)"));
  EXPECT_THAT(r.output, HasSubstr("1_ground_force_vy below 20 N"));
  // The left foot's force: toe-off 0.7882 s, heel contact 1.2452 s.
  EXPECT_THAT(r.output, HasSubstr("    1     0.7882          1.2452      0.4570  grf           grf"));
}

const std::string kRunIk = kRoot + "/tests/data/opensim-running/rajagopal_subject01_run_ik.mot";
const std::string kRunGrf = kRoot + "/tests/data/opensim-running/rajagopal_grf_run.mot";

TEST(SwingsCommand, ARunGetsTheRunningRulesAndEachEventsDisagreement) {
  const auto dir = scratch("run");
  const CliRun r = runSwingsim("swings " + kRunIk + " --knee-sign 1 --grf " + kRunGrf +
                               " --vertical-force R_ground_force_vy --json " + (dir / "s.json").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("gait: running (detected: median stride 0.69 s, under 0.85 s)"));
  EXPECT_THAT(
      r.output,
      HasSubstr(
          "more than 2 frames at this file's 100 Hz: the kinematics alone cannot place an event within 2 frames"));
  // The right foot's force: toe-off 0.4178 s, heel contact 0.8678 s; the kinematics' 0.3 ms later and 9.1 ms earlier.
  EXPECT_THAT(r.output, HasSubstr("    1     0.4178          0.8678      0.4500  grf           grf"));
  EXPECT_THAT(r.output, HasSubstr("-0.3          +9.1"));
  const Json j = Json::parse(slurp(dir / "s.json"));
  EXPECT_EQ(j["gait"], "running");
  EXPECT_NEAR(j["swings"][0]["toe_off_force_minus_kinematics_ms"].get<double>(), -0.3, 0.05);
  // Stated walking on a run: the walking rules' toe-offs land 60-120 ms late, so the force is refused.
  const CliRun walking = runSwingsim("swings " + kRunIk + " --knee-sign 1 --gait walking --grf " + kRunGrf +
                                     " --vertical-force R_ground_force_vy");
  EXPECT_EQ(walking.code, 1);
  EXPECT_THAT(walking.output, HasSubstr("walking rules"));
}

TEST(SwingsCommand, TheOtherFootsColumnIsRefusedOrGivesWayWhenAsked) {
  const auto dir = scratch("other");
  const std::string json = (dir / "s.json").string();
  const CliRun refused =
      runSwingsim("swings " + kIk + " --grf " + kGrf + " --vertical-force 1_ground_force_vy --json " + json);
  EXPECT_EQ(refused.code, 1);
  EXPECT_THAT(
      refused.output,
      HasSubstr(
          "they match the other leg's (hip_flexion_l, knee_angle_l): is 1_ground_force_vy the other foot's force?"));
  EXPECT_FALSE(fs::exists(json));
  const CliRun fallback = runSwingsim("swings " + kIk + " --grf " + kGrf +
                                      " --vertical-force 1_ground_force_vy --fallback-to-kinematics --json " + json);
  ASSERT_EQ(fallback.code, 0) << fallback.output;
  EXPECT_THAT(fallback.output, HasSubstr("note: events from the kinematics, not the force (fallback_to_kinematics): "));
  EXPECT_THAT(fallback.output, HasSubstr("kinematics    kinematics"));
  const Json j = Json::parse(slurp(json));
  ASSERT_EQ(j["notes"].size(), 1u);
  EXPECT_EQ(j["swings"][0]["toe_off_source"], "kinematics");
  EXPECT_TRUE(j["swings"][0]["toe_off_force_minus_kinematics_ms"].is_null());
}

TEST(SwingsCommand, BadInputExitsWithAMessageAndWritesNothing) {
  const auto dir = scratch("bad");
  const std::string json = (dir / "s.json").string();
  const CliRun column = runSwingsim("swings " + kIk + " --grf " + kGrf + " --vertical-force force_vy --json " + json);
  EXPECT_EQ(column.code, 1);
  EXPECT_THAT(column.output,
              HasSubstr("subject01_walk1_grf.mot:7: force_vy: column is missing (available: time, ground_force_vx"));
  const CliRun side = runSwingsim("swings " + kIk + " --side x");
  EXPECT_EQ(side.code, 2);
  EXPECT_THAT(side.output, HasSubstr("expected one of r, l (got 'x')"));
  const CliRun sign = runSwingsim("swings " + kIk + " --knee-sign 2");
  EXPECT_EQ(sign.code, 2);
  EXPECT_THAT(sign.output, HasSubstr("expected +1 or -1"));
  // The force file as kinematics: it has no hip_flexion_r.
  const CliRun hip = runSwingsim("swings " + kGrf + " --json " + json);
  EXPECT_EQ(hip.code, 1);
  EXPECT_THAT(hip.output, HasSubstr("hip_flexion_r: column is missing"));
  EXPECT_FALSE(fs::exists(json));
}

// Issue 57: the force's options without --grf were ignored without a word.
TEST(SwingsCommand, ForceOptionsWithoutAForceFileAreRefused) {
  for (const char* option : {"--threshold-N 30", "--vertical-force 1_ground_force_vy", "--fallback-to-kinematics"}) {
    const CliRun r = runSwingsim("swings " + kIk + " " + option);
    EXPECT_NE(r.code, 0) << option;
    EXPECT_THAT(r.output, HasSubstr("requires --grf")) << option << ": " << r.output;
  }
}

}  // namespace
