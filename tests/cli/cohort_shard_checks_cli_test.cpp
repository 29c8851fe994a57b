// `swingsim merge` of cohort shards with the real binary: a shard whose swing time was edited
// by hand to a plausible value (x 0.8) is refused naming the file and its checksum; one edited
// to a swing time no swing computes (-0.4 s) is refused naming the file, the key and the
// range. Exit code 1 and nothing written in either case.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "run_swingsim.h"

namespace {

namespace fs = std::filesystem;
using swingsim::testing::freshTempDir;
using swingsim::testing::runSwingsim;
using swingsim::testing::slurp;
using ::testing::HasSubstr;

const std::string kRoot = SWINGSIM_SOURCE_DIR;
const std::string kSuite = "swingsim-cohort-shard-checks-cli";

// The shipped example's distributions with 2 participants and lowerings 0 and 0.05 m.
fs::path writeTinyCohort(const fs::path& dir) {
  std::string text = slurp(kRoot + "/studies/cohort-example.yaml");
  auto swap = [&](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  };
  swap("participants: 120", "participants: 2");
  swap("template: ../participants/p1.yaml", "template: " + kRoot + "/participants/p1.yaml");
  swap("max_m: 0.200", "max_m: 0.050");
  swap("step_m: 0.010", "step_m: 0.050");
  const auto path = dir / "tiny-cohort.yaml";
  std::ofstream(path) << text;
  return path;
}

const std::regex kFirstSwingTime("\"swing_times_s\": \\[\\s*([0-9.eE+-]+)");

bool hasSwingTime(const fs::path& path) {
  const std::string text = slurp(path);
  return std::regex_search(text, kFirstSwingTime);
}

// Replaces the first swing time of the file at `path` by what `change` makes of it.
template <class Change>
void editFirstSwingTime(const fs::path& path, Change change) {
  std::string text = slurp(path);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(text, m, kFirstSwingTime)) << text;
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", change(std::stod(m[1].str())));
  text.replace(static_cast<std::size_t>(m.position(1)), static_cast<std::size_t>(m.length(1)), buf);
  std::ofstream(path) << text;
}

TEST(CohortShardChecksCli, EditedShardsAreRefusedNamingFileKeyAndWhy) {
  const fs::path dir = freshTempDir(kSuite, "edited");
  const std::string study = writeTinyCohort(dir).string();
  const fs::path shards = dir / "shards";
  for (int k = 0; k < 2; ++k) {
    const auto r =
        runSwingsim("sweep " + study + " --shard " + std::to_string(k) + "/2 --out " + shards.string() + " --jobs 1");
    ASSERT_EQ(r.code, 0) << r.output;
  }
  const fs::path first = shards / "cohort-shard-0-of-2.json", other = shards / "cohort-shard-1-of-2.json";
  const std::string files = first.string() + " " + other.string();
  // The shard to edit: one whose participant calibrated, so it holds swing times.
  const fs::path second = hasSwingTime(other) ? other : first;
  ASSERT_TRUE(hasSwingTime(second));
  const fs::path merged = dir / "merged";
  const std::string original = slurp(second);

  editFirstSwingTime(second, [](double t) { return 0.8 * t; });
  const auto plausible = runSwingsim("merge " + files + " --out " + merged.string());
  EXPECT_EQ(plausible.code, 1) << plausible.output;
  EXPECT_THAT(plausible.output, HasSubstr(second.string() + ": results_checksum: expected "));
  EXPECT_THAT(plausible.output, HasSubstr("the results were changed after swingsim wrote them"));
  EXPECT_FALSE(fs::exists(merged / "report.md"));

  std::ofstream(second) << original;
  editFirstSwingTime(second, [](double) { return -0.4; });
  const auto negative = runSwingsim("merge " + files + " --out " + merged.string());
  EXPECT_EQ(negative.code, 1) << negative.output;
  EXPECT_THAT(negative.output, HasSubstr(second.string() + ": results["));
  EXPECT_THAT(negative.output, HasSubstr("].swing_times_s[0]: expected a swing time above 0 and at most 10 s"));
  EXPECT_THAT(negative.output, HasSubstr("found -0.4"));
  EXPECT_FALSE(fs::exists(merged / "report.md"));

  // The shards as written merge.
  std::ofstream(second) << original;
  const auto good = runSwingsim("merge " + files + " --out " + merged.string());
  EXPECT_EQ(good.code, 0) << good.output;
  EXPECT_TRUE(fs::exists(merged / "report.md"));
}

}  // namespace
