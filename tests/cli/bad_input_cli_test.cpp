// The bad-input catalogue at the command line: each bad input exits non-zero
// with a message naming the file, key or option, and leaves no output, no half-written
// file and no temporary file behind; the already-fixed kinds stay fixed.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <thread>

#include "../core/cpu_time.h"
#include "../test_build.h"
#include "run_swingsim.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using testing::runSwingsim;
using testing::slurp;
const std::string kRoot = SWINGSIM_SOURCE_DIR;

fs::path freshDir(const std::string& name) { return testing::freshTempDir("swingsim_bad_input_cli_test", name); }

// P1 with its knee model path made absolute and `from` replaced by `to`.
fs::path writeP1(const fs::path& dir, const std::string& from = "", const std::string& to = "") {
  std::string t = slurp(kRoot + "/participants/p1.yaml");
  t = std::regex_replace(t, std::regex("\\.\\./models/"), kRoot + "/models/");
  if (!from.empty()) {
    const auto at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    t.replace(at, from.size(), to);
  }
  std::ofstream(dir / "p.yaml", std::ios::binary) << t;
  return dir / "p.yaml";
}

// `extra`: more study lines (e.g. a slow integrator accuracy for the interrupt tests).
fs::path writeStudy(const fs::path& dir, const std::vector<fs::path>& participants, double step = 0.1, double max = 0.1,
                    const std::string& extra = "") {
  std::string list;
  for (const auto& p : participants) list += (list.empty() ? "" : ", ") + p.string();
  std::ofstream(dir / "study.yaml") << "kind: knee-axis-sweep\nname: cli\nparticipants: [" << list
                                    << "]\nlowering: {step_m: " << step << ", max_m: " << max
                                    << ", include_published: false}\n"
                                    << extra;
  return dir / "study.yaml";
}

// Every file below `dir` whose name shows a temporary or staging file.
std::vector<std::string> litterIn(const fs::path& dir) {
  std::vector<std::string> found;
  if (!fs::exists(dir)) return found;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.find(".tmp-") != std::string::npos || name.find(".staging-") != std::string::npos ||
        name.find(".staged") != std::string::npos)
      found.push_back(e.path().string());
  }
  return found;
}

using swingsim::testing::childCpuSecondsOf;

// ---- Budgets --------------------------------------------------------------------------

TEST(BadInputCli, DampingTableOneMillionTimesTooLargeStopsWithinSecondsSayingWhatToChange) {
  const fs::path dir = freshDir("stiff");
  std::string model = slurp(kRoot + "/models/damping-table-default.yaml");
  model = std::regex_replace(model, std::regex("moment_Nm: +\\[[^\\]]*\\]"),
                             "moment_Nm: [1e6, 1e6, 1e6, 1e6, 1e6, 1e6, 1e6, 1e6]");
  std::ofstream(dir / "stiff.yaml") << model;
  const fs::path p = writeP1(dir, "knee_model: " + kRoot + "/models/damping-table-default.yaml",
                             "knee_model: " + (dir / "stiff.yaml").string());
  testing::CliRun r{};
  constexpr double kFewSeconds = 10;  // CPU s: the budget is about 1.5 s of computing here (minutes before)
  EXPECT_LT(childCpuSecondsOf([&] { r = runSwingsim("simulate " + p.string() + " --out " + (dir / "out").string()); }),
            kFewSeconds);
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("swingsim: P1 at lowering 0 m: the swing was stopped after"));
  EXPECT_THAT(r.output, HasSubstr("loosen the accuracy"));
  EXPECT_THAT(r.output, HasSubstr("check the knee model " + (dir / "stiff.yaml").string()));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// The same too-stiff model given with --knee: the message names that file, not the
// participant's knee_model (issue 29: the file actually used).
TEST(BadInputCli, TooStiffKneeGivenWithKneeOptionIsTheFileNamed) {
  const fs::path dir = freshDir("stiffknee");
  std::string model = slurp(kRoot + "/models/damping-table-default.yaml");
  model = std::regex_replace(model, std::regex("moment_Nm: +\\[[^\\]]*\\]"),
                             "moment_Nm: [1e6, 1e6, 1e6, 1e6, 1e6, 1e6, 1e6, 1e6]");
  std::ofstream(dir / "stiff.yaml") << model;
  const auto r = runSwingsim("simulate participants/p1.yaml --knee " + (dir / "stiff.yaml").string() + " --out " +
                             (dir / "out").string());
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("check the knee model " + (dir / "stiff.yaml").string()));
  EXPECT_THAT(r.output, ::testing::Not(HasSubstr("damping-table-default.yaml")));
}

// A lab export's missing-data marker in a bench file stops `fit` at load (rc 1), naming the
// file, line and column, instead of a fit with 1e35 coefficients and rc 0.
TEST(BadInputCli, FitOnABenchFileWithAMissingDataMarkerExitsOneNamingTheLine) {
  const fs::path dir = freshDir("marker");
  std::string bench = slurp(kRoot + "/studies/data/mauch2014/normal.csv");
  const auto third = bench.find('\n', bench.find('\n', bench.find('\n') + 1) + 1);  // end of line 3
  const auto comma = bench.rfind(',', third);
  bench.replace(comma + 1, third - comma - 1, "9.9e37");
  std::ofstream(dir / "normal.csv") << bench;
  std::ofstream(dir / "study.yaml") << "kind: cylinder-fit\nname: marker\nmodels: [" << kRoot
                                    << "/models/mauch-2phase.yaml]\ntrain: [normal.csv]\nvalidate: [" << kRoot
                                    << "/studies/data/mauch2014/slow.csv]\n";
  const auto r = runSwingsim("fit " + (dir / "study.yaml").string() + " --json " + (dir / "fit.json").string());
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_THAT(r.output,
              HasSubstr((dir / "normal.csv").string() + ":3: force_N: expected a force in [-100000, 100000] N"));
  EXPECT_THAT(r.output, HasSubstr("missing-data marker"));
  EXPECT_FALSE(fs::exists(dir / "fit.json"));
}

TEST(BadInputCli, AccuracyOf1e18WithRungeKutta3IsAUsageErrorNotAnHourLongRun) {
  const auto r =
      runSwingsim("simulate participants/p1.yaml --integrator runge-kutta-3 --accuracy 1e-18 --out /nonexistent/x");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("--accuracy: expected a relative accuracy in [1e-14, 0.01] (got 1e-18)"));
}

TEST(BadInputCli, AccuracyOf1e300IsAUsageErrorNotASimbodyNaN) {
  const auto r = runSwingsim("simulate participants/p1.yaml --accuracy 1e-300");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("(got 1e-300)"));
  EXPECT_THAT(r.output, ::testing::Not(HasSubstr("Inertia")));
}

// ---- Implausible values ---------------------------------------------------------------

TEST(BadInputCli, AddedMassOf1e300IsNamedAndWritesNothing) {
  const fs::path dir = freshDir("addmass");
  const auto r = runSwingsim("simulate participants/p1.yaml --add-mass 1e300@0.1 --out " + (dir / "out").string() +
                             " --json " + (dir / "r.json").string());
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("participants/p1.yaml: added mass: expected at most 150 kg (heavier than a whole "
                                  "body: is it in grams?) (got 1e+300 kg)"));
  EXPECT_FALSE(fs::exists(dir / "out"));
  EXPECT_FALSE(fs::exists(dir / "r.json"));
}

TEST(BadInputCli, SweepAddedMassOf1e300FailsItsPointsWithTheReason) {
  const fs::path dir = freshDir("sweepaddmass");
  const fs::path study = writeStudy(dir, {writeP1(dir)});
  const auto r = runSwingsim("sweep " + study.string() + " --add-mass 1e300@0.1 --out " + (dir / "out").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_THAT(slurp(dir / "out" / "report.md"), HasSubstr("added mass: expected at most 150 kg"));
  EXPECT_THAT(slurp(dir / "out" / "sweep.csv"), HasSubstr(",failed\n"));
}

TEST(BadInputCli, SegmentMassOf1e300ExitsOneNamingFileLineAndKey) {
  const fs::path dir = freshDir("mass");
  const fs::path p = writeP1(dir, "mass_kg: 3.350", "mass_kg: 1e300");
  const auto r = runSwingsim("simulate " + p.string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.output,
              HasSubstr(p.string() + ":10: segments.thigh.mass_kg: expected a segment mass of at most 150 kg"));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(BadInputCli, ShankLengthInMillimetresExitsOneSayingSo) {
  const fs::path dir = freshDir("mm");
  const fs::path p = writeP1(dir, "length_m: 0.515", "length_m: 515");
  const auto r = runSwingsim("simulate " + p.string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.output, HasSubstr(p.string() + ":11: segments.shank.length_m:"));
  EXPECT_THAT(r.output, HasSubstr("is it in millimetres?"));
}

// ---- Inputs that are not ordinary files -----------------------------------------------

TEST(BadInputCli, DevZeroAsParticipantExitsOneQuickly) {
  testing::CliRun r{};
  EXPECT_LT(childCpuSecondsOf([&] { r = runSwingsim("simulate /dev/zero"); }), 5.0);
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.output, HasSubstr("swingsim: /dev/zero: file too large for an input file"));
}

TEST(BadInputCli, DirectoryAsParticipantExitsOneSayingItIsADirectory) {
  const auto r = runSwingsim("simulate participants");
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.output, HasSubstr("swingsim: participants: is a directory (expected a file)"));
}

TEST(BadInputCli, FifoThatNeverEndsExitsOne) {
  const fs::path dir = freshDir("fifo");
  const fs::path fifo = dir / "endless.yaml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // The writer ends on SIGPIPE once swingsim has closed the pipe.
  const std::string cmd = "(yes 'a: 1' > " + fifo.string() + " 2>/dev/null &) ; " + SWINGSIM_BINARY + " simulate " +
                          fifo.string() + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string out;
  char buf[4096];
  while (std::fgets(buf, sizeof buf, pipe)) out += buf;
  const int status = pclose(pipe);
  EXPECT_EQ(WEXITSTATUS(status), 1) << out;
  EXPECT_THAT(
      out, HasSubstr(fifo.string() + ": file too large for an input file (more than 16 MiB read and not at its end"));
}

TEST(BadInputCli, StudyOverTheSizeLimitWritesNothing) {
  const fs::path dir = freshDir("hugestudy");
  {
    std::ofstream out(dir / "study.yaml");
    out << "kind: knee-axis-sweep\n";
    const std::string comment = "#" + std::string(1000, 'x') + "\n";
    for (int i = 0; i < 17000; ++i) out << comment;
  }
  const auto r = runSwingsim("sweep " + (dir / "study.yaml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.output, HasSubstr("study.yaml: file too large for an input file (16.24 MiB; the limit is 16 MiB)"));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(BadInputCli, ValueBombUnderAnUnknownKeyExitsOneQuickly) {
  const fs::path dir = freshDir("bomb");
  std::string list = "[0";
  for (int i = 0; i < 2'000'000; ++i) list += ",0";
  const fs::path p = writeP1(dir, "name: P1\n", "name: P1\njunk: " + list + "]\n");
  testing::CliRun r{};
  EXPECT_LT(childCpuSecondsOf([&] { r = runSwingsim("simulate " + p.string()); }), 5.0);
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.output, HasSubstr(p.string() + ":6: more than 100000 YAML values in one file"));
}

// ---- Output places checked before any computation -------------------------------------

TEST(BadInputCli, SimulateJsonNamingADirectoryFailsBeforeComputing) {
  const fs::path dir = freshDir("jsondir");
  const auto r =
      runSwingsim("simulate participants/p1.yaml --json " + dir.string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.output, HasSubstr("--json: expected a file to write, got the directory '" + dir.string() + "'"));
  EXPECT_THAT(r.output, ::testing::Not(HasSubstr("swing time")));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(BadInputCli, SweepJsonNamingADirectoryFailsBeforeAnyOutput) {
  const fs::path dir = freshDir("sweepjsondir");
  const fs::path study = writeStudy(dir, {writeP1(dir)});
  fs::create_directories(dir / "j");
  const auto r =
      runSwingsim("sweep " + study.string() + " --out " + (dir / "out").string() + " --json " + (dir / "j").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.output, HasSubstr("--json: expected a file to write, got the directory"));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(BadInputCli, JsonBelowAFileIsAnUnwritablePlace) {
  const fs::path dir = freshDir("jsonbelowfile");
  std::ofstream(dir / "plain.txt") << "x";
  const auto r = runSwingsim("simulate participants/p1.yaml --json " + (dir / "plain.txt" / "r.json").string() +
                             " --out " + (dir / "out").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.output, HasSubstr("is not a folder, so nothing can be written below it"));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(BadInputCli, OutNamingAnExistingFileFailsBeforeComputing) {
  const fs::path dir = freshDir("outfile");
  std::ofstream(dir / "plain.txt") << "keep";
  const auto r = runSwingsim("simulate participants/p1.yaml --out " + (dir / "plain.txt").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.output, HasSubstr("--out: expected an output folder, got the existing file"));
  EXPECT_EQ(slurp(dir / "plain.txt"), "keep");
}

TEST(BadInputCli, EveryCommandChecksItsOutputPlacesWhileParsing) {
  const fs::path dir = freshDir("allcommands");
  std::ofstream(dir / "plain.txt") << "x";
  const std::string file = (dir / "plain.txt").string();
  // The study need not exist: the output place is refused first.
  for (const std::string command : {"fit", "compare", "diagnose", "sweep"}) {
    const auto json = runSwingsim(command + " no-such-study.yaml --json " + dir.string());
    EXPECT_EQ(json.code, 2) << command << ": " << json.output;
    EXPECT_THAT(json.output, HasSubstr("--json: expected a file to write, got the directory")) << command;
    const auto out = runSwingsim(command + " no-such-study.yaml --out " + file);
    EXPECT_EQ(out.code, 2) << command << ": " << out.output;
    EXPECT_THAT(out.output, HasSubstr("--out: expected an output folder, got the existing file")) << command;
  }
  const auto generate = runSwingsim("generate no-such-study.yaml --out " + file);
  EXPECT_EQ(generate.code, 2) << generate.output;
  const auto saveModel = runSwingsim("diagnose no-such-study.yaml --save-model " + dir.string());
  EXPECT_EQ(saveModel.code, 2) << saveModel.output;
  EXPECT_THAT(saveModel.output, HasSubstr("--save-model: expected a file to write, got the directory"));
}

TEST(BadInputCli, EmptyOutAndEmptyJsonAreUsageErrorsForSweep) {
  const fs::path dir = freshDir("emptysweep");
  const fs::path study = writeStudy(dir, {writeP1(dir)});
  const auto out = runSwingsim("sweep " + study.string() + " --out \"\"");
  EXPECT_EQ(out.code, 2);
  EXPECT_THAT(out.output, HasSubstr("--out: expected a value, got an empty string"));
  const auto json = runSwingsim("sweep " + study.string() + " --out " + (dir / "out").string() + " --json \"\"");
  EXPECT_EQ(json.code, 2);
  EXPECT_THAT(json.output, HasSubstr("--json: expected a value, got an empty string"));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// ---- Sweep output staging -------------------------------------------------------------

TEST(BadInputCli, ASuccessfulSweepRemovesAStalePartialCsvAndLeavesNoStaging) {
  const fs::path dir = freshDir("stale");
  const fs::path study = writeStudy(dir, {writeP1(dir)});
  fs::create_directories(dir / "out");
  std::ofstream(dir / "out" / "sweep.partial.csv") << "participant,lowering_m\nP1,0.000\n";
  const auto r = runSwingsim("sweep " + study.string() + " --out " + (dir / "out").string() + " --json " +
                             (dir / "r.json").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out" / "sweep.partial.csv"));
  EXPECT_TRUE(fs::exists(dir / "out" / "sweep.csv"));
  EXPECT_TRUE(fs::exists(dir / "out" / "report.md"));
  EXPECT_NO_THROW(nlohmann::json::parse(slurp(dir / "r.json")));
  EXPECT_EQ(litterIn(dir), std::vector<std::string>{});
}

TEST(BadInputCli, SigtermDuringASweepLeavesOnlyThePartialCsvAndNoLitter) {
  const fs::path dir = freshDir("sigterm");
  // Accuracy 1e-10: about 50 ms a swing, so the 201 swings take seconds after the first
  // progress line, however late the signal comes on a loaded machine (1e-5: 0.3 s in all).
  const fs::path study = writeStudy(dir, {writeP1(dir)}, 0.001, 0.2, "integrator: {accuracy: 1e-10}\n");
  const fs::path out = dir / "out", log = dir / "log.txt";
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::FILE* f = std::freopen(log.c_str(), "w", stdout);
    if (f == nullptr || ::dup2(STDOUT_FILENO, STDERR_FILENO) < 0) ::_exit(127);
    ::execl(SWINGSIM_BINARY, SWINGSIM_BINARY, "sweep", study.c_str(), "--out", out.c_str(), "--jobs", "1", "--json",
            (dir / "r.json").c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  // "DONE/TOTAL swings" is printed once the interrupt handler is in place (the grid's
  // announcement before it also says "swings").
  const std::regex progressLine(R"(\d+/\d+ swings)");
  while (!std::regex_search(slurp(log), progressLine) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_TRUE(std::regex_search(slurp(log), progressLine)) << slurp(log);
  ASSERT_EQ(::kill(pid, SIGTERM), 0);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by the signal instead of stopping cleanly";
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_THAT(slurp(log), HasSubstr("interrupted; finished rows are in " + out.string() + "/sweep.partial.csv"));
  EXPECT_FALSE(fs::exists(out / "report.md"));
  EXPECT_FALSE(fs::exists(out / "sweep.csv"));
  EXPECT_FALSE(fs::exists(dir / "r.json"));
  EXPECT_EQ(litterIn(dir), std::vector<std::string>{});
}

// ---- Names from user files (already fixed; kept fixed) --------------------------------

TEST(BadInputCli, Latin1NameGivesValidUtf8Json) {
  const fs::path dir = freshDir("latin1");
  const fs::path p = writeP1(dir, "name: P1\n", "name: \"J\xF6rg\"\n");
  const auto r = runSwingsim("simulate " + p.string() + " --out " + (dir / "out").string() + " --json " +
                             (dir / "r.json").string());
  ASSERT_EQ(r.code, 0) << r.output;
  nlohmann::json j;
  ASSERT_NO_THROW(j = nlohmann::json::parse(slurp(dir / "r.json")));
  EXPECT_NO_THROW((void)j.dump());  // throws on invalid UTF-8
}

TEST(BadInputCli, PathTraversalNameWritesOnlyInsideOut) {
  const fs::path dir = freshDir("traversal");
  const fs::path p = writeP1(dir, "name: P1\n", "name: \"../../escaped/P1\"\n");
  const auto r = runSwingsim("simulate " + p.string() + " --out " + (dir / "out").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_FALSE(fs::exists(dir / "escaped"));
  EXPECT_FALSE(fs::exists(dir.parent_path() / "escaped"));
  for (const auto& e : fs::recursive_directory_iterator(dir))
    EXPECT_EQ(fs::canonical(e.path()).string().rfind(fs::canonical(dir).string(), 0), 0u) << e.path();
}

TEST(BadInputCli, NewlineInANameIsQuotedInTheSweepCsv) {
  const fs::path dir = freshDir("newline");
  const fs::path study = writeStudy(dir, {writeP1(dir, "name: P1\n", "name: \"P1\\nleft\"\n")});
  const auto r = runSwingsim("sweep " + study.string() + " --out " + (dir / "out").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_THAT(slurp(dir / "out" / "sweep.csv"), HasSubstr("\n\"P1\nleft\",0.000,"));
}

TEST(BadInputCli, SameParticipantFileTwiceIsADuplicateNameError) {
  const fs::path dir = freshDir("twice");
  const fs::path p = writeP1(dir);
  const auto r = runSwingsim("sweep " + writeStudy(dir, {p, p}).string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.output, HasSubstr("participants: two participant files have the same name 'P1'"));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(BadInputCli, LoweringsBelowAMillimetreNeverShareAFile) {
  const fs::path dir = freshDir("lowerings");
  for (const char* lowering : {"0", "0.0004", "0.0006"})
    ASSERT_EQ(
        runSwingsim(std::string("simulate participants/p1.yaml --lowering ") + lowering + " --out " + dir.string())
            .code,
        0);
  EXPECT_TRUE(fs::exists(dir / "P1-lower000mm.csv"));
  EXPECT_TRUE(fs::exists(dir / "P1-lower0.4mm.csv"));
  EXPECT_TRUE(fs::exists(dir / "P1-lower0.6mm.csv"));
  EXPECT_NE(slurp(dir / "P1-lower0.4mm.csv"), slurp(dir / "P1-lower0.6mm.csv"));
}

// ---- calibrate ------------------------------------------------------------------------

TEST(BadInputCli, CalibrateKeepsAReadOnlyMode444) {
  const fs::path dir = freshDir("mode444");
  const fs::path p = writeP1(dir);
  fs::permissions(p, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read, fs::perm_options::replace);
  const auto r = runSwingsim("calibrate " + p.string() + " --target 0.43");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(fs::status(p).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  EXPECT_EQ(litterIn(dir), std::vector<std::string>{});
}

TEST(BadInputCli, CalibrateOnADirectoryOrDevZeroExitsOne) {
  const auto directory = runSwingsim("calibrate participants --target 0.43");
  EXPECT_EQ(directory.code, 1);
  EXPECT_THAT(directory.output, HasSubstr("participants: is a directory (expected a file)"));
  const auto zero = runSwingsim("calibrate /dev/zero --target 0.43");
  EXPECT_EQ(zero.code, 1);
  EXPECT_THAT(zero.output, HasSubstr("/dev/zero: file too large"));
}

TEST(BadInputCli, CalibrateLeavesTheFirstFileUntouchedWhenALaterOneIsTooLarge) {
  const fs::path dir = freshDir("calibratehuge");
  const fs::path good = writeP1(dir);
  const std::string before = slurp(good);
  {
    std::ofstream out(dir / "huge.yaml");
    const std::string comment = "#" + std::string(1000, 'x') + "\n";
    for (int i = 0; i < 17000; ++i) out << comment;
  }
  const auto r = runSwingsim("calibrate " + good.string() + " " + (dir / "huge.yaml").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.output, HasSubstr("huge.yaml: file too large"));
  EXPECT_EQ(slurp(good), before);
  EXPECT_EQ(litterIn(dir), std::vector<std::string>{});
}

TEST(BadInputCli, CalibrateOnAFlowStyleFileWithAKeySpaceColonLoadsBack) {
  const fs::path dir = freshDir("flowspaced");
  std::string t = slurp(kRoot + "/participants/p1.yaml");
  t = std::regex_replace(t, std::regex("\\.\\./models/"), kRoot + "/models/");
  t = t.substr(0, t.find("hip_moment:")) +
      "hip_moment : {profile: biphasic_sine, flexion_amplitude_Nm: 30, flexion_duration_s: 0.20, "
      "extension_amplitude_Nm: 15, extension_duration_s: 0.20, time_scale : 1.08}\n";
  std::ofstream(dir / "p.yaml") << t;
  const auto r = runSwingsim("calibrate " + (dir / "p.yaml").string() + " --target 0.43");
  ASSERT_EQ(r.code, 0) << r.output;
  const auto again = runSwingsim("simulate " + (dir / "p.yaml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(again.code, 0) << again.output;  // the edited file loads back
  EXPECT_THAT(slurp(dir / "p.yaml"), ::testing::Not(HasSubstr("time_scale : 1.08")));
}

}  // namespace
}  // namespace swingsim
