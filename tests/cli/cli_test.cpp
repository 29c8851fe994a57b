// The command line end to end: usage, exit codes, outputs, and no output on bad input.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "run_swingsim.h"

namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

using swingsim::testing::CliRun;
CliRun run(const std::string& args) { return swingsim::testing::runSwingsim(args); }

fs::path freshDir(const std::string& name) {
  fs::path d = fs::temp_directory_path() / ("swingsim_cli_test_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

TEST(Cli, NoArgumentsPrintsUsageListingEveryCommand) {
  CliRun r = run("");
  EXPECT_EQ(r.code, 2);
  for (const char* c : {"simulate", "sweep", "calibrate"}) EXPECT_THAT(r.output, HasSubstr(c));
}

TEST(Cli, UnknownOptionIsAUsageError) {
  CliRun r = run("simulate participants/p1.yaml --lowring 0.1");
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.output, HasSubstr("unknown option --lowring"));
}

TEST(Cli, SimulateWritesTrajectoryStoAndJson) {
  fs::path out = freshDir("simulate");
  CliRun r = run("simulate participants/p1.yaml --lowering 0.05 --out " + out.string() + " --json " + (out / "r.json").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("swing time"));
  EXPECT_THAT(r.output, HasSubstr("peak knee flexion"));
  std::ifstream sto(out / "P1-lower050mm.sto");
  std::stringstream s;
  s << sto.rdbuf();
  EXPECT_THAT(s.str(), HasSubstr("version=1\nnRows="));
  EXPECT_THAT(s.str(), HasSubstr("inDegrees=yes\nendheader\ntime\t"));
  std::ifstream js(out / "r.json");
  std::stringstream j;
  j << js.rdbuf();
  for (const char* key : {"\"swing_time_s\"", "\"peak_knee_flexion_deg\"", "\"peak_knee_flexion_time_s\"", "\"bounce\"",
                          "\"events\":[{\"name\":\"toe_off\""})
    EXPECT_THAT(j.str(), HasSubstr(key));
  EXPECT_TRUE(fs::exists(out / "P1-lower050mm.csv"));
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
  CliRun r = run("simulate " + (out / "bad.yaml").string() + " --out " + (out / "o").string() + " --json " + (out / "r.json").string());
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

}  // namespace
