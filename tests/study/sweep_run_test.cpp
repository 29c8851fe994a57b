// A sweep run's sequence (study/sweep_run.h): the shards of an uncertainty analysis, merged,
// give the JSON one run gives; an interrupted analysis resumes to the same JSON; a run stopped
// before its sweep keeps its finished rows and writes no report.
#include "study/sweep_run.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "study/sweep_study.h"
#include "study/uncertainty_swings_file.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;

std::string scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("swingsim-sweep-run-" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// P1 alone on a 50 mm grid, with a 2-sample uncertainty analysis: a few hundred swings.
SweepStudy tinyStudy() {
  SweepStudy s = loadSweepStudy("studies/burkett2004.yaml");
  s.participants = {s.participants[0]};
  s.loweringStep = 0.05;
  s.addedMasses = {0.0};
  s.includePublishedLowerings = false;
  s.uncertaintySamples = 2;
  s.uncertaintySeed = 7;
  return s;
}

/// One whole run into `dir`; its JSON text.
std::string runWhole(const std::string& dir, SweepRunControl control = {}) {
  SweepRun run(tinyStudy(), 2, control);
  run.calibrate();
  run.planUncertainty(dir + "/" + uncertaintyPartialFileName());
  EXPECT_EQ(run.runToOutputs(dir, dir + "/sweep.json"), 0);
  return readText(dir + "/sweep.json");
}

TEST(SweepRun, ShardsMergedGiveTheJsonOfOneRun) {
  const std::string whole = scratch("whole");
  const std::string json = runWhole(whole);
  ASSERT_NE(json.find("\"fastest_lowering_interval_m\""), std::string::npos);
  EXPECT_TRUE(fs::exists(whole + "/report.md"));

  const std::string shardDir = scratch("shards");
  std::vector<UncertaintySwingsFile> shards;
  for (int k = 0; k < 3; ++k) {
    SweepRun shard(tinyStudy(), 2, {});
    shard.calibrate();
    ASSERT_EQ(shard.runShard(k, 3, shardDir), 0);
    shards.push_back(readUncertaintySwingsFile(shardDir + "/" + uncertaintyShardFileName(k, 3)));
  }
  const std::string merged = scratch("merged");
  SweepRun merge(tinyStudy(), 2, {});
  merge.calibrate();
  merge.planUncertainty("");
  for (const auto& s : shards) checkSameUncertaintyRun(merge.uncertaintyRun(), s, "the study");
  merge.takeUncertaintySwings(mergeUncertaintyShards(shards));
  ASSERT_EQ(merge.runToOutputs(merged, merged + "/sweep.json"), 0);
  EXPECT_EQ(readText(merged + "/sweep.json"), json);
  EXPECT_EQ(readText(merged + "/report.md"), readText(whole + "/report.md"));
}

TEST(SweepRun, AnInterruptedAnalysisResumesToTheSameJson) {
  const std::string json = runWhole(scratch("reference"));

  const std::string dir = scratch("interrupted");
  const std::string partial = dir + "/" + uncertaintyPartialFileName();
  volatile bool stop = false;
  SweepRunControl control;
  control.stop = &stop;
  control.stopAfterSwings = 5;
  {
    SweepRun run(tinyStudy(), 2, control);
    run.calibrate();
    run.planUncertainty(partial);
    EXPECT_EQ(run.runToOutputs(dir, dir + "/sweep.json"), 1);
  }
  ASSERT_TRUE(fs::exists(partial));
  EXPECT_FALSE(fs::exists(dir + "/report.md"));
  EXPECT_FALSE(fs::exists(dir + "/sweep.json"));
  const UncertaintySwingsFile kept = readUncertaintySwingsFile(partial);
  EXPECT_TRUE(kept.isPartial());
  EXPECT_GE(kept.times.countFinished(), 5u);
  EXPECT_LT(kept.times.countFinished(), kept.times.finished.size());

  EXPECT_EQ(runWhole(dir), json);
  EXPECT_FALSE(fs::exists(partial)) << "a finished run removes the partial file it resumed from";
}

TEST(SweepRun, AStopBeforeTheSweepKeepsTheRowsAndWritesNoReport) {
  const std::string dir = scratch("stopped");
  volatile bool stop = true;
  SweepRunControl control;
  control.stop = &stop;
  SweepRun run(tinyStudy(), 2, control);
  run.calibrate();
  run.planUncertainty(dir + "/" + uncertaintyPartialFileName());
  EXPECT_FALSE(run.sweep());
  EXPECT_EQ(run.runToOutputs(dir, dir + "/sweep.json"), 1);
  EXPECT_TRUE(fs::exists(dir + "/sweep.partial.csv"));
  EXPECT_FALSE(fs::exists(dir + "/report.md"));
  EXPECT_FALSE(fs::exists(dir + "/sweep.json"));
  EXPECT_EQ(run.uncertainty(), nullptr);
}

}  // namespace
}  // namespace swingsim
