// `swingsim simulate` on a measured trial that ends before the swing does (Winter's walking
// subject, cut at heel contact with the knee still flexed): a result, written and exit 0;
// what the swing did not have prints "none" and is null in the JSON; a knee flung past
// 180 deg is a failed run.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/json_file.h"
#include "run_swingsim.h"

namespace {

using swingsim::Json;
using ::testing::HasSubstr;
using ::testing::Not;
namespace fs = std::filesystem;

TEST(SimulateCommand, MeasuredTrialEndingBeforeTheSwingIsAResult) {
  const fs::path out = swingsim::testing::freshTempDir("swingsim_simulate_command_test", "winter");
  const auto r = swingsim::testing::runSwingsim("simulate participants/winter.yaml --out " + out.string() + " --json " +
                                                (out / "r.json").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("swing time          not reached (knee_zone)"));
  EXPECT_THAT(r.output, HasSubstr("the measured trial ended at "));
  // The drive file (time_s, hip_flexion_deg, knee_flexion_deg) has the measured knee.
  EXPECT_THAT(r.output, HasSubstr("measured knee"));
  EXPECT_TRUE(fs::exists(out / "winter-lower000mm.csv"));
  EXPECT_TRUE(fs::exists(out / "winter-lower000mm.sto"));
  EXPECT_TRUE(fs::exists(out / "winter-lower000mm-moments.svg"));
  std::ifstream js(out / "r.json");
  const Json j = Json::parse(js);
  ASSERT_TRUE(j.contains("trial_end"));
  EXPECT_EQ(j["trial_end"]["unmet"], "knee_zone");
  // The knee above its zone of stability at the trial's end, by the amount printed.
  EXPECT_GT(j["trial_end"]["knee_flexion_deg"].get<double>(), j["trial_end"]["zone_of_stability_deg"].get<double>());
  EXPECT_TRUE(j["swing_time_s"].is_null());  // NaN: no swing end
}

// Winter's subject with a zone of stability above anything the walking knee reaches: the
// knee never peaks above it, so the swing has no peak knee flexion and no toe clearance.
std::string writeWinterWithoutAKneePeak() {
  std::string text = swingsim::testing::slurp("participants/winter.yaml");
  const fs::path folder = fs::absolute("participants");
  auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace("zone_of_stability_deg: 6", "zone_of_stability_deg: 150");
  replace("../models/", (folder / "../models/").string());
  replace("../studies/", (folder / "../studies/").string());
  return swingsim::testing::writeSuiteTempFile("swingsim_simulate_command_test", "winter-no-peak.yaml", text);
}

TEST(SimulateCommand, NoKneePeakPrintsNoneAndWritesNull) {
  const std::string participant = writeWinterWithoutAKneePeak();
  const fs::path out = swingsim::testing::freshTempDir("swingsim_simulate_command_test", "no-peak");
  const auto r = swingsim::testing::runSwingsim("simulate " + participant + " --out " + out.string() + " --json " +
                                                (out / "r.json").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("swing time          not reached (knee_peak)"));
  EXPECT_THAT(r.output, HasSubstr("peak knee flexion   none"));
  EXPECT_THAT(r.output, HasSubstr("min toe clearance   none"));
  EXPECT_THAT(r.output, Not(HasSubstr("e+")));  // no marker number in any notation
  std::ifstream js(out / "r.json");
  const Json j = Json::parse(js);
  for (const char* key : {"swing_time_s", "peak_knee_flexion_deg", "peak_knee_flexion_time_s", "bounce_height_deg",
                          "min_toe_clearance_m"})
    EXPECT_TRUE(j[key].is_null()) << key << ": " << j[key];
  EXPECT_TRUE(j["trial_end"]["settle_dwell_done_s"].is_null());
}

TEST(SimulateCommand, KneePastItsRangeFailsWithWhatAndWhen) {
  const fs::path out = swingsim::testing::freshTempDir("swingsim_simulate_command_test", "knee-past-range");
  const auto r = swingsim::testing::runSwingsim(
      "simulate participants/winter.yaml --knee-start initial --knee-rate-deg-s 3000 --out " + out.string() +
      " --json " + (out / "r.json").string());
  EXPECT_NE(r.code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("swingsim: winter at lowering 0 m: the knee flexion passed 180 deg at "));
  EXPECT_FALSE(fs::exists(out / "r.json"));  // a failed run writes no result
}

}  // namespace

namespace {

// The case: a measured-thigh participant cut to one running swing (the public
// Rajagopal run, `swing: 1`) starts its knee where the record does and prints the real peak,
// never a marker number; the old start stays available (and here fails, the knee passing
// 180 deg), and a knee rate given on top of the record's is refused with the option that
// allows it.
std::string writeWinterOnARunningSwing() {
  std::string text = swingsim::testing::slurp("participants/winter.yaml");
  const fs::path root = fs::absolute(".");
  const std::string from = "thigh_kinematics: ../studies/data/winter-swing/swing1.csv";
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos);
  text.replace(
      at, from.size(),
      "thigh_kinematics: {file: " + (root / "tests/data/opensim-running/rajagopal_subject01_run_ik.mot").string() +
          ", hip: hip_flexion_r, knee: knee_angle_r, knee_sign: 1, pelvis_tilt: pelvis_tilt, swing: 1}");
  const auto model = text.find("../models/");
  EXPECT_NE(model, std::string::npos);
  text.replace(model, 10, (root / "models/").string());
  // A runner's swing: the running event rules (Winter's file states walking).
  const std::string walking = "toe_clearance:\n  gait: walking";
  const auto gait = text.find(walking);
  EXPECT_NE(gait, std::string::npos);
  text.replace(gait, walking.size(), "toe_clearance:\n  gait: running");
  return swingsim::testing::writeSuiteTempFile("swingsim_simulate_command_test", "winter-run.yaml", text);
}

TEST(SimulateCommand, AMeasuredSwingStartsWhereTheRecordDoesAndPrintsNoMarker) {
  const std::string participant = writeWinterOnARunningSwing();
  const fs::path out = swingsim::testing::freshTempDir("swingsim_simulate_command_test", "run");
  const auto r = swingsim::testing::runSwingsim("simulate " + participant + " --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  // The record's knee at toe-off (Rajagopal's runner: 17.9 deg, flexing at 103 deg/s), not the participant's 46.7 deg.
  EXPECT_THAT(
      r.output,
      HasSubstr("toe-off             knee 17.9 deg, 103.5 deg/s (the record's, smoothing-spline value and slope)"));
  EXPECT_THAT(r.output, HasSubstr("peak knee flexion   132.9 deg at 0.3020 s"));
  EXPECT_THAT(r.output, Not(HasSubstr("e+")));
  EXPECT_THAT(r.output, HasSubstr("samples over 0.4406 s"));  // a time to 0.1 ms, not 16 digits
  const auto refused =
      swingsim::testing::runSwingsim("simulate " + participant + " --knee-rate-deg-s 100 --out " + out.string());
  EXPECT_EQ(refused.code, 1);
  EXPECT_THAT(refused.output,
              HasSubstr("--knee-rate-deg-s: under the measured thigh drive the knee starts at the record's"));
  EXPECT_THAT(refused.output, HasSubstr("add --knee-start initial"));
  // The old start (the participant's 46.7 deg at 386 deg/s) flings the knee past 180 deg, the
  // issue's "knee reached 181 deg": now a failed run saying what and when, not a result.
  const auto initial =
      swingsim::testing::runSwingsim("simulate " + participant + " --knee-start initial --out " + out.string());
  EXPECT_EQ(initial.code, 1);
  EXPECT_THAT(initial.output,
              HasSubstr("the knee flexion passed 180 deg at 0.2518 s, beyond the knee's physical range"));
}

}  // namespace
