// `swingsim sweep` with stderr in a file (a CI log, `2> log`): its progress is whole lines,
// each starting with the step name, never a carriage return or two reports run together.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include "../test_build.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;

TEST(SweepProgress, StderrInAFileGetsOneWholeLinePerReport) {
  const fs::path dir = fs::path(::testing::TempDir()) / "swingsim_sweep_progress_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path log = dir / "stderr.txt";
  const std::string cmd = std::string(SWINGSIM_BINARY) + " sweep studies/burkett2004.yaml --out " +
                          (dir / "out").string() + " >/dev/null 2>" + log.string();
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << cmd;
  std::ifstream in(log, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  const std::string text = s.str();

  EXPECT_EQ(text.find('\r'), std::string::npos) << text;
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n') << "the last line is not ended";
  const std::regex progressLine(R"(sweep burkett2004: (\d+)/(\d+) swings \((\d+) %\), \d+\.\d s)");
  std::istringstream lines(text);
  std::string line;
  int progressLines = 0, lastDone = -1, total = 0;
  while (std::getline(lines, line)) {
    ASSERT_EQ(line.rfind("sweep burkett2004: ", 0), 0u) << "not a line of the sweep's step: " << line;
    std::smatch m;
    if (!std::regex_match(line, m, progressLine)) {
      if (line.rfind("sweep burkett2004: terminal impact check: ", 0) == 0) continue;  // the step after the sweep
      // The grid announced before anything runs: its swing count and estimated time.
      if (std::regex_match(line, std::regex(R"(sweep burkett2004: \d+ swings \(.*\), about .* on \d+ threads?)")))
        continue;
      EXPECT_EQ(line, "sweep burkett2004: 4 participants (studies/burkett2004.yaml)");
      continue;
    }
    const int done = std::stoi(m[1]);
    total = std::stoi(m[2]);
    EXPECT_GT(done, lastDone) << line;
    EXPECT_EQ(std::stoi(m[3]), 100 * done / total) << line;
    lastDone = done;
    ++progressLines;
  }
  // At most one line per 5 % of the work, plus the start and the end.
  EXPECT_GE(progressLines, 2);
  EXPECT_LE(progressLines, 22);
  EXPECT_EQ(lastDone, total) << "no final report";
}

}  // namespace
}  // namespace swingsim
