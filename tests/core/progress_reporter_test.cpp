// ProgressReporter: whole lines for a log (throttled to one per 5 %, or one per step when
// there are few), a bar redrawn in place for a terminal, always ended by a newline.
#include "core/progress_reporter.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace swingsim {
namespace {

using ::testing::EndsWith;
using ::testing::HasSubstr;

// A scratch stream and what was written to it.
class Capture {
 public:
  Capture() : file_(std::tmpfile()) {}
  ~Capture() { std::fclose(file_); }
  std::FILE* file() { return file_; }
  std::string text() {
    std::fflush(file_);
    std::rewind(file_);
    std::string out;
    for (int c; (c = std::fgetc(file_)) != EOF;) out += static_cast<char>(c);
    return out;
  }

 private:
  std::FILE* file_;
};

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(ProgressReporter, LinesAreWholeAndThrottledToOnePerFivePercent) {
  Capture out;
  {
    ProgressReporter progress("sweep", "swings", out.file(), ProgressReporter::Style::kLines);
    for (int done = 0; done <= 84; ++done) {
      progress.update(done, 84);
      progress.update(done, 84);  // repeated reports write nothing
    }
  }
  const std::string text = out.text();
  EXPECT_EQ(text.find('\r'), std::string::npos);
  const std::vector<std::string> lines = splitLines(text);
  const std::regex line(R"(sweep: \d+/84 swings \(\d+ %\), \d+\.\d s)");
  for (const auto& l : lines) EXPECT_TRUE(std::regex_match(l, line)) << l;
  ASSERT_EQ(lines.size(), 21u);  // 0 %, then one per 5 % bucket up to 100 %
  EXPECT_THAT(lines[10], HasSubstr("sweep: 42/84 swings (50 %), "));
  EXPECT_THAT(lines.back(), HasSubstr("sweep: 84/84 swings (100 %), "));
  EXPECT_THAT(text, EndsWith("\n"));
}

TEST(ProgressReporter, FewStepsGetOneLineEach) {
  Capture out;
  ProgressReporter progress("fit", "switch settings", out.file(), ProgressReporter::Style::kLines);
  for (int done = 1; done <= 5; ++done) progress.update(done, 5);
  progress.update(5, 5);  // after the end: nothing
  const std::vector<std::string> lines = splitLines(out.text());
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_THAT(lines[0], HasSubstr("fit: 1/5 switch settings (20 %), "));
  EXPECT_THAT(lines[4], HasSubstr("fit: 5/5 switch settings (100 %), "));
}

TEST(ProgressReporter, NoteIsAWholeLineNamingTheStep) {
  Capture out;
  ProgressReporter progress("sweep b", "swings", out.file(), ProgressReporter::Style::kLines);
  progress.note("4 participants");
  progress.update(0, 3);
  EXPECT_THAT(out.text(), ::testing::StartsWith("sweep b: 4 participants\nsweep b: 0/3 swings (0 %), "));
}

TEST(ProgressReporter, BarIsRedrawnInPlaceAndEndedByANewline) {
  Capture out;
  {
    ProgressReporter progress("sweep", "swings", out.file(), ProgressReporter::Style::kBar);
    for (int done = 0; done <= 200; ++done) progress.update(done, 200);
  }
  const std::string text = out.text();
  EXPECT_EQ(text.find('\n'), text.size() - 1) << "one newline, at the end";
  EXPECT_EQ(text.front(), '\r');
  EXPECT_LE(std::count(text.begin(), text.end(), '\r'), 101) << "redrawn at most once per percent";
  const std::string last = text.substr(text.rfind('\r') + 1);
  EXPECT_TRUE(std::regex_match(last, std::regex(R"(sweep \[#{40}\] 200/200 swings \(100 %\), \d+\.\d s\n)"))) << last;
}

TEST(ProgressReporter, AnInterruptedBarIsEndedWhenTheReporterGoes) {
  Capture out;
  {
    ProgressReporter progress("sweep", "swings", out.file(), ProgressReporter::Style::kBar);
    progress.update(3, 10);
  }
  const std::string text = out.text();
  EXPECT_THAT(text, HasSubstr("3/10 swings (30 %)"));
  EXPECT_THAT(text, EndsWith("\n"));
}

TEST(ProgressReporter, AutoStyleWritesLinesToAFile) {
  Capture out;
  ProgressReporter progress("sweep", "swings", out.file());  // a file is not a terminal
  progress.update(1, 2);
  EXPECT_EQ(out.text().find('\r'), std::string::npos);
}

}  // namespace
}  // namespace swingsim

namespace swingsim {
namespace {

// setShowRate: lines carry the rate and the time left at that rate once something is done;
// the first line (nothing done yet) and the last (all done) have nothing to extrapolate
// from or to, except that the last says 0 s left.
TEST(ProgressReporterRate, LinesShowRateAndTimeLeft) {
  Capture c;
  {
    ProgressReporter p("uncertainty demo", "swings", c.file(), ProgressReporter::Style::kLines);
    p.setShowRate(true);
    p.update(0, 10);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    p.update(5, 10);
    p.update(10, 10);
  }
  const auto lines = splitLines(c.text());
  ASSERT_EQ(lines.size(), 3u) << c.text();
  EXPECT_THAT(lines[0], ::testing::Not(HasSubstr("left")));
  const std::regex rate(R"(uncertainty demo: 5/10 swings \(50 %\), [0-9.]+ s, [0-9]+ swings/s, [0-9]+ s left)");
  EXPECT_TRUE(std::regex_match(lines[1], rate)) << lines[1];
  EXPECT_THAT(lines[2], HasSubstr(", 0 s left"));
}

// Without setShowRate the lines stay as they were (the sweep's documented format).
TEST(ProgressReporterRate, OffByDefault) {
  Capture c;
  {
    ProgressReporter p("sweep demo", "swings", c.file(), ProgressReporter::Style::kLines);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    p.update(5, 10);
  }
  EXPECT_THAT(c.text(), ::testing::Not(HasSubstr("/s")));
}

}  // namespace
}  // namespace swingsim

namespace swingsim {
namespace {

// setResumedFrom: a run that resumes with 900 of 2000 swings done earlier reports the whole
// count, but its rate counts only what it did itself (100 swings in at least 0.1 s: at most
// 1000 swings/s, not 10,000), so the time left is not underestimated.
TEST(ProgressReporterRate, AResumedRunCountsOnlyItsOwnSwingsInTheRate) {
  Capture c;
  {
    ProgressReporter p("uncertainty demo", "swings", c.file(), ProgressReporter::Style::kLines);
    p.setShowRate(true);
    p.setResumedFrom(900);
    p.update(900, 2000);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    p.update(1000, 2000);
  }
  const auto lines = splitLines(c.text());
  ASSERT_EQ(lines.size(), 2u) << c.text();
  EXPECT_THAT(lines[0], ::testing::Not(HasSubstr("left")));  // nothing done in this run yet
  std::smatch m;
  const std::regex rate(
      R"(uncertainty demo: 1000/2000 swings \(50 %\), [0-9.]+ s, ([0-9]+) swings/s, ([0-9]+) s left)");
  ASSERT_TRUE(std::regex_match(lines[1], m, rate)) << lines[1];
  EXPECT_LE(std::stoi(m[1].str()), 1000) << lines[1];
  EXPECT_GE(std::stoi(m[2].str()), 1) << lines[1];  // 1000 swings left at <= 1000 swings/s
}

}  // namespace
}  // namespace swingsim
