// `swingsim tune` through the real binary: the shipped example, a re-run of `simulate` with
// the tuned files, and Ctrl-C (the test stop hook) leaving nothing written.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>

#include "io/json_file.h"
#include "release_only.h"
#include "run_swingsim.h"

namespace {

namespace fs = std::filesystem;
using swingsim::Json;
using swingsim::testing::runSwingsim;
using swingsim::testing::slurp;

const std::string kRoot = SWINGSIM_SOURCE_DIR;
const std::string kStudy = kRoot + "/studies/tune-p1-damping.yaml";

fs::path scratch(const std::string& name) { return swingsim::testing::freshTempDir("swingsim_tune_cli_test", name); }

// The number after `label` in `text` (NaN if absent).
double numberAfter(const std::string& text, const std::string& label) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex(label + R"( +([-0-9.]+))"))) return std::nan("");
  return std::stod(m[1]);
}

TEST(TuneCli, TheTunedFilesRerunBySimulateGiveTheReportedSwing) {
  SWINGSIM_RELEASE_ONLY();
  const auto dir = scratch("rerun");
  const auto tune =
      runSwingsim("tune " + kStudy + " --out " + (dir / "out").string() + " --json " + (dir / "t.json").string());
  ASSERT_EQ(tune.code, 0) << tune.output;
  for (const char* name : {"tuned-knee.yaml", "tuning.md", "tuning.json", "tradeoff.svg"})
    EXPECT_TRUE(fs::exists(dir / "out" / name));
  const Json j = Json::parse(slurp(dir / "t.json"));
  EXPECT_EQ(slurp(dir / "t.json"), slurp(dir / "out" / "tuning.json"));
  const std::string command = j["simulate_command"];
  ASSERT_EQ(command.rfind("swingsim simulate ", 0), 0u) << command;
  const auto sim = runSwingsim(command.substr(9) + " --out " + (dir / "sim").string());
  ASSERT_EQ(sim.code, 0) << sim.output;
  // simulate prints 4 decimals of a second and 1 of a degree; the tuning's JSON has every digit.
  EXPECT_NEAR(numberAfter(sim.output, "swing time"), j["swing"]["swing_time_s"].get<double>(), 0.5e-4);
  EXPECT_NEAR(numberAfter(sim.output, "peak knee flexion"), j["swing"]["peak_knee_flexion_deg"].get<double>(), 0.05);
  EXPECT_NEAR(numberAfter(sim.output, "min toe clearance"), j["swing"]["min_toe_clearance_m"].get<double>(), 0.5e-3);
  // Every hard limit is met by the result, with its margin.
  for (const auto& t : j["targets"])
    if (t["hard"].get<bool>()) {
      EXPECT_GE(t["margin"].get<double>(), 0.0) << t.dump();
    }
}

TEST(TuneCli, InterruptedItWritesNothingAndPrintsTheBestPointSoFar) {
  const auto dir = scratch("stop");
  ::setenv("SWINGSIM_TEST_STOP_AFTER_SWINGS", "4", 1);
  const auto r = runSwingsim("tune " + kStudy + " --jobs 1 --out " + (dir / "out").string() + " --json " +
                             (dir / "t.json").string());
  ::unsetenv("SWINGSIM_TEST_STOP_AFTER_SWINGS");
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_NE(r.output.find("nothing in " + (dir / "out").string() + " was written"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("best so far: lowering_m "), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "t.json"));
  EXPECT_TRUE(!fs::exists(dir / "out") || fs::is_empty(dir / "out"));
}

TEST(TuneCli, ABadStudyIsRefusedWithFileLineKeyAndExitCode1) {
  const auto dir = scratch("bad");
  const std::string study = swingsim::testing::writeSuiteTempFile(
      "swingsim_tune_cli_test", "bad.yaml",
      "kind: knee-tuning\nparticipant: " + kRoot +
          "/participants/p1.yaml\nknobs:\n  - key: lowering_m\n    range: [0.04, 0.01]\n"
          "targets:\n  swing_time_s: {value: sound_limb}\n");
  const auto r = runSwingsim("tune " + study + " --out " + (dir / "out").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.output.find("bad.yaml:5: knobs[0].range: expected min < max (got 0.04 >= 0.01)"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir / "out" / "tuning.md"));
}

}  // namespace

namespace {

TEST(TuneCli, HelpListsTheCommandAndItsOptionsAndABadJobsIsAUsageError) {
  EXPECT_NE(runSwingsim("--help").output.find("tune"), std::string::npos);
  const auto help = runSwingsim("tune --help");
  EXPECT_EQ(help.code, 0);
  for (const char* flag : {"STUDY.yaml", "--out", "--json", "--jobs"})
    EXPECT_NE(help.output.find(flag), std::string::npos) << flag;
  const auto bad = runSwingsim("tune " + kStudy + " --jobs -1");
  EXPECT_EQ(bad.code, 2) << bad.output;
}

}  // namespace

namespace {

TEST(TuneCli, ItRefusesToWriteOverItsOwnStudy) {
  const auto dir = scratch("over-input");
  const std::string study = (dir / "study.yaml").string();
  fs::copy_file(kStudy, study);
  // The copy's relative paths point nowhere: name P1 and the model absolutely.
  std::string text = slurp(study);
  text.replace(text.find("../participants"), 2, kRoot + "/studies/..");
  text.replace(text.find("../models"), 2, kRoot + "/studies/..");
  std::ofstream(study) << text;
  const auto r = runSwingsim("tune " + study + " --out " + (dir / "out").string() + " --json " + study);
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_NE(r.output.find("would write over the input"), std::string::npos) << r.output;
  EXPECT_EQ(slurp(study), text);
  EXPECT_FALSE(fs::exists(dir / "out" / "tuning.md"));
}

}  // namespace
