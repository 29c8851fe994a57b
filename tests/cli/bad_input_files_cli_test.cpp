// The bad-input catalogue at the command line, part two (issue 29, items 3 and 4): where
// output goes and what a shell or a container hands over. Each case exits non-zero with a
// message naming the file or option before any work or output, or is a tested acceptance
// (`--json /dev/stdout` streams the JSON and leaves the link as it was).
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <tuple>

#include "../core/cpu_time.h"
#include "../test_build.h"
#include "core/output_files.h"
#include "io/json_file.h"
#include "release_only.h"
#include "run_swingsim.h"
#include "study/uncertainty_swings_file.h"
#include "sweep/sweep.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using testing::runSwingsim;
using testing::slurp;
const std::string kRoot = SWINGSIM_SOURCE_DIR;

// s: a refusal before any work loads the study and participants, nothing more.
constexpr double kBeforeAnyWork = 5.0;

fs::path freshDir(const std::string& name) { return testing::freshTempDir("swingsim_bad_input_files_cli_test", name); }

// P1 with its knee model path made absolute (so the copy loads from anywhere).
fs::path writeP1(const fs::path& dir) {
  std::string t = slurp(kRoot + "/participants/p1.yaml");
  t = std::regex_replace(t, std::regex("\\.\\./models/"), kRoot + "/models/");
  std::ofstream(dir / "p.yaml", std::ios::binary) << t;
  return dir / "p.yaml";
}

/// Runs the command line; `seconds` is its CPU time (not wall: a loaded machine only delays it).
testing::CliRun timedRun(const std::string& args, double& seconds) {
  testing::CliRun run{};
  seconds = swingsim::testing::childCpuSecondsOf([&] { run = runSwingsim(args); });
  return run;
}

TEST(BadInputFilesCli, SweepGridAboveTheLimitIsCountedAndRefusedBeforeAnyWork) {
  const fs::path dir = freshDir("grid");
  std::string masses, distances;
  for (int i = 1; i <= 200; ++i) masses += ", " + std::to_string(0.01 * i);
  for (int i = 1; i <= 200; ++i) distances += (i > 1 ? ", " : "") + std::to_string(0.0005 * i);
  const fs::path study = testing::writeTinySweepStudy(
      dir, 0.1, "added_mass: {mass_kg: [0" + masses + "], distance_below_knee_m: [" + distances + "]}\n");
  // Lowerings 0, 0.05, 0.1 m; each with 200 x 200 added masses that all fit on the shank.
  const std::string swings = std::to_string(3 * (1 + 200 * 200));
  double seconds = 0;
  const auto r = timedRun("sweep " + study.string() + " --out " + (dir / "out").string(), seconds);
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("sweep tiny: " + swings +
                                  " swings (1 participant, 200 added masses above 0 kg x 200 distances), about "));
  EXPECT_THAT(r.output, HasSubstr(study.string() + ": the sweep has " + swings + " swings"));
  EXPECT_THAT(r.output, HasSubstr("more than the limit of " + std::to_string(kDefaultMaxSweepSwings)));
  EXPECT_THAT(r.output, HasSubstr("--max-swings " + swings + " if you mean it"));
  EXPECT_LT(seconds, kBeforeAnyWork);
  EXPECT_FALSE(fs::exists(dir / "out"));
  // The limit is the user's to lower (or raise): a 3-swing sweep refused at 2.
  const fs::path small = testing::writeTinySweepStudy(freshDir("small"), 0.1, "");
  const auto low = runSwingsim("sweep " + small.string() + " --max-swings 2 --out " + (dir / "out").string());
  EXPECT_EQ(low.code, 1) << low.output;
  EXPECT_THAT(low.output, HasSubstr("the sweep has 3 swings"));
  EXPECT_EQ(runSwingsim("sweep " + small.string() + " --max-swings 0").code, 2);
}

TEST(BadInputFilesCli, StudyOutputDirThatCannotBeWrittenIsRefusedBeforeAnyWork) {
  const fs::path dir = freshDir("output-dir");
  std::ofstream(dir / "file") << "x";
  const std::string below = (dir / "file" / "out").string();
  const fs::path study = testing::writeTinySweepStudy(dir, 0.1, "output_dir: " + below + "\n");
  double seconds = 0;
  const auto r = timedRun("sweep " + study.string(), seconds);
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr(study.string() + ": output_dir: cannot write into '" + below + "': '" +
                                  (dir / "file").string() + "' is not a folder"));
  EXPECT_LT(seconds, kBeforeAnyWork);

  const std::string longName(300, 'n');
  const fs::path longStudy = testing::writeTinySweepStudy(freshDir("long"), 0.1, "output_dir: " + longName + "\n");
  const auto l = runSwingsim("sweep " + longStudy.string());
  EXPECT_EQ(l.code, 1) << l.output;
  EXPECT_THAT(l.output, HasSubstr("output_dir: cannot write into '" + longName + "': the name"));
  EXPECT_THAT(l.output, HasSubstr("NAME_MAX"));
  // The same over-long name as --out is a usage error.
  EXPECT_EQ(runSwingsim("sweep " + longStudy.string() + " --out " + longName).code, 2);
}

TEST(BadInputFilesCli, CalibrateRefusesTheSameFileTwiceBeforeWritingAnything) {
  const fs::path dir = freshDir("calibrate-twice");
  const fs::path p = writeP1(dir);
  const std::string before = slurp(p);
  const std::string again = (dir / "." / "p.yaml").string();
  double seconds = 0;
  const auto r = timedRun("calibrate " + p.string() + " " + again, seconds);
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr(again + ": the same file as " + p.string() +
                                  " (arguments 1 and 2): give each "
                                  "participant file once"));
  EXPECT_LT(seconds, kBeforeAnyWork);
  EXPECT_EQ(slurp(p), before);
}

// `--json -`: the JSON alone on standard output (through a pipe here, as into jq), the text on
// standard error; no file named "-" is written.
TEST(BadInputFilesCli, JsonDashIsTheJsonAloneOnStandardOutput) {
  const fs::path dir = freshDir("json-dash");
  const fs::path json = dir / "piped.json", text = dir / "text.txt";
  const auto r =
      runSwingsim("simulate " + writeP1(dir).string() + " --json - 2> " + text.string() + " | cat > " + json.string());
  EXPECT_EQ(r.code, 0) << r.output;
  const std::string piped = slurp(json);
  ASSERT_FALSE(piped.empty());
  EXPECT_EQ(piped.front(), '{') << piped;
  EXPECT_EQ(piped[piped.find_last_not_of('\n')], '}') << piped;
  EXPECT_THAT(piped, HasSubstr("\"swing_time_s\": "));
  EXPECT_THAT(slurp(text), HasSubstr("swing time"));  // the text went to standard error
  EXPECT_FALSE(fs::exists("-"));
}

TEST(BadInputFilesCli, JsonToDevStdoutIsStreamedAndTheLinkStays) {
  if (!fs::is_symlink(fs::symlink_status("/dev/stdout"))) GTEST_SKIP() << "/dev/stdout is not a link here";
  const fs::path dir = freshDir("dev-stdout");
  const auto r =
      runSwingsim("simulate " + writeP1(dir).string() + " --json /dev/stdout --out " + (dir / "out").string());
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("\"drive\": "));  // the JSON came out on stdout
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status("/dev/stdout"))) << "/dev/stdout was replaced by a file";
  for (const auto& e : fs::directory_iterator("/dev"))
    EXPECT_EQ(e.path().filename().string().find("stdout.tmp-"), std::string::npos) << e.path();
}

// Issue 57: with stdout redirected to a file, `--json /dev/stdout` opened that file a second
// time at its own offset, and the text printed after overwrote the JSON. Now the JSON goes
// through stdout's own descriptor: the file holds the text before, the whole JSON, the text
// after, each once.
TEST(BadInputFilesCli, JsonToDevStdoutRedirectedToAFileIsWrittenOnceInOrder) {
  if (!fs::is_symlink(fs::symlink_status("/dev/stdout"))) GTEST_SKIP() << "/dev/stdout is not a link here";
  const fs::path dir = freshDir("dev-stdout-file");
  const fs::path file = dir / "both.txt";
  const auto r = runSwingsim("simulate " + writeP1(dir).string() + " --json /dev/stdout --out " +
                             (dir / "out").string() + " > " + file.string());
  EXPECT_EQ(r.code, 0) << r.output;
  const std::string all = slurp(file);
  const auto open = all.find("{\n"), close = all.rfind("\n}");
  ASSERT_NE(open, std::string::npos) << all;
  ASSERT_NE(close, std::string::npos) << all;
  EXPECT_TRUE(swingsim::Json::accept(all.substr(open, close + 2 - open))) << "the JSON is whole: " << all;
  EXPECT_THAT(all.substr(0, open), HasSubstr("swing time")) << "the text printed before the JSON is kept";
}

// A complete one-shard analysis of a study at `studyPath` (relative), as `sweep --shard 0/1` writes it.
fs::path writeShard(const fs::path& dir, const std::string& studyPath) {
  UncertaintySwingsFile f;
  f.run.study = "tiny";
  f.run.studyPath = studyPath;
  f.run.inputsFingerprint = "0123456789abcdef";
  f.run.assumptionsFingerprint = "fedcba9876543210";
  f.run.samples = 1;
  f.run.seed = 1;
  f.run.swingCount = 4;
  f.run.version = "0.test";
  f.sharded = true;
  f.shardIndex = 0;
  f.shardCount = 1;
  std::tie(f.first, f.last) = calcShardSwings(f.run.swingCount, 0, 1);
  f.times = UncertaintySwingTimes::makeEmpty(f.last - f.first);
  for (std::size_t i = 0; i < f.times.swingTimes.size(); ++i) {
    f.times.finished[i] = 1;
    f.times.swingTimes[i] = 0.5;
  }
  const fs::path path = dir / uncertaintyShardFileName(0, 1);
  writeFileAtomic(path.string(), formatUncertaintySwingsJson(f));
  return path;
}

TEST(BadInputFilesCli, MergeFromAnotherFolderSaysTheStudyPathCameFromTheShards) {
  const fs::path dir = freshDir("merge-elsewhere");
  const fs::path shard = writeShard(dir, "studies/tiny.yaml");
  const auto r = runSwingsim("merge " + shard.string());  // run from the build folder: no studies/tiny.yaml there
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_THAT(r.output,
              HasSubstr(shard.string() + ": study_path: the shards name the study file \"studies/tiny.yaml\" "
                                         "(as their sweep command gave it), which is not there from this folder ("));
  EXPECT_THAT(r.output, HasSubstr("run merge from the folder the shards were run in"));
  const auto twice = runSwingsim("merge " + shard.string() + " " + (dir / "." / shard.filename()).string());
  EXPECT_EQ(twice.code, 1) << twice.output;
  EXPECT_THAT(twice.output,
              HasSubstr("the same file as " + shard.string() + " (arguments 1 and 2): give each shard file once"));
}

// A large --jobs under an address-space limit (ulimit -v): before issue 29 the threads that
// started ran out of memory in their first swing and std::bad_alloc aborted the run (exit
// 134). The pool now starts only the threads the limit leaves room for and says so; the
// sweep ends normally. (Not under the sanitizers: their shadow memory needs terabytes of
// address space.)
TEST(BadInputFilesCli, LargeJobsUnderAnAddressSpaceLimitRunOnTheThreadsThatFit) {
  SWINGSIM_RELEASE_ONLY();
  const fs::path dir = freshDir("ulimit");
  const std::string cmd = "ulimit -v 500000 && " + std::string(SWINGSIM_BINARY) + " sweep " + kRoot +
                          "/studies/burkett2004.yaml --jobs 64 --out " + (dir / "out").string() + " >/dev/null 2>" +
                          (dir / "err.txt").string();
  const int status = std::system(("bash -c '" + cmd + "'").c_str());
  const std::string err = slurp((dir / "err.txt").string());
  ASSERT_TRUE(WIFEXITED(status)) << err;
  EXPECT_EQ(WEXITSTATUS(status), 0) << err;
  EXPECT_THAT(err, HasSubstr("the address-space limit (ulimit -v 500000 kB) leaves room for"));
  EXPECT_THAT(err, ::testing::Not(HasSubstr("bad_alloc")));
  EXPECT_TRUE(fs::exists(dir / "out" / "report.md"));
}

}  // namespace
}  // namespace swingsim
