// Staged output: files appear in their folder together at commit(), or not at
// all; nothing of the staging is left behind either way.
#include "core/output_files.h"

#include "../cli/run_swingsim.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace swingsim {
namespace {

namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) { return testing::freshTempDir("swingsim_output_files_test", name); }
using testing::slurp;

TEST(StagedOutput, CommitMovesEveryFileInReplacesOldOnesAndRemovesStaleOnes) {
  const fs::path dir = freshDir("commit");
  std::ofstream(dir / "report.md") << "old";
  std::ofstream(dir / "sweep.partial.csv") << "stale";
  {
    StagedOutput staged(dir.string());
    staged.add("report.md", "new");
    staged.add("figures/a.svg", "<svg/>");
    EXPECT_EQ(slurp(dir / "report.md"), "old");  // nothing visible before commit
    EXPECT_FALSE(fs::exists(dir / "figures" / "a.svg"));
    staged.commit({"sweep.partial.csv"});
  }
  EXPECT_EQ(slurp(dir / "report.md"), "new");
  EXPECT_EQ(slurp(dir / "figures" / "a.svg"), "<svg/>");
  EXPECT_FALSE(fs::exists(dir / "sweep.partial.csv"));
  int entries = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    ++entries;
    EXPECT_EQ(e.path().string().find(".staging-"), std::string::npos) << e.path();
    EXPECT_EQ(e.path().string().find(".tmp-"), std::string::npos) << e.path();
  }
  EXPECT_EQ(entries, 3);  // report.md, figures/, figures/a.svg
}

TEST(StagedOutput, WithoutCommitTheFolderIsLeftAsItWas) {
  const fs::path dir = freshDir("discard");
  std::ofstream(dir / "report.md") << "old";
  {
    StagedOutput staged(dir.string());
    staged.add("report.md", "new");
    staged.add("sweep.csv", "rows");
    EXPECT_TRUE(fs::exists(staged.getStagingFolder()));
  }  // a failure or an interrupt before commit
  EXPECT_EQ(slurp(dir / "report.md"), "old");
  EXPECT_FALSE(fs::exists(dir / "sweep.csv"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

}  // namespace
}  // namespace swingsim
