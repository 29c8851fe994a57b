// The bad-input catalogue, part two: inputs and outputs a shell loop or a container hands
// over (issue 29, items 3 and 4). Each case is a clear error naming the file, or a tested
// acceptance: headers of millions of labels are checked in linear time; a FIFO nobody
// serves is refused after kFifoWaitSeconds instead of blocking; a FIFO, a device or a link
// to one is written through, never replaced by a file; over-long and unwritable output
// paths are refused before any work; the same file twice is refused; a thread pool that
// cannot start its threads runs on fewer; a sweep grid is counted before it starts.
#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <limits.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <thread>

#include "../cli/release_only.h"
#include "../cli/run_swingsim.h"
#include "../core/cpu_time.h"
#include "core/input_error.h"
#include "core/output_files.h"
#include "core/output_paths.h"
#include "core/special_files.h"
#include "io/csv_table.h"
#include "io/motion_file.h"
#include "study/sweep_study.h"
#include "sweep/sweep.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;
namespace fs = std::filesystem;

constexpr double kLinearCheck = 3.0;  // CPU s (1.0-1.4 s): labels hashed once; pairwise would take minutes to hours

fs::path scratch(const std::string& name) { return swingsim::testing::freshTempDir("catalogue-files", name); }

double secondsOf(const std::function<void()>& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "accepted";
}

// ---- Linear-time checks ----------------------------------------------------------------

TEST(BadInputCatalogueFiles, MotionHeaderOfMillionsOfLabelsIsCheckedInLinearTime) {
  std::string text = "name\nnRows=1\nendheader\ntime";
  constexpr int kLabels = 1'000'000;
  text.reserve(12 * kLabels);
  for (int i = 0; i < kLabels; ++i) text += " c" + std::to_string(i);
  text += " c0\n";  // the repeat is the last label: a pairwise check reaches it after 5e11 comparisons
  std::string e;
  EXPECT_LT(swingsim::testing::cpuSecondsOf([&] { e = errorOf([&] { parseMotionTable(text, "wide.mot"); }); }),
            kLinearCheck);
  EXPECT_THAT(e, StartsWith("wide.mot:4: c0: column label appears twice"));
}

TEST(BadInputCatalogueFiles, CsvHeaderOfMillionsOfColumnsIsCheckedInLinearTime) {
  std::string text = "time_s";
  constexpr int kColumns = 100'000;  // a 700 kB header line, under the 1 MiB line limit
  text.reserve(12 * kColumns);
  for (int i = 0; i < kColumns; ++i) text += ",c" + std::to_string(i);
  text += ",c0\n0,1\n";
  CsvSpec spec;
  spec.required = {"time_s"};
  std::string e;
  EXPECT_LT(swingsim::testing::cpuSecondsOf([&] { e = errorOf([&] { parseCsv(text, "wide.csv", spec); }); }),
            kLinearCheck);
  EXPECT_THAT(e, StartsWith("wide.csv:1: c0: column appears twice in the header"));
}

// ---- Opens that cannot block -------------------------------------------------------------

// The wait on a FIFO nobody serves: kFifoWaitSeconds, and not much more.
constexpr double kWaitSlack = 3.0;  // s: thread start-up and a loaded CI machine

TEST(BadInputCatalogueFiles, FifoThatNobodyWritesIsRefusedAfterTheDocumentedWait) {
  const fs::path fifo = scratch("fifo-in") / "study.yaml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string e;
  const double waited = secondsOf([&] { e = errorOf([&] { readFile(fifo.string()); }); });
  EXPECT_GE(waited, kFifoWaitSeconds - 0.5);
  EXPECT_LT(waited, kFifoWaitSeconds + kWaitSlack);
  EXPECT_THAT(e, StartsWith(fifo.string() + ": a FIFO (named pipe) that nobody writes: waited " +
                            std::to_string(kFifoWaitSeconds) + " s"));
}

TEST(BadInputCatalogueFiles, FifoWithAWriterIsReadWhole) {
  const fs::path fifo = scratch("fifo-writer") / "p.yaml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string text = "name: P1\nmass_kg: 70\n";
  std::thread writer([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // after the reader opened
    std::ofstream(fifo) << text;
  });
  std::string read;
  EXPECT_NO_THROW(read = readFile(fifo.string()));
  writer.join();
  EXPECT_EQ(read, text);
}

TEST(BadInputCatalogueFiles, CsvFromAFifoIsReadWithoutBlocking) {
  const fs::path fifo = scratch("fifo-csv") / "bench.csv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] { std::ofstream(fifo) << "time_s,force_N\n0,1\n0.1,2\n"; });
  CsvSpec spec;
  spec.required = {"time_s", "force_N"};
  CsvTable table;
  EXPECT_NO_THROW(table = readCsv(fifo.string(), spec));
  writer.join();
  EXPECT_EQ(table.column("force_N"), (std::vector<double>{1, 2}));
}

// ---- Outputs that are devices, FIFOs or links ---------------------------------------------

TEST(BadInputCatalogueFiles, FifoOutputIsWrittenThroughAndStaysAFifo) {
  const fs::path fifo = scratch("fifo-out") / "result.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] {
    std::ifstream in(fifo);
    received.assign(std::istreambuf_iterator<char>(in), {});
  });
  EXPECT_NO_THROW(writeFileAtomic(fifo.string(), "{\"ok\": true}\n"));
  reader.join();
  EXPECT_EQ(received, "{\"ok\": true}\n");
  EXPECT_TRUE(fs::is_fifo(fifo)) << "replaced by a file";
  EXPECT_EQ(std::distance(fs::directory_iterator(fifo.parent_path()), fs::directory_iterator{}), 1)
      << "a temporary file was left";
}

TEST(BadInputCatalogueFiles, FifoOutputThatNobodyReadsIsRefusedAfterTheDocumentedWait) {
  const fs::path fifo = scratch("fifo-no-reader") / "result.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string e;
  const double waited = secondsOf([&] { e = errorOf([&] { writeFileAtomic(fifo.string(), "{}"); }); });
  EXPECT_GE(waited, kFifoWaitSeconds - 0.5);
  EXPECT_LT(waited, kFifoWaitSeconds + kWaitSlack);
  EXPECT_THAT(e, StartsWith(fifo.string() + ": a FIFO (named pipe) that nobody reads: waited"));
  EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST(BadInputCatalogueFiles, LinkToADeviceIsWrittenThroughAndStaysALink) {
  const fs::path link = scratch("link-device") / "out.json";
  fs::create_symlink("/dev/null", link);
  EXPECT_NO_THROW(writeFileAtomic(link.string(), "{}"));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  StagedOutput staged(scratch("link-device-staged").string());
  staged.add("report.md", "# report\n");
  EXPECT_NO_THROW(staged.addBeside(link.string(), "{}"));
  EXPECT_NO_THROW(staged.commit());
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
}

TEST(BadInputCatalogueFiles, LinkToAPlainFileStaysALinkAndItsTargetIsReplaced) {
  const fs::path dir = scratch("link-file");
  std::ofstream(dir / "target.json") << "old";
  fs::create_symlink("target.json", dir / "out.json");
  writeFileAtomic((dir / "out.json").string(), "new");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "out.json")));
  EXPECT_EQ(swingsim::testing::slurp(dir / "target.json"), "new");
  EXPECT_FALSE(isWriteThroughTarget((dir / "out.json").string()));
  EXPECT_TRUE(isWriteThroughTarget("/dev/stdout"));
}

// ---- Output paths checked before any work --------------------------------------------------

TEST(BadInputCatalogueFiles, OverLongOutputNamesAndPathsAreRefused) {
  const std::string longName(NAME_MAX + 1, 'x');
  EXPECT_THAT(findOutputFolderProblem("/tmp/" + longName),
              HasSubstr("bytes; a file system takes at most " + std::to_string(NAME_MAX) + " here (NAME_MAX"));
  // A name that fits, but not with the `.tmp-PID` suffix of an atomic write.
  EXPECT_THAT(findOutputFileProblem("/tmp/" + std::string(NAME_MAX - 2, 'y')), HasSubstr("less the temporary suffix"));
  std::string deep = "/tmp";
  while (deep.size() < PATH_MAX) deep += "/" + std::string(200, 'd');
  EXPECT_THAT(findOutputFolderProblem(deep), HasSubstr("as an absolute path; at most"));
  EXPECT_EQ(findOutputFolderProblem(scratch("fine").string() + "/a/b"), "");
  EXPECT_EQ(findOutputFileProblem("/dev/null"), "");
}

TEST(BadInputCatalogueFiles, OutputBelowAFileOrInAReadOnlyFolderIsRefused) {
  const fs::path dir = scratch("unwritable");
  std::ofstream(dir / "file") << "x";
  EXPECT_THAT(findOutputFolderProblem((dir / "file" / "out").string()), HasSubstr("is not a folder"));
  EXPECT_THAT(findOutputFileProblem((dir / "file" / "r.json").string()), HasSubstr("is not a folder"));
  if (::geteuid() == 0) GTEST_SKIP() << "root may write in a read-only folder";
  fs::create_directories(dir / "ro");
  fs::permissions(dir / "ro", fs::perms::owner_read | fs::perms::owner_exec);
  EXPECT_THAT(findOutputFolderProblem((dir / "ro" / "out").string()), HasSubstr("(permissions)"));
  fs::permissions(dir / "ro", fs::perms::owner_all);
}

TEST(BadInputCatalogueFiles, TheSameFileTwiceIsRefusedWhateverItsSpelling) {
  const fs::path dir = scratch("same-file");
  std::ofstream(dir / "a.yaml") << "name: A\n";
  std::ofstream(dir / "b.yaml") << "name: B\n";
  fs::create_symlink("a.yaml", dir / "link.yaml");
  const std::string a = (dir / "a.yaml").string(), b = (dir / "b.yaml").string();
  EXPECT_NO_THROW(checkDistinctFiles({a, b, (dir / "missing.yaml").string()}, "why"));
  EXPECT_THAT(
      errorOf([&] {
        checkDistinctFiles({a, b, (dir / "." / "a.yaml").string()}, "once, please");
      }),
      StartsWith((dir / "." / "a.yaml").string() + ": the same file as " + a + " (arguments 1 and 3): once, please"));
  EXPECT_THAT(errorOf([&] {
                checkDistinctFiles({(dir / "link.yaml").string(), a}, "once");
              }),
              HasSubstr("the same file as"));
}

// ---- Resource limits -------------------------------------------------------------------------

// Address space left to a child for its thread stacks: a few 8 MiB stacks, not 64.
constexpr rlim_t kSpareAddressSpace = rlim_t{48} << 20;

TEST(BadInputCatalogueFiles, ThreadPoolRunsOnFewerThreadsWhenTheyCannotStart) {
  if (swingsim::testing::kSanitized) GTEST_SKIP() << "an address-space limit breaks the sanitizers' shadow memory";
  int pipeFds[2];
  ASSERT_EQ(::pipe(pipeFds), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::dup2(pipeFds[1], STDERR_FILENO);
    // The child's current size plus a little: most of 64 thread stacks cannot be mapped.
    std::ifstream statm("/proc/self/statm");
    unsigned long pages = 0;
    statm >> pages;
    const rlim_t limit = static_cast<rlim_t>(pages) * static_cast<rlim_t>(::sysconf(_SC_PAGESIZE)) + kSpareAddressSpace;
    const rlimit rl{limit, limit};
    if (::setrlimit(RLIMIT_AS, &rl) != 0) ::_exit(3);
    std::atomic<int> ran{0};
    const int done = runParallelJobs(
        200, 64, [&](int) { ran.fetch_add(1); }, {}, nullptr);
    ::_exit(done == 200 && ran.load() == 200 ? 0 : 1);
  }
  ::close(pipeFds[1]);
  std::string err;
  char buf[512];
  for (ssize_t n; (n = ::read(pipeFds[0], buf, sizeof buf)) > 0;) err.append(buf, static_cast<std::size_t>(n));
  ::close(pipeFds[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "the child died (signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0)
                                 << "): " << err;
  EXPECT_EQ(WEXITSTATUS(status), 0) << "not every job ran: " << err;
  // The pool sees the limit first (capThreadsToAddressSpace), or a thread that still cannot
  // start (startWorkerThreads): either way fewer threads, said on stderr.
  EXPECT_THAT(err, ::testing::ContainsRegex("swingsim: (the address-space limit \\(ulimit -v [0-9]+ kB\\) leaves room "
                                            "for|could start only) [0-9]+ of 64 worker threads"));
}

// ---- Grids counted before they start ------------------------------------------------------------

TEST(BadInputCatalogueFiles, AMillionPointAddedMassGridIsCountedAtOnce) {
  const fs::path dir = scratch("grid");
  std::string masses, distances;
  constexpr int kMasses = 1000, kDistances = 1000;
  for (int i = 1; i <= kMasses; ++i) masses += (i > 1 ? ", " : "") + std::to_string(0.001 * i);
  for (int i = 1; i <= kDistances; ++i) distances += (i > 1 ? ", " : "") + std::to_string(0.0001 * i);
  const fs::path study = swingsim::testing::writeTinySweepStudy(
      dir, 0.1, "added_mass: {mass_kg: [0, " + masses + "], distance_below_knee_m: [" + distances + "]}\n");
  const SweepStudy s = loadSweepStudy(study.string());
  std::uint64_t swings = 0;
  EXPECT_LT(swingsim::testing::cpuSecondsOf([&] { swings = countSweepSwings(s); }), 1.0);
  // Lowerings 0, 0.05 and 0.1 m; every distance (at most 0.1 m) fits on the shortened shank.
  const std::uint64_t lowerings = sweepLowerings(s, s.participants.front()).size();
  EXPECT_EQ(lowerings, 3u);
  EXPECT_EQ(swings, lowerings * (1 + std::uint64_t{kMasses} * kDistances));
  EXPECT_GT(swings, kDefaultMaxSweepSwings);
}

}  // namespace
}  // namespace swingsim
