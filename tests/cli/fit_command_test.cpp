// End-to-end checks of `swingsim generate` and `swingsim fit` through the real binary.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
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

using RunResult = swingsim::testing::CliRun;
RunResult run(const std::string& args) { return swingsim::testing::runSwingsim(args); }

using swingsim::testing::slurp;

fs::path scratch(const std::string& name) { return swingsim::testing::freshTempDir("swingsim_fit_command_test", name); }

const std::string kRoot = SWINGSIM_SOURCE_DIR;

std::string study(const std::string& train) {
  return "kind: cylinder-fit\nname: t\nmodels:\n  - " + kRoot + "/models/mauch-4phase.yaml\ntrain:\n  - " + train +
         "\n";
}

TEST(FitCommand, GenerateIsReproducibleAndFitWritesTheIssueJsonShape) {
  const auto dir = scratch("good");
  ASSERT_EQ(run("generate " + kRoot + "/studies/mauch2014-bench.yaml --out " + (dir / "a").string()).code, 0);
  ASSERT_EQ(run("generate " + kRoot + "/studies/mauch2014-bench.yaml --out " + (dir / "b").string()).code, 0);
  EXPECT_EQ(slurp(dir / "a" / "normal.csv"), slurp(dir / "b" / "normal.csv"));
  EXPECT_THAT(slurp(dir / "a" / "normal.csv"), ::testing::StartsWith("time_s,position_m,force_N\n"));
  // The committed study data are what the committed study generates.
  EXPECT_EQ(slurp(dir / "a" / "fast.csv"), slurp(kRoot + "/studies/data/mauch2014/fast.csv"));

  std::ofstream(dir / "s.yaml") << study((dir / "a" / "normal.csv").string()) + "validate:\n  - " +
                                       (dir / "a" / "slow.csv").string() + "\n";
  const RunResult r = run("fit " + (dir / "s.yaml").string() + " --out " + (dir / "out").string() + " --json " +
                          (dir / "r.json").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("mauch-4phase"));
  const Json json = Json::parse(slurp(dir / "r.json"));
  ASSERT_EQ(json["models"].size(), 1u);
  const Json& m = json["models"][0];
  EXPECT_EQ(m["model"], "mauch-4phase");
  ASSERT_EQ(m["coefficients"].size(), 4u);
  for (const char* key : {"phase", "f_N", "k_N_per_m", "c_Ns_per_m"})
    EXPECT_TRUE(m["coefficients"][0].contains(key)) << key;
  EXPECT_EQ(m["coefficients"][0]["phase"], 1);
  for (const char* file : {"normal", "slow"})
    for (const char* key : {"me_N", "rmse_N", "r2"})
      EXPECT_TRUE(m["metrics"][file].contains(key)) << file << " " << key;
  EXPECT_TRUE(fs::exists(dir / "out" / "report.md"));
  EXPECT_TRUE(fs::exists(dir / "out" / "mauch-4phase-slow-force.svg"));
  EXPECT_TRUE(fs::exists(dir / "out" / "mauch-4phase-normal-loop.svg"));
}

TEST(FitCommand, BadBenchFilesFailWithLocationAndWriteNothing) {
  const auto dir = scratch("bad");
  struct Case {
    std::string csv, expected;
  };
  const std::vector<Case> cases = {
      {"time_s,position_m\n0,0\n", "bad.csv:1: force_N: required column is missing"},
      {"time_s,position_m,force_N\n0,0,1\n0,0.01,2\n", "bad.csv:3: time_s: must be strictly increasing"},
      {"time_s,position_m,force_N\n0,0,1\n0.1,NaN,2\n", "bad.csv:3: position_m: expected a finite number"},
      {"time_s,position_m,force_N\n0,0,1\n0.1,0.01,2\n0.2,0.02,3\n", "too few data rows (got 3, need at least 13)"},
  };
  for (const auto& c : cases) {
    std::ofstream(dir / "bad.csv") << c.csv;
    std::ofstream(dir / "s.yaml") << study((dir / "bad.csv").string());
    const RunResult r = run("fit " + (dir / "s.yaml").string() + " --out " + (dir / "out").string() + " --json " +
                            (dir / "r.json").string());
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_THAT(r.output, HasSubstr(c.expected));
    EXPECT_FALSE(fs::exists(dir / "out"));
    EXPECT_FALSE(fs::exists(dir / "r.json"));
  }
  // A model YAML with a phase missing: the model file and line are named.
  std::string model = slurp(kRoot + "/models/mauch-4phase.yaml");
  model.erase(model.find("      - {phase: 3"), model.find("      - {phase: 4") - model.find("      - {phase: 3"));
  std::ofstream(dir / "m.yaml") << model;
  std::ofstream(dir / "s.yaml") << "kind: cylinder-fit\nname: t\nmodels:\n  - m.yaml\ntrain:\n  - " + kRoot +
                                       "/studies/data/mauch2014/normal.csv\n";
  const RunResult r = run("fit " + (dir / "s.yaml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.output, HasSubstr("m.yaml:"));
  EXPECT_THAT(r.output, HasSubstr("settings[0].coefficients: phase 3 is missing"));
  EXPECT_FALSE(fs::exists(dir / "out"));
  EXPECT_EQ(run("fit").code, 2);
}

}  // namespace
