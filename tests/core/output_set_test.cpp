// One run per output folder: a staged set replaces the folder's earlier run whole or not at
// all, removes the earlier run's files it does not write again (never a user's), and a
// staging folder is cleaned only once its owner is provably gone.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "../cli/run_swingsim.h"
#include "core/input_error.h"
#include "core/output_files.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;
using testing::slurp;

fs::path freshDir(const std::string& name) { return testing::freshTempDir("swingsim_output_set_test", name); }

// A pid that has provably ended: a child that exited and was waited for.
pid_t deadPid() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  ::waitpid(pid, nullptr, 0);
  return pid;
}

// This host's staging folder name for `pid`.
std::string stagingNameFor(pid_t pid) {
  const std::string mine = makeStagingFolderName();
  return mine.substr(0, mine.rfind('-') + 1) + std::to_string(pid);
}

std::vector<std::string> stagingFoldersIn(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().rfind(".staging-", 0) == 0) found.push_back(e.path().filename().string());
  std::sort(found.begin(), found.end());
  return found;
}

TEST(OutputSet, AFolderInTheWayOfOneFileKeepsTheEarlierRunWhole) {
  const fs::path dir = freshDir("in-the-way");
  std::ofstream(dir / "report.md") << "earlier";
  fs::create_directories(dir / "sweep.csv" / "mine");  // a folder where the CSV goes
  {
    StagedOutput staged(dir.string(), OutputSetKind::kWholeRun);
    staged.add("report.md", "new");
    staged.add("figures/P1-swing-time.svg", "<svg/>");
    staged.add("sweep.csv", "rows");
    try {
      staged.commit();
      FAIL() << "committed over a folder";
    } catch (const RunError& e) {
      EXPECT_THAT(e.what(),
                  HasSubstr("--out " + dir.string() + ": a folder is in the way of the output file sweep.csv"));
      EXPECT_THAT(e.what(), HasSubstr("nothing in the folder was changed"));
      EXPECT_THAT(e.what(), Not(HasSubstr(".staging")));
    }
  }
  EXPECT_EQ(slurp(dir / "report.md"), "earlier");
  EXPECT_FALSE(fs::exists(dir / "figures"));
  EXPECT_TRUE(fs::is_directory(dir / "sweep.csv" / "mine"));
  EXPECT_EQ(stagingFoldersIn(dir), std::vector<std::string>{});
}

TEST(OutputSet, ASecondRunRemovesTheFirstRunsExtraFiguresButNoUserFile) {
  const fs::path dir = freshDir("two-runs");
  std::ofstream(dir / "notes.txt") << "mine";
  {
    StagedOutput first(dir.string(), OutputSetKind::kWholeRun);
    for (const char* name : {"report.md", "figures/P1-swing-time.svg", "figures/P2-swing-time.svg"})
      first.add(name, "1");
    first.commit();
  }
  std::ofstream(dir / "figures" / "my-sketch.svg") << "mine";
  {
    StagedOutput second(dir.string(), OutputSetKind::kWholeRun);
    for (const char* name : {"report.md", "figures/P1-swing-time.svg"}) second.add(name, "2");
    second.commit();
  }
  EXPECT_EQ(slurp(dir / "report.md"), "2");
  EXPECT_EQ(slurp(dir / "figures" / "P1-swing-time.svg"), "2");
  EXPECT_FALSE(fs::exists(dir / "figures" / "P2-swing-time.svg"));
  EXPECT_EQ(slurp(dir / "notes.txt"), "mine");
  EXPECT_EQ(slurp(dir / "figures" / "my-sketch.svg"), "mine");
  EXPECT_THAT(slurp(dir / kOutputManifestName), HasSubstr("\nreport.md\nfigures/P1-swing-time.svg\n"));
}

TEST(OutputSet, FilesAddedLeaveTheFoldersOtherFiles) {
  const fs::path dir = freshDir("added");
  for (const char* name : {"P1-lower000mm.csv", "P2-lower000mm.csv"}) {
    StagedOutput staged(dir.string());
    staged.add(name, "rows");
    staged.commit();
  }
  EXPECT_TRUE(fs::exists(dir / "P1-lower000mm.csv"));
  EXPECT_TRUE(fs::exists(dir / "P2-lower000mm.csv"));
  EXPECT_FALSE(fs::exists(dir / kOutputManifestName));
}

TEST(OutputSet, ADeadRunsStagingIsRemovedALiveSiblingsAndAnotherHostsAreKept) {
  const fs::path dir = freshDir("stale");
  const std::string dead = stagingNameFor(deadPid()), live = stagingNameFor(::getppid());
  const std::string otherHost = ".staging-another-host-" + std::to_string(deadPid());
  const std::string legacy = ".staging-" + std::to_string(deadPid());  // no host: cannot be proven gone
  for (const auto& name : {dead, live, otherHost, legacy}) {
    fs::create_directories(dir / name);
    std::ofstream(dir / name / "report.md") << "half";
  }
  {
    StagedOutput staged(dir.string(), OutputSetKind::kWholeRun);
    staged.add("report.md", "new");
    staged.commit();
  }
  EXPECT_FALSE(fs::exists(dir / dead));
  std::vector<std::string> kept = {live, otherHost, legacy};
  std::sort(kept.begin(), kept.end());
  EXPECT_EQ(stagingFoldersIn(dir), kept);
  EXPECT_EQ(slurp(dir / live / "report.md"), "half");
}

TEST(OutputSet, ACompleteSetOfARunKilledWhileMovingItInIsMovedInByTheNextRun) {
  const fs::path dir = freshDir("killed-commit");
  // The earlier run: report.md and one figure, named in the manifest.
  fs::create_directories(dir / "figures");
  std::ofstream(dir / "report.md") << "earlier";
  std::ofstream(dir / "figures" / "old.svg") << "earlier";
  std::ofstream(dir / kOutputManifestName) << "# manifest\nreport.md\nfigures/old.svg\n";
  // A run killed after its marker, before its report moved in (its figure already had).
  const fs::path staging = dir / stagingNameFor(deadPid());
  fs::create_directories(staging);
  std::ofstream(staging / "report.md") << "killed run";
  std::ofstream(dir / "figures" / "new.svg") << "killed run";
  std::ofstream(staging / kOutputManifestName) << "# manifest\nreport.md\nfigures/new.svg\n";
  std::ofstream(staging / ".commit") << "run\n";
  { StagedOutput next(dir.string(), OutputSetKind::kWholeRun); }  // started, then failed before its commit
  EXPECT_EQ(slurp(dir / "report.md"), "killed run");
  EXPECT_EQ(slurp(dir / "figures" / "new.svg"), "killed run");
  EXPECT_FALSE(fs::exists(dir / "figures" / "old.svg"));
  EXPECT_EQ(slurp(dir / kOutputManifestName), "# manifest\nreport.md\nfigures/new.svg\n");
  EXPECT_EQ(stagingFoldersIn(dir), std::vector<std::string>{});
}

TEST(OutputSet, AManifestCannotMakeARunDeleteOutsideItsFolder) {
  const fs::path dir = freshDir("hostile-manifest");
  fs::create_directories(dir / "out");
  std::ofstream(dir / "precious.txt") << "keep";
  std::ofstream(dir / "out" / kOutputManifestName) << "../precious.txt\n" << (dir / "precious.txt").string() << "\n";
  StagedOutput staged((dir / "out").string(), OutputSetKind::kWholeRun);
  staged.add("report.md", "new");
  staged.commit();
  EXPECT_EQ(slurp(dir / "precious.txt"), "keep");
}

TEST(OutputSet, ErrorsNameOutNeverTheStagingFolder) {
  const fs::path dir = freshDir("replaced");
  const fs::path out = dir / "out";
  StagedOutput staged(out.string(), OutputSetKind::kWholeRun);
  staged.add("report.md", "finished");
  // --out moved away and a file put in its place while the run worked.
  fs::rename(out, dir / "moved");
  std::ofstream(out) << "a file";
  try {
    staged.commit();
    FAIL() << "committed into a file";
  } catch (const RunError& e) {
    EXPECT_THAT(e.what(), HasSubstr("--out " + out.string() + ": the output folder was moved, removed or replaced"));
    EXPECT_THAT(e.what(), Not(HasSubstr(".staging")));
  }
  try {
    StagedOutput onAFile(out.string());
    FAIL() << "staged into a file";
  } catch (const RunError& e) {
    EXPECT_THAT(e.what(), HasSubstr("--out " + out.string() + ": a file is in the place of the output folder"));
    EXPECT_THAT(e.what(), Not(HasSubstr(".staging")));
  }
}

TEST(OutputSet, OnlyAStagingFolderOfThisHostAndADeadPidIsOrphaned) {
  EXPECT_TRUE(isOrphanedStagingFolder(stagingNameFor(deadPid())));
  EXPECT_FALSE(isOrphanedStagingFolder(stagingNameFor(::getppid())));
  EXPECT_FALSE(isOrphanedStagingFolder(".staging-another-host-" + std::to_string(deadPid())));
  EXPECT_FALSE(isOrphanedStagingFolder(".staging-" + std::to_string(deadPid())));
  EXPECT_FALSE(isOrphanedStagingFolder("report.md"));
  EXPECT_FALSE(isOrphanedStagingFolder(stagingNameFor(1).substr(0, stagingNameFor(1).size() - 1) + "x"));
}

}  // namespace
}  // namespace swingsim
