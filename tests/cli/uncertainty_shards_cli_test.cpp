// Interrupted runs and shards end to end: an uncertainty analysis interrupted (the test hook
// SWINGSIM_TEST_STOP_AFTER_SWINGS stops it as Ctrl-C would) keeps its finished swings in a
// partial file and the same command resumes to the uninterrupted run's result, bit for bit;
// `sweep --shard K/N` + `swingsim merge` give the single run's report and JSON; every way a
// shard set or a --shard value can be wrong is refused with file, key, expected and found,
// and nothing is written; the Slurm example's scripts, run locally for every array index,
// merge to the single run's result. A tiny study: P1, lowerings 0, 0.05 and 0.10 m, two
// samples (81 swings with the one-at-a-time runs).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "../test_build.h"
#include "run_swingsim.h"

namespace {

namespace fs = std::filesystem;
using swingsim::testing::CliRun;
using swingsim::testing::freshTempDir;
using swingsim::testing::runSwingsim;
using swingsim::testing::ScopedEnv;
using swingsim::testing::slurp;
using ::testing::HasSubstr;
using ::testing::Not;

const std::string kRoot = SWINGSIM_SOURCE_DIR;
const std::string kSuite = "swingsim-uncertainty-shards";

fs::path writeTinyStudy(const fs::path& dir) {
  return swingsim::testing::writeTinySweepStudy(dir, 0.1, "output_dir: " + (dir / "default-out").string() + "\n");
}

// Every file under `dir`, relative name -> contents.
std::map<std::string, std::string> readTree(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = slurp(e.path());
  return files;
}

// The uncertainty tables of a run's stdout: from their title to the report line.
std::string uncertaintyTables(const std::string& output) {
  const auto from = output.find("How sure is the optimum:");
  const auto to = output.find("\nreport: ", from);
  return from == std::string::npos || to == std::string::npos ? "" : output.substr(from, to - from);
}

// Runs `swingsim ARGS` with stdout and stderr to files of `dir`; returns the exit code.
int runSeparated(const std::string& args, const fs::path& dir, const std::string& name) {
  const int status = std::system((std::string(SWINGSIM_BINARY) + " " + args + " > " +
                                  (dir / (name + ".stdout")).string() + " 2> " + (dir / (name + ".stderr")).string())
                                     .c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// stdout without its last line, "report: DIR/report.md", which names the output folder.
std::string withoutReportLine(const std::string& stdoutText) {
  const auto at = stdoutText.rfind("\nreport: ");
  return at == std::string::npos ? stdoutText : stdoutText.substr(0, at);
}

struct SingleRun {
  fs::path out, json;
  std::string tables;  ///< the uncertainty tables
  std::string stdoutText;
};

// The uninterrupted, unsharded run everything is compared with.
SingleRun runSingle(const fs::path& dir, const fs::path& study) {
  SingleRun s{dir / "single", dir / "single.json", "", ""};
  const int code = runSeparated("sweep " + study.string() + " --uncertainty 2 --seed 5 --jobs 2 --out " +
                                    s.out.string() + " --json " + s.json.string(),
                                dir, "single");
  EXPECT_EQ(code, 0) << slurp(dir / "single.stderr");
  s.stdoutText = slurp(dir / "single.stdout");
  s.tables = uncertaintyTables(s.stdoutText);
  EXPECT_THAT(s.tables, HasSubstr("2 Monte Carlo samples, seed 5"));
  EXPECT_THAT(s.stdoutText, HasSubstr("P1 — swing time vs knee-axis lowering"));
  return s;
}

TEST(UncertaintyResume, InterruptedRunKeepsItsSwingsAndTheSameCommandResumesToTheSameResult) {
  const auto dir = freshTempDir(kSuite, "resume");
  const auto study = writeTinyStudy(dir);
  const SingleRun single = runSingle(dir, study);
  const fs::path out = dir / "out", json = dir / "out.json", partial = out / "uncertainty.partial.json";
  const std::string command =
      "sweep " + study.string() + " --uncertainty 2 --seed 5 --out " + out.string() + " --json " + json.string();
  constexpr int kStopAfter = 30;  // swings; fewer than the one-at-a-time runs alone
  {
    ScopedEnv stop("SWINGSIM_TEST_STOP_AFTER_SWINGS", std::to_string(kStopAfter));
    const CliRun r = runSwingsim(command + " --jobs 1");  // one thread: stops after exactly kStopAfter
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_THAT(r.output, HasSubstr("interrupted; " + std::to_string(kStopAfter) + " of "));
    EXPECT_THAT(r.output, HasSubstr("\"partial\": true"));
    EXPECT_THAT(r.output, HasSubstr("run the same command again to resume"));
  }
  // The partial file says so; no result that looks complete was written.
  ASSERT_TRUE(fs::exists(partial));
  const auto p = nlohmann::json::parse(slurp(partial));
  EXPECT_EQ(p.at("partial"), true);
  EXPECT_EQ(p.at("seed"), 5);
  EXPECT_EQ(p.at("samples"), 2);
  EXPECT_EQ(p.at("swings_finished"), kStopAfter);
  EXPECT_LT(kStopAfter, p.at("swings_total").get<int>());
  EXPECT_EQ(p.at("samples_finished"), 0);
  EXPECT_EQ(p.at("not_run").size(), p.at("swings_total").get<std::size_t>() - kStopAfter);
  EXPECT_FALSE(fs::exists(out / "report.md"));
  EXPECT_FALSE(fs::exists(json));

  // Another seed, or another N, is not this analysis: refused, naming file, key, expected, found.
  const CliRun otherSeed = runSwingsim("sweep " + study.string() + " --uncertainty 2 --seed 6 --out " + out.string());
  EXPECT_EQ(otherSeed.code, 1) << otherSeed.output;
  EXPECT_THAT(otherSeed.output, HasSubstr(partial.string() + ": seed: expected 6 (this run), found 5"));
  const CliRun otherN = runSwingsim("sweep " + study.string() + " --uncertainty 3 --seed 5 --out " + out.string());
  EXPECT_EQ(otherN.code, 1) << otherN.output;
  EXPECT_THAT(otherN.output, HasSubstr(partial.string() + ": samples: expected 3 (this run), found 2"));
  EXPECT_FALSE(fs::exists(out / "report.md"));

  // Interrupted again after more swings: the file grows, still partial.
  {
    ScopedEnv stop("SWINGSIM_TEST_STOP_AFTER_SWINGS", std::to_string(kStopAfter));
    const CliRun r = runSwingsim(command + " --jobs 2");
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_THAT(r.output, HasSubstr("resuming from " + partial.string() + ": " + std::to_string(kStopAfter) + " of "));
    const auto again = nlohmann::json::parse(slurp(partial));
    EXPECT_GE(again.at("swings_finished").get<int>(), 2 * kStopAfter);
  }

  // Resumed to the end: the uninterrupted run's JSON, report and figures, byte for byte.
  const CliRun resumed = runSwingsim(command + " --jobs 2");
  ASSERT_EQ(resumed.code, 0) << resumed.output;
  EXPECT_THAT(resumed.output, HasSubstr("resuming from " + partial.string()));
  EXPECT_EQ(slurp(json), slurp(single.json));
  EXPECT_EQ(readTree(out), readTree(single.out));
  EXPECT_EQ(uncertaintyTables(resumed.output), single.tables);
  EXPECT_FALSE(fs::exists(partial)) << "a finished run removes the partial file";
}

// Shards 0/3, 1/3, 2/3 merged: the single run's stdout tables, report, figures and JSON.
TEST(UncertaintyShards, MergedShardsGiveTheSingleRunsReportAndJson) {
  const auto dir = freshTempDir(kSuite, "merge");
  const auto study = writeTinyStudy(dir);
  const SingleRun single = runSingle(dir, study);
  const fs::path shards = dir / "shards";
  std::vector<nlohmann::json> files;
  for (int k = 0; k < 3; ++k) {
    const CliRun r = runSwingsim("sweep " + study.string() + " --uncertainty 2 --seed 5 --shard " + std::to_string(k) +
                                 "/3 --jobs 2 --out " + shards.string());
    ASSERT_EQ(r.code, 0) << r.output;
    const fs::path file = shards / ("uncertainty-shard-" + std::to_string(k) + "-of-3.json");
    ASSERT_TRUE(fs::exists(file)) << r.output;
    files.push_back(nlohmann::json::parse(slurp(file)));
    EXPECT_EQ(files.back().at("partial"), false);
    EXPECT_EQ(files.back().at("shard").at("index"), k);
  }
  // The shards tile the swings: contiguous, no gap, no overlap, sizes within one.
  const int total = files[0].at("swings_total").get<int>();
  EXPECT_EQ(files[0].at("first_swing"), 0);
  for (int k = 1; k < 3; ++k) EXPECT_EQ(files[k].at("first_swing"), files[k - 1].at("last_swing"));
  EXPECT_EQ(files[2].at("last_swing"), total);
  EXPECT_FALSE(fs::exists(shards / "report.md")) << "a shard writes no report";

  const fs::path out = dir / "merged", json = dir / "merged.json";
  const CliRun m = runSwingsim("merge " + (shards / "uncertainty-shard-2-of-3.json").string() + " " +
                               (shards / "uncertainty-shard-0-of-3.json").string() + " " +
                               (shards / "uncertainty-shard-1-of-3.json").string() + " --out " + out.string() +
                               " --json " + json.string());
  ASSERT_EQ(m.code, 0) << m.output;
  EXPECT_EQ(slurp(json), slurp(single.json));
  EXPECT_EQ(readTree(out), readTree(single.out));
  EXPECT_EQ(uncertaintyTables(m.output), single.tables);
  // The whole stdout too (plain tables and uncertainty tables), but for the report's folder.
  ASSERT_EQ(runSeparated("merge " + (shards / "uncertainty-shard-0-of-3.json").string() + " " +
                             (shards / "uncertainty-shard-1-of-3.json").string() + " " +
                             (shards / "uncertainty-shard-2-of-3.json").string() + " --out " + out.string(),
                         dir, "merge"),
            0);
  EXPECT_EQ(withoutReportLine(slurp(dir / "merge.stdout")), withoutReportLine(single.stdoutText));
  EXPECT_THAT(slurp(dir / "merge.stdout"), HasSubstr("\nreport: " + out.string() + "/report.md"));

  // Without --out: the study's output_dir, as the sweep.
  const CliRun d = runSwingsim("merge " + (shards / "uncertainty-shard-0-of-3.json").string() + " " +
                               (shards / "uncertainty-shard-1-of-3.json").string() + " " +
                               (shards / "uncertainty-shard-2-of-3.json").string());
  ASSERT_EQ(d.code, 0) << d.output;
  EXPECT_EQ(slurp(dir / "default-out" / "report.md"), slurp(single.out / "report.md"));
}

// Every wrong shard set is refused before anything runs or is written: file, key, expected, found.
TEST(UncertaintyShards, WrongShardSetsAreRefusedAndNothingIsWritten) {
  const auto dir = freshTempDir(kSuite, "errors");
  const auto study = writeTinyStudy(dir);
  const fs::path shards = dir / "shards", other = dir / "other";
  auto shard = [&](const std::string& spec, const std::string& seed, const fs::path& out, int jobs = 2) {
    return runSwingsim("sweep " + study.string() + " --uncertainty 2 --seed " + seed + " --shard " + spec + " --jobs " +
                       std::to_string(jobs) + " --out " + out.string());
  };
  for (const char* spec : {"0/3", "1/3", "2/3"}) ASSERT_EQ(shard(spec, "5", shards).code, 0) << spec;
  ASSERT_EQ(shard("1/3", "6", other).code, 0);  // another seed
  ASSERT_EQ(shard("1/2", "5", other).code, 0);  // another shard count
  const std::string s0 = (shards / "uncertainty-shard-0-of-3.json").string();
  const std::string s1 = (shards / "uncertainty-shard-1-of-3.json").string();
  const std::string s2 = (shards / "uncertainty-shard-2-of-3.json").string();
  const std::string seed6 = (other / "uncertainty-shard-1-of-3.json").string();
  const std::string ofTwo = (other / "uncertainty-shard-1-of-2.json").string();
  const fs::path out = dir / "merged";
  auto merge = [&](const std::string& files) { return runSwingsim("merge " + files + " --out " + out.string()); };

  const CliRun missing = merge(s0 + " " + s2);
  EXPECT_EQ(missing.code, 1);
  EXPECT_THAT(missing.output, HasSubstr("merge: expected all 3 shards of tiny (K = 0 to 2), found 2; missing K = 1"));
  const CliRun duplicate = merge(s0 + " " + s1 + " " + s0 + " " + s2);
  EXPECT_EQ(duplicate.code, 1);
  EXPECT_THAT(duplicate.output,
              HasSubstr(s0 + ": the same file as " + s0 + " (arguments 1 and 3): give each shard file once"));
  // A copy of a shard is another file, with the same shard in it.
  const std::string copy = (dir / "copy-of-shard-0.json").string();
  fs::copy_file(s0, copy, fs::copy_options::overwrite_existing);
  const CliRun copied = merge(s0 + " " + s1 + " " + copy + " " + s2);
  EXPECT_EQ(copied.code, 1);
  EXPECT_THAT(copied.output,
              HasSubstr(copy + ": shard.index: expected each shard once, found shard 0/3 again (also in " + s0));
  const CliRun seed = merge(s0 + " " + seed6 + " " + s2);
  EXPECT_EQ(seed.code, 1);
  EXPECT_THAT(seed.output, HasSubstr(seed6 + ": seed: expected 5 (the first shard, " + s0 + "), found 6"));
  const CliRun count = merge(s0 + " " + ofTwo + " " + s2);
  EXPECT_EQ(count.code, 1);
  EXPECT_THAT(count.output, HasSubstr(ofTwo + ": shard.count: expected 3 (the first shard, " + s0 + "), found 2"));

  // A partial shard (interrupted) is named, with how far it got.
  {
    ScopedEnv stop("SWINGSIM_TEST_STOP_AFTER_SWINGS", "3");
    ASSERT_EQ(shard("0/3", "5", other, 1).code, 1);  // one thread: stops after exactly 3
  }
  const std::string partial0 = (other / "uncertainty-shard-0-of-3.json").string();
  const CliRun partial = merge(partial0 + " " + s1 + " " + s2);
  EXPECT_EQ(partial.code, 1);
  EXPECT_THAT(partial.output, HasSubstr(partial0 + ": partial: expected false (a finished shard), found true (3 of "));

  // Not a shard file at all.
  const std::string garbage = swingsim::testing::writeSuiteTempFile(kSuite, "garbage.json", "{\"format\": 3}\n");
  const CliRun bad = merge(garbage + " " + s1 + " " + s2);
  EXPECT_EQ(bad.code, 1);
  EXPECT_THAT(bad.output, HasSubstr(garbage + ": format: expected a string, found 3"));
  const std::string notJson = swingsim::testing::writeSuiteTempFile(kSuite, "not.json", "shard 0\n");
  EXPECT_THAT(merge(notJson).output, HasSubstr(notJson + ": expected the JSON of an uncertainty swings file"));

  // A study edited after the shards ran: the merge would not be the shards' analysis.
  std::ofstream(study, std::ios::app) << "description: edited\n";
  const CliRun edited = merge(s0 + " " + s1 + " " + s2);
  EXPECT_EQ(edited.code, 1);
  EXPECT_THAT(edited.output, HasSubstr(s0 + ": inputs_fingerprint: expected "));
  EXPECT_THAT(edited.output, HasSubstr("the study, a participant or a knee model differs"));

  EXPECT_FALSE(fs::exists(out)) << "no merge wrote anything";
}

// Malformed or out-of-range K/N are usage errors (exit 2) before anything runs.
TEST(UncertaintyShards, BadShardValuesAreUsageErrors) {
  const auto dir = freshTempDir(kSuite, "bad-values");
  const auto study = writeTinyStudy(dir);
  const std::string base = "sweep " + study.string() + " --uncertainty 2 --out " + (dir / "out").string() + " --shard ";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"3/3", "expected K from 0 to N - 1 = 2, found \"3/3\""},
      {"0/0", "expected N of at least 1, found \"0/0\""},
      {"1", "expected K/N, two whole numbers (shard K of N, K from 0 to N - 1), found \"1\""},
      {"a/b", "expected K/N, two whole numbers"},
      {"1/3x", "expected K/N, two whole numbers"},
  };
  for (const auto& [value, message] : cases) {
    const CliRun r = runSwingsim(base + value);
    EXPECT_EQ(r.code, 2) << value << "\n" << r.output;
    EXPECT_THAT(r.output, HasSubstr("--shard")) << value;
    EXPECT_THAT(r.output, HasSubstr(message)) << value;
  }
  // Nothing to shard without --uncertainty; the JSON is the merge's to write.
  const CliRun alone = runSwingsim("sweep " + study.string() + " --shard 0/2 --out " + (dir / "out").string());
  EXPECT_EQ(alone.code, 1) << alone.output;
  EXPECT_THAT(alone.output, HasSubstr("--shard: shards the uncertainty analysis, which needs --uncertainty N"));
  const CliRun json = runSwingsim(base + "0/2 --json " + (dir / "x.json").string());
  EXPECT_EQ(json.code, 2) << json.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// examples/slurm: the array job's script run locally once per SLURM_ARRAY_TASK_ID, then the
// merge job's script: the single run's JSON and report. submit.sh with a stand-in `sbatch`
// that records its arguments: an array 0..N-1 and a merge that waits for all of it.
TEST(SlurmExample, ShardsRunLocallyMergeToTheSingleRun) {
  const auto dir = freshTempDir(kSuite, "slurm");
  const auto study = writeTinyStudy(dir);
  const SingleRun single = runSingle(dir, study);
  const fs::path out = dir / "slurm-out";
  const std::string env = "STUDY=" + study.string() + " SAMPLES=2 SEED=5 SHARDS=3 OUT=" + out.string() +
                          " SWINGSIM=" + std::string(SWINGSIM_BINARY) + " ";
  for (int k = 0; k < 3; ++k) {
    const int code = std::system((env + "SLURM_ARRAY_TASK_ID=" + std::to_string(k) + " bash " + kRoot +
                                  "/examples/slurm/shard.sbatch > " + (dir / "shard.log").string() + " 2>&1")
                                     .c_str());
    ASSERT_EQ(code, 0) << slurp(dir / "shard.log");
  }
  const int merged = std::system(
      (env + "bash " + kRoot + "/examples/slurm/merge.sbatch > " + (dir / "merge.log").string() + " 2>&1").c_str());
  ASSERT_EQ(merged, 0) << slurp(dir / "merge.log");
  EXPECT_EQ(slurp(out / "sweep.json"), slurp(single.json));
  EXPECT_EQ(slurp(out / "report.md"), slurp(single.out / "report.md"));

  // The array script refuses to run outside an array job (no SLURM_ARRAY_TASK_ID).
  EXPECT_NE(std::system((env + "bash " + kRoot + "/examples/slurm/shard.sbatch > /dev/null 2>&1").c_str()), 0);

  // submit.sh: what it asks of sbatch.
  const fs::path bin = dir / "bin", log = dir / "sbatch.log";
  fs::create_directories(bin);
  std::ofstream(bin / "sbatch") << "#!/bin/sh\necho \"$@\" >> " << log.string() << "\necho 4242\n";
  fs::permissions(bin / "sbatch", fs::perms::owner_all);
  const int submitted = std::system(("PATH=" + bin.string() + ":$PATH " + env + "bash " + kRoot +
                                     "/examples/slurm/submit.sh > " + (dir / "submit.log").string() + " 2>&1")
                                        .c_str());
  ASSERT_EQ(submitted, 0) << slurp(dir / "submit.log");
  const std::string calls = slurp(log);
  EXPECT_THAT(calls, HasSubstr("--array=0-2 "));
  EXPECT_THAT(calls, HasSubstr("examples/slurm/shard.sbatch"));
  EXPECT_THAT(calls, HasSubstr("--dependency=afterok:4242 "));
  EXPECT_THAT(calls, HasSubstr("examples/slurm/merge.sbatch"));
}

}  // namespace
