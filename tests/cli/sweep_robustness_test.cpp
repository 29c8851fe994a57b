// Nothing lost (docs/robustness.md): an interrupted `swingsim sweep` keeps its finished rows readable
// and names the missing ones without writing anything that looks like a final result, and
// the same study run twice gives byte-identical files.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <thread>

#include "../test_build.h"
#include "run_swingsim.h"

namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
  return swingsim::testing::freshTempDir("swingsim_sweep_robustness", name);
}
using swingsim::testing::slurp;

// A one-participant study; `step` sets how many swings it runs.
// `extra`: more study lines (e.g. a slow integrator accuracy for the interrupt tests).
fs::path writeStudy(const fs::path& dir, const std::string& name, double step, double max,
                    const std::string& extra = "") {
  const fs::path study = dir / (name + ".yaml");
  std::ofstream(study) << "kind: knee-axis-sweep\nname: " << name << "\nparticipants: ["
                       << fs::absolute("participants/p1.yaml").string() << "]\nlowering: {step_m: " << step
                       << ", max_m: " << max << ", include_published: false}\n"
                       << extra;
  return study;
}

struct Finished {
  int code = -1;
  std::string output;  // stdout and stderr
};

// Starts `swingsim args...` with output to a file; the caller signals and reaps it.
pid_t spawn(const std::vector<std::string>& args, const fs::path& log) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::FILE* f = std::freopen(log.c_str(), "w", stdout);
    if (f == nullptr || ::dup2(STDOUT_FILENO, STDERR_FILENO) < 0) ::_exit(127);
    std::vector<char*> argv{const_cast<char*>(SWINGSIM_BINARY)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(SWINGSIM_BINARY, argv.data());
    ::_exit(127);
  }
  return pid;
}

Finished reap(pid_t pid, const fs::path& log) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(log)};
}

Finished runToEnd(const std::vector<std::string>& args, const fs::path& log) { return reap(spawn(args, log), log); }

// Progress lines on a non-terminal stderr read "  DONE/TOTAL swings".
int swingsDone(const std::string& log) {
  static const std::regex line(R"(\s(\d+)/(\d+) swings)");
  int done = 0;
  for (auto it = std::sregex_iterator(log.begin(), log.end(), line); it != std::sregex_iterator(); ++it)
    done = std::max(done, std::stoi((*it)[1]));
  return done;
}

TEST(SweepRobustness, SigintKeepsFinishedRowsReadableNamesTheMissingAndWritesNoReport) {
  const fs::path dir = freshDir("sigint");
  // 201 swings of 1 mm lowering steps at accuracy 1e-10 (about 50 ms a swing): seconds of
  // work remain after the first progress line however late the signal comes on a loaded
  // machine (at the default 1e-5 the whole sweep takes 0.3 s).
  const fs::path study = writeStudy(dir, "interrupted", 0.001, 0.2, "integrator: {accuracy: 1e-10}\n");
  const fs::path out = dir / "out";
  const fs::path log = dir / "log.txt";
  const pid_t pid =
      spawn({"sweep", study.string(), "--out", out.string(), "--jobs", "1", "--json", (dir / "r.json").string()}, log);
  // Wait (up to 5 min under sanitizers on a loaded machine) for the first progress report.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (swingsDone(slurp(log)) == 0 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_GT(swingsDone(slurp(log)), 0) << "the sweep never reported progress:\n" << slurp(log);
  ASSERT_EQ(::kill(pid, SIGINT), 0);
  const Finished r = reap(pid, log);

  ASSERT_EQ(r.code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("interrupted; finished rows are in " + out.string() + "/sweep.partial.csv"));
  EXPECT_THAT(r.output, HasSubstr("not run: P1@"));
  // Nothing that looks complete: no report, no final CSV, no JSON, no temporary files.
  EXPECT_FALSE(fs::exists(out / "report.md"));
  EXPECT_FALSE(fs::exists(out / "sweep.csv"));
  EXPECT_FALSE(fs::exists(dir / "r.json"));
  for (const auto& e : fs::directory_iterator(out))
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();

  // The partial file: the sweep CSV header, one row per lowering (finished rows with a
  // swing time, the rest marked as not ended), every row with the header's field count.
  std::istringstream partial(slurp(out / "sweep.partial.csv"));
  std::string header, row;
  ASSERT_TRUE(std::getline(partial, header));
  EXPECT_EQ(header.rfind("participant,lowering_m,", 0), 0u) << header;
  const auto fields = [](const std::string& s) { return std::count(s.begin(), s.end(), ',') + 1; };
  // The last column tells a point that never ran from a swing that ran and did not end.
  EXPECT_EQ(header.substr(header.rfind(',') + 1), "status") << header;
  int rows = 0, finished = 0, notRun = 0;
  while (std::getline(partial, row)) {
    ++rows;
    EXPECT_EQ(fields(row), fields(header)) << row;
    std::smatch m;
    if (std::regex_search(row, m, std::regex(R"(^P1,[0-9.]+,0\.000,0\.000,1,(0\.[0-9]+),.*,ended$)"))) {
      ++finished;
      EXPECT_GT(std::stod(m[1]), 0.2) << row;
    } else {
      // Every swing of this study ends (P1, up to 0.2 m): an unfinished row was not run.
      EXPECT_TRUE(std::regex_search(row, std::regex(R"(^P1,[0-9.]+,0\.000,0\.000,0,,,,,,not_run$)"))) << row;
      ++notRun;
    }
  }
  EXPECT_EQ(finished + notRun, rows);
  EXPECT_EQ(rows, 201);
  EXPECT_GT(finished, 0);
  EXPECT_LT(finished, rows) << "the interrupt came too late to test anything";
}

// A real SIGINT during the uncertainty analysis (after the plain sweep finished): exit 1, no
// report, CSV or JSON, since a report without the analysis asked for would look complete;
// the finished swings are kept in uncertainty.partial.json, which says it is partial (the
// resume from it: uncertainty_shards_cli_test.cpp).
TEST(SweepRobustness, SigintDuringTheUncertaintyAnalysisKeepsOnlyAPartialFile) {
  const fs::path dir = freshDir("sigint-uncertainty");
  const fs::path study = writeStudy(dir, "interrupted-uncertainty", 0.05, 0.2);  // 5 lowerings
  const fs::path out = dir / "out";
  const fs::path log = dir / "log.txt";
  // 5 x (23 + 200) = 1115 swings on one thread: seconds, long enough to interrupt.
  const pid_t pid = spawn({"sweep", study.string(), "--out", out.string(), "--jobs", "1", "--json",
                           (dir / "r.json").string(), "--uncertainty", "200"},
                          log);
  static const std::regex started(R"(uncertainty interrupted-uncertainty: ([1-9]\d*)/\d+ swings)");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (!std::regex_search(slurp(log), started) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_TRUE(std::regex_search(slurp(log), started)) << "the analysis never reported progress:\n" << slurp(log);
  ASSERT_EQ(::kill(pid, SIGINT), 0);
  const Finished r = reap(pid, log);
  ASSERT_EQ(r.code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("are kept in " + (out / "uncertainty.partial.json").string() +
                                  " (\"partial\": true); run the same command again to resume"));
  EXPECT_THAT(r.output, HasSubstr("no report, CSV or JSON in " + out.string() + " was written"));
  const std::string partial = slurp(out / "uncertainty.partial.json");
  EXPECT_THAT(partial, HasSubstr("\"partial\": true"));
  EXPECT_THAT(partial, HasSubstr("\"samples\": 200"));
  EXPECT_THAT(partial, HasSubstr("\"seed\": 1"));
  EXPECT_FALSE(fs::exists(out / "report.md"));
  EXPECT_FALSE(fs::exists(out / "sweep.csv"));
  EXPECT_FALSE(fs::exists(dir / "r.json"));
}

TEST(SweepRobustness, SameStudyTwiceGivesByteIdenticalFiles) {
  const fs::path dir = freshDir("twice");
  const fs::path study = writeStudy(dir, "twice", 0.05, 0.15);
  std::map<std::string, std::string> first;
  for (int run = 0; run < 2; ++run) {
    // Same output folder both times (the report names it), different thread counts.
    const fs::path out = dir / "out";
    fs::remove_all(out);
    const Finished r = runToEnd({"sweep", study.string(), "--out", out.string(), "--jobs", run == 0 ? "1" : "2",
                                 "--json", (out / "sweep.json").string()},
                                dir / "log.txt");
    ASSERT_EQ(r.code, 0) << r.output;
    std::map<std::string, std::string> files;
    for (const auto& e : fs::directory_iterator(out)) files[e.path().filename().string()] = slurp(e.path());
    for (const char* name : {"sweep.csv", "report.md", "sweep.json"}) EXPECT_TRUE(files.count(name)) << name;
    if (run == 0) {
      first = files;
      continue;
    }
    ASSERT_EQ(files.size(), first.size());
    for (const auto& [name, contents] : files) EXPECT_TRUE(contents == first[name]) << name << " differs between runs";
  }
}

// A Simbody exception inside a worker thread (an added mass of 1e300 kg: "Inertia matrix
// contains a NaN") is that point's failure, with the participant and lowering that caused
// it, never an abort of the whole sweep.
TEST(SweepRobustness, AnExceptionInAWorkerIsAFailedPointNotAnAbort) {
  const fs::path dir = freshDir("worker_exception");
  const fs::path study = writeStudy(dir, "heavy", 0.1, 0.1);
  const fs::path out = dir / "out";
  const Finished r =
      runToEnd({"sweep", study.string(), "--out", out.string(), "--add-mass", "1e300@0.1"}, dir / "log.txt");
  ASSERT_EQ(r.code, 0) << r.output;
  const std::string csv = slurp(out / "sweep.csv");
  // The plain points ran; every added-mass point failed and says so.
  EXPECT_THAT(csv, HasSubstr(",ended\n"));
  EXPECT_THAT(csv, HasSubstr(",failed\n"));
  EXPECT_THAT(slurp(out / "report.md"), HasSubstr("P1 at lowering 0 m: the simulation failed:"));
}

}  // namespace
