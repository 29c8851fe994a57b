// Issue 41 item 6 with the real binary: a cohort run and a diagnosis print their size and an
// estimate before any work and are refused above their limit, naming the option that raises
// it (--max-swings, --max-rows); the refusal comes before a participant is drawn or a fit
// starts, and the output folder is not created.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_swingsim.h"

namespace {

namespace fs = std::filesystem;
using swingsim::testing::freshTempDir;
using swingsim::testing::runSwingsim;
using swingsim::testing::slurp;
using ::testing::HasSubstr;
using ::testing::Not;

const std::string kRoot = SWINGSIM_SOURCE_DIR;
const std::string kSuite = "swingsim-large-runs";

// The shipped cohort example with `participants` drawn and its template found from `dir`.
fs::path writeCohort(const fs::path& dir, int participants) {
  std::string text = slurp(kRoot + "/studies/cohort-example.yaml");
  auto swap = [&](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  };
  swap("participants: 120", "participants: " + std::to_string(participants));
  swap("template: ../participants/p1.yaml", "template: " + kRoot + "/participants/p1.yaml");
  const fs::path path = dir / "cohort.yaml";
  std::ofstream(path) << text;
  return path;
}

// The swing diagnosis demo with absolute paths, its training record replaced by `train`.
fs::path writeSwingDiagnosis(const fs::path& dir, const std::string& train) {
  const std::string data = kRoot + "/studies/data/diagnose-demo-swing/";
  const fs::path path = dir / "diagnose.yaml";
  std::ofstream(path) << "kind: swing-diagnosis\nname: long-record\nparticipant: " << kRoot
                      << "/participants/p1.yaml\nbase_model: " << kRoot
                      << "/models/damping-table-default.yaml\ntrain: [" << train << "]\nvalidate: [" << data
                      << "slow.csv, " << data << "fast.csv]\n";
  return path;
}

TEST(LargeRunEstimates, AHundredThousandParticipantCohortIsCountedAndRefusedBeforeAnyIsDrawn) {
  const fs::path dir = freshTempDir(kSuite, "big-cohort");
  const fs::path out = dir / "out";
  // 100,000 x (20 calibration swings + 21 lowerings); drawing them alone took 82 s.
  const auto run = runSwingsim("sweep " + writeCohort(dir, 100000).string() + " --out " + out.string());
  EXPECT_EQ(run.code, 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("cohort cohort-example: 4100000 swings (100000 participants"));
  EXPECT_THAT(run.output, HasSubstr("cohort.yaml: participants: the cohort run has 4100000 swings"));
  EXPECT_THAT(run.output, HasSubstr("more than the limit of 100000"));
  EXPECT_THAT(run.output, HasSubstr("raise the limit with --max-swings 4100000"));
  EXPECT_FALSE(fs::exists(out));
}

TEST(LargeRunEstimates, ACohortShardIsHeldToMaxSwings) {
  const fs::path dir = freshTempDir(kSuite, "cohort-shard");
  // Shard 0 of 4 of 120 participants: 30 x 41 swings.
  const auto run = runSwingsim("sweep " + writeCohort(dir, 120).string() + " --out " + (dir / "out").string() +
                               " --shard 0/4 --max-swings 100");
  EXPECT_EQ(run.code, 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("the cohort run has 1230 swings (30 participants"));
  EXPECT_THAT(run.output, HasSubstr("--max-swings 1230"));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(LargeRunEstimates, ALongSwingRecordIsCountedAfterReadingAndRefusedBeforeTheFit) {
  const fs::path dir = freshTempDir(kSuite, "long-record");
  // 0.3 s of swing sampled every 2 us: 150,001 rows, above the default 20,000.
  const fs::path record = dir / "long.csv";
  {
    std::ofstream csv(record);
    csv << "time_s,hip_flexion_deg,knee_flexion_deg,hip_moment_Nm\n";
    for (int i = 0; i <= 150000; ++i) {
      const double t = i * 2e-6;
      csv << t << "," << -15 + 100 * t << "," << 10 + 150 * t << "," << 20 * t << "\n";
    }
  }
  const fs::path out = dir / "out";
  const auto run =
      runSwingsim("diagnose " + writeSwingDiagnosis(dir, record.string()).string() + " --out " + out.string());
  EXPECT_EQ(run.code, 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("diagnose long-record: "));
  EXPECT_THAT(run.output, HasSubstr("the diagnosis has "));
  EXPECT_THAT(run.output, HasSubstr("3 swing record(s), after any resample_s"));
  EXPECT_THAT(run.output, HasSubstr("more than the limit of 20000"));
  EXPECT_THAT(run.output, HasSubstr("or raise the limit with --max-rows "));
  EXPECT_FALSE(fs::exists(out));
}

TEST(LargeRunEstimates, AMeasuredSweepTableIsHeldToMaxRows) {
  const fs::path out = freshTempDir(kSuite, "sweep-table") / "out";
  const auto run =
      runSwingsim("diagnose " + kRoot + "/studies/burkett2004-table4.yaml --out " + out.string() + " --max-rows 10");
  EXPECT_EQ(run.code, 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("rows (a measured sweep table"));
  EXPECT_THAT(run.output, HasSubstr("more than the limit of 10: give fewer rows"));
  EXPECT_FALSE(fs::exists(out));
}

TEST(LargeRunEstimates, MaxRowsMustBeAWholeNumber) {
  const auto run = runSwingsim("diagnose " + kRoot + "/studies/burkett2004-table4.yaml --max-rows 0");
  EXPECT_NE(run.code, 0);
  EXPECT_THAT(run.output, HasSubstr("--max-rows"));
  EXPECT_THAT(run.output, HasSubstr("expected a whole number of rows from 1"));
}

}  // namespace
