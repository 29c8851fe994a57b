// Cohort studies end to end with the real binary: a tiny cohort (4 participants, lowerings
// 0, 0.05 and 0.10 m) run whole, run as 3 shards and merged (report, CSV, figures and JSON
// byte for byte the whole run's), interrupted (the test hook stops it after 2 participants,
// as Ctrl-C would) and resumed to the same result, and a shard set with a shard missing or
// from another seed refused with file, key, expected and found, nothing written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "run_swingsim.h"

namespace {

namespace fs = std::filesystem;
using swingsim::testing::freshTempDir;
using swingsim::testing::runSwingsim;
using swingsim::testing::ScopedEnv;
using swingsim::testing::slurp;
using ::testing::HasSubstr;

const std::string kRoot = SWINGSIM_SOURCE_DIR;
const std::string kSuite = "swingsim-cohort-cli";

// The shipped example's distributions with 6 participants and a short grid.
fs::path writeTinyCohort(const fs::path& dir, int seed) {
  std::string text = slurp(kRoot + "/studies/cohort-example.yaml");
  auto swap = [&](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  };
  swap("participants: 120", "participants: 4");
  swap("seed: 2004", "seed: " + std::to_string(seed));
  swap("template: ../participants/p1.yaml", "template: " + kRoot + "/participants/p1.yaml");
  swap("max_m: 0.200", "max_m: 0.100");
  swap("step_m: 0.010", "step_m: 0.050");
  const auto path = dir / ("tiny-cohort-" + std::to_string(seed) + ".yaml");
  std::ofstream(path) << text;
  return path;
}

std::map<std::string, std::string> readTree(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file()) files[e.path().filename().string()] = slurp(e.path());
  return files;
}

TEST(CohortCli, ShardsMergeAndResumeToTheWholeRunByteForByte) {
  const fs::path dir = freshTempDir(kSuite, "shards");
  const std::string study = writeTinyCohort(dir, 5).string();
  const fs::path whole = dir / "whole", merged = dir / "merged", shards = dir / "shards", resumed = dir / "resumed";

  const auto one = runSwingsim("sweep " + study + " --out " + whole.string() + " --json " +
                               (whole / "cohort.json").string() + " --jobs 2");
  ASSERT_EQ(one.code, 0) << one.output;
  EXPECT_THAT(one.output, HasSubstr("cohort cohort-example: 4 participants (seed 5)"));
  const auto wholeFiles = readTree(whole);
  for (const char* name : {"report.md", "cohort.csv", "cohort-fastest-lowering.svg", "cohort-time-gained.svg",
                           "cohort-predictors.svg", "cohort.json"})
    EXPECT_TRUE(wholeFiles.count(name)) << name;
  EXPECT_THAT(wholeFiles.at("report.md"), HasSubstr("## What predicts the gain"));

  for (int k = 0; k < 3; ++k) {
    const auto r =
        runSwingsim("sweep " + study + " --shard " + std::to_string(k) + "/3 --out " + shards.string() + " --jobs 1");
    ASSERT_EQ(r.code, 0) << r.output;
  }
  const std::string files = (shards / "cohort-shard-0-of-3.json").string() + " " +
                            (shards / "cohort-shard-1-of-3.json").string() + " " +
                            (shards / "cohort-shard-2-of-3.json").string();
  const auto m =
      runSwingsim("merge " + files + " --out " + merged.string() + " --json " + (merged / "cohort.json").string());
  ASSERT_EQ(m.code, 0) << m.output;
  EXPECT_EQ(readTree(merged), wholeFiles);

  {
    ScopedEnv stop("SWINGSIM_TEST_STOP_AFTER_SWINGS", "2");
    const auto cut = runSwingsim("sweep " + study + " --out " + resumed.string() + " --jobs 1");
    EXPECT_EQ(cut.code, 1) << cut.output;
    EXPECT_THAT(cut.output, HasSubstr("participants are kept in " + (resumed / "cohort.partial.json").string()));
    EXPECT_FALSE(fs::exists(resumed / "report.md"));
  }
  const auto again = runSwingsim("sweep " + study + " --out " + resumed.string() + " --json " +
                                 (resumed / "cohort.json").string() + " --jobs 2");
  ASSERT_EQ(again.code, 0) << again.output;
  EXPECT_THAT(again.output, HasSubstr("resuming from"));
  EXPECT_FALSE(fs::exists(resumed / "cohort.partial.json"));
  EXPECT_EQ(readTree(resumed), wholeFiles);

  // A missing shard, and a shard of another seed: refused, nothing written.
  const fs::path refused = dir / "refused";
  const auto missing = runSwingsim("merge " + (shards / "cohort-shard-0-of-3.json").string() + " " +
                                   (shards / "cohort-shard-2-of-3.json").string() + " --out " + refused.string());
  EXPECT_EQ(missing.code, 1);
  EXPECT_THAT(missing.output, HasSubstr("missing K = 1"));
  const std::string other = writeTinyCohort(dir, 6).string();
  ASSERT_EQ(runSwingsim("sweep " + other + " --shard 1/3 --out " + (dir / "other").string()).code, 0);
  const auto mixed = runSwingsim("merge " + (shards / "cohort-shard-0-of-3.json").string() + " " +
                                 (dir / "other" / "cohort-shard-1-of-3.json").string() + " " +
                                 (shards / "cohort-shard-2-of-3.json").string() + " --out " + refused.string());
  EXPECT_EQ(mixed.code, 1);
  EXPECT_THAT(mixed.output, HasSubstr("cohort-shard-1-of-3.json: seed: expected 5 (the first shard"));
  EXPECT_THAT(mixed.output, HasSubstr("found 6"));
  EXPECT_FALSE(fs::exists(refused / "report.md"));
}

}  // namespace
