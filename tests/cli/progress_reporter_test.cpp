// Progress written to a non-terminal (a CI log, `| tee`) is whole lines: one per step, each
// naming its step, never a carriage return or two reports run together.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <sstream>
#include <string>


namespace swingsim {
namespace {

TEST(ProgressReporter, SweepProgressIntoAPipeIsOneWholeLinePerStep) {
  const std::string out = ::testing::TempDir() + "swingsim_progress_test";
  // stderr into the pipe, stdout to /dev/null: what is read is the progress only.
  const std::string cmd = std::string(SWINGSIM_BINARY) + " sweep studies/burkett2004.yaml --out " + out + " 2>&1 >/dev/null";
  FILE* pipe = popen(cmd.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string text;
  std::array<char, 4096> buf{};
  while (std::fgets(buf.data(), buf.size(), pipe)) text += buf.data();
  ASSERT_EQ(pclose(pipe), 0) << text;
  EXPECT_EQ(text.find('\r'), std::string::npos);
  std::istringstream lines(text);
  std::string line;
  int progressLines = 0;
  while (std::getline(lines, line)) {
    if (line.rfind("sweeping ", 0) == 0) continue;  // the announcement before the work
    ASSERT_EQ(line.rfind("sweep burkett2004: ", 0), 0u) << "not a progress line: " << line;
    EXPECT_NE(line.find(" swings ("), std::string::npos) << line;
    EXPECT_NE(line.find(" s"), std::string::npos) << line;
    ++progressLines;
  }
  // A tenth of the work per line: 2 to 12 lines (start, tenths, end).
  EXPECT_GE(progressLines, 2);
  EXPECT_LE(progressLines, 12);
}

}  // namespace
}  // namespace swingsim
