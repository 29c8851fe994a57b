// The command line end to end: usage, exit codes, outputs, and no output on bad input.
#include <gmock/gmock.h>

#include <gtest/gtest.h>
#include <map>
#include <vector>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/json_file.h"
#include "run_swingsim.h"

namespace {

using swingsim::Json;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

using swingsim::testing::CliRun;
CliRun run(const std::string& args) { return swingsim::testing::runSwingsim(args); }

fs::path freshDir(const std::string& name) { return swingsim::testing::freshTempDir("swingsim_cli_test", name); }

TEST(Cli, NoArgumentsPrintsUsageListingEveryCommand) {
  CliRun r = run("");
  EXPECT_EQ(r.code, 2);
  for (const char* c : {"simulate", "sweep", "calibrate", "merge", "swings", "import-osim"})
    EXPECT_THAT(r.output, HasSubstr(c));
}

// Every option of every subcommand is in its --help (CLI11 builds it from the registry), and
// --version names the version.
TEST(Cli, HelpListsEveryOptionAndVersionPrintsIt) {
  const std::map<std::string, std::vector<std::string>> options = {
      {"simulate",
       {"--lowering", "--knee", "--add-mass", "--hip-rate-deg-s", "--knee-rate-deg-s", "--integrator", "--accuracy",
        "--json", "--out"}},
      {"sweep", {"--out", "--json", "--jobs", "--add-mass", "--uncertainty", "--seed", "--shard"}},
      {"merge", {"SHARD_FILES", "--out", "--json", "--jobs"}},
      {"calibrate", {"--target", "--dry-run"}},
      {"fit", {"--out", "--json"}},
      {"compare", {"--out", "--json"}},
      {"diagnose", {"--out", "--json", "--save-model"}},
      {"generate", {"--out"}},
      {"swings", {"FILE.mot", "--side", "--grf", "--vertical-force", "--threshold-N", "--knee-sign", "--json"}},
      {"import-osim",
       {"MODEL.osim", "--side", "--out", "--name", "--knee", "--knee-friction-Nm", "--shank-mass-kg", "--foot-mass-kg",
        "--foot-length-m", "--height-m"}}};
  for (const auto& [command, flags] : options) {
    const CliRun r = run(command + " --help");
    EXPECT_EQ(r.code, 0) << command;
    for (const auto& f : flags) EXPECT_THAT(r.output, HasSubstr(f)) << command;
  }
  const CliRun v = run("--version");
  EXPECT_EQ(v.code, 0);
  EXPECT_THAT(v.output, HasSubstr("swingsim 0."));
}

TEST(Cli, UnknownOptionIsAUsageError) {
  CliRun r = run("simulate participants/p1.yaml --lowring 0.1");
  EXPECT_EQ(r.code, 2);
  // CLI11's wording: "The following arguments were not expected: 0.1 --lowring" (the value
  // too, as the command takes one positional).
  EXPECT_THAT(r.output, HasSubstr("not expected: "));
  EXPECT_THAT(r.output, HasSubstr("--lowring"));
}

TEST(Cli, SimulateWritesTrajectoryStoAndJson) {
  fs::path out = freshDir("simulate");
  CliRun r = run("simulate participants/p1.yaml --lowering 0.05 --out " + out.string() + " --json " +
                 (out / "r.json").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("swing time"));
  EXPECT_THAT(r.output, HasSubstr("peak knee flexion"));
  std::ifstream sto(out / "P1-lower050mm.sto");
  std::stringstream s;
  s << sto.rdbuf();
  EXPECT_THAT(s.str(), HasSubstr("version=1\nnRows="));
  EXPECT_THAT(s.str(), HasSubstr("inDegrees=yes\nendheader\ntime\t"));
  std::ifstream js(out / "r.json");
  const Json j = Json::parse(js);
  for (const char* key : {"participant", "lowering_m", "swing_time_s", "peak_knee_flexion_deg",
                          "peak_knee_flexion_time_s", "bounce", "min_toe_clearance_m", "events"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["events"][0]["name"], "toe_off");
  EXPECT_DOUBLE_EQ(j["lowering_m"].get<double>(), 0.05);
  EXPECT_TRUE(fs::exists(out / "P1-lower050mm.csv"));
}

// --integrator picks Simbody's own integrator at its converged accuracy; the swing time is
// the same to the converged 0.1 ms; a wrong name or accuracy is a usage error.
TEST(Cli, SimulateChoosesTheIntegrator) {
  const fs::path out = freshDir("integrator");
  auto swingTime = [](const std::string& output) {
    const auto p = output.find("swing time");
    return std::stod(output.substr(output.find_first_of("0123456789", p)));
  };
  const CliRun dp = run("simulate participants/p1.yaml --out " + out.string());
  ASSERT_EQ(dp.code, 0) << dp.output;
  EXPECT_THAT(dp.output,
              HasSubstr("integrator          Dormand-Prince 5(4) over Simbody realizations, accuracy 1e-05"));
  const CliRun rkm = run("simulate participants/p1.yaml --integrator runge-kutta-merson --out " + out.string());
  ASSERT_EQ(rkm.code, 0) << rkm.output;
  EXPECT_THAT(rkm.output, HasSubstr("integrator          Simbody Runge-Kutta-Merson, accuracy 0.0001"));
  EXPECT_NEAR(swingTime(rkm.output), swingTime(dp.output), 1e-4);
  const CliRun tight = run("simulate participants/p1.yaml --accuracy 1e-7 --out " + out.string());
  EXPECT_THAT(tight.output, HasSubstr("accuracy 1e-07"));

  const CliRun badName = run("simulate participants/p1.yaml --integrator euler --out " + out.string());
  EXPECT_EQ(badName.code, 2);
  EXPECT_THAT(badName.output, HasSubstr("--integrator: expected one of dormand-prince, runge-kutta-merson"));
  EXPECT_THAT(badName.output, HasSubstr("(got 'euler')"));
  const CliRun badAccuracy = run("simulate participants/p1.yaml --accuracy 0.5 --out " + out.string());
  EXPECT_EQ(badAccuracy.code, 2);
  EXPECT_THAT(badAccuracy.output, HasSubstr("--accuracy: expected a relative accuracy in [1e-14, 0.01] (got 0.5)"));
}

TEST(Cli, BadParticipantExitsOneWithLocatedMessageAndWritesNothing) {
  fs::path out = freshDir("bad");
  std::ifstream in("participants/p1.yaml");
  std::stringstream s;
  s << in.rdbuf();
  std::string text = s.str();
  text.replace(text.find("mass_kg: 3.350"), 14, "mass_kg: -3.35");
  text.replace(text.find("../models"), 9, fs::absolute("models").string());
  std::ofstream(out / "bad.yaml") << text;
  CliRun r = run("simulate " + (out / "bad.yaml").string() + " --out " + (out / "o").string() + " --json " +
                 (out / "r.json").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.output, HasSubstr("bad.yaml:10: segments.thigh.mass_kg: must be positive (got -3.35)"));
  EXPECT_FALSE(fs::exists(out / "o"));
  EXPECT_FALSE(fs::exists(out / "r.json"));
}

TEST(Cli, LoweringBeyondTheShankExitsOneAndWritesNothing) {
  fs::path out = freshDir("lowering");
  CliRun r = run("simulate participants/p1.yaml --lowering 0.5 --out " + (out / "o").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.output, HasSubstr("leaves no room for the shank"));
  EXPECT_FALSE(fs::exists(out / "o"));
}

/// Winter's participant in `dir`, driven by `thigh` (its thigh_kinematics value); paths absolute.
fs::path writeWinterWith(const fs::path& dir, const std::string& thigh) {
  std::ifstream in(std::string(SWINGSIM_SOURCE_DIR) + "/participants/winter.yaml");
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"knee_model: ../models/", "knee_model: " + std::string(SWINGSIM_SOURCE_DIR) + "/models/"},
           {"thigh_kinematics: ../studies/data/winter-swing/swing1.csv", "thigh_kinematics: " + thigh}}) {
    const auto at = yaml.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    yaml.replace(at, from.size(), to);
  }
  // The measured pelvis moves the hip: where the hip sits in the pelvis (subject01's scaled
  // Gait2354 model, hip_r's location in the pelvis, as import-osim writes it).
  yaml += "hip_offset_in_pelvis_m: [-0.0724, -0.0677]\n";
  std::ofstream(dir / "walk.yaml") << yaml;
  return dir / "walk.yaml";
}

// OpenSim IK output as it comes, named in the participant: the right leg's labels are read.
TEST(Cli, SimulateRunsOnAnOpenSimMotParticipant) {
  const fs::path dir = freshDir("simulate-mot");
  const std::string ik = std::string(SWINGSIM_SOURCE_DIR) + "/tests/data/opensim-gait10dof/subject01_walk_IK.mot";
  CliRun r = run("simulate " + writeWinterWith(dir, ik).string() + " --out " + (dir / "out").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("swing time"));
  EXPECT_TRUE(fs::exists(dir / "out"));

  // A .mot without those labels: exit 1, the map form named, nothing written.
  std::ofstream(dir / "other.mot") << "other\ninDegrees=yes\nendheader\ntime\thip\tknee\n";
  for (int k = 0; k < 12; ++k) std::ofstream(dir / "other.mot", std::ios::app) << 0.01 * k << "\t1\t" << 5 * k << "\n";
  CliRun bad = run("simulate " + writeWinterWith(dir, (dir / "other.mot").string()).string() + " --out " +
                   (dir / "bad").string());
  EXPECT_EQ(bad.code, 1) << bad.output;
  EXPECT_THAT(bad.output, HasSubstr("hip_flexion_r: column is missing (available: time, hip, knee)"));
  EXPECT_THAT(bad.output,
              HasSubstr("thigh_kinematics: a plain .mot/.sto name is read with OpenSim's right-leg labels"));
  EXPECT_FALSE(fs::exists(dir / "bad"));
}

}  // namespace
