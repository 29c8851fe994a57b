// Measured sweep times CSV (io/sweep_times_csv.h): what a lab writes is read, nonsense is
// refused with file, line, column, what was expected and what was found.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/input_error.h"
#include "io/sweep_times_csv.h"

namespace swingsim {
namespace {

std::string errorOf(const std::string& text) {
  try {
    parseSweepTimesCsv(text, "t.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SweepTimesCsv, ReadsRowsWithAndWithoutTrialStatistics) {
  const auto rows = parseSweepTimesCsv(
      "\xEF\xBB\xBF# source line\r\nparticipant,lowering_m,swing_time_s,sd_s,n\r\n"
      "P1,0,0.463,0.031,5\r\nP1,0.05,0.423,0.031,5\r\n",
      "t.csv");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].participant, "P1");
  EXPECT_DOUBLE_EQ(rows[1].lowering, 0.05);
  EXPECT_EQ(rows[1].line, 4);
  EXPECT_NEAR(rows[1].calcStandardError(), 0.031 / std::sqrt(5.0), 1e-15);
  const auto plain = parseSweepTimesCsv("participant,lowering_m,swing_time_s\nA,0,0.4\n", "t.csv");
  EXPECT_TRUE(std::isnan(plain[0].sd));
  EXPECT_EQ(plain[0].trials, 1);
}

TEST(SweepTimesCsv, RefusesNonsenseWithFileLineAndColumn) {
  const std::string h = "participant,lowering_m,swing_time_s,sd_s,n\n";

  EXPECT_NE(errorOf("participant,lowering,time\nP1,0,0.4\n").find("t.csv:1: header: expected"), std::string::npos);
  EXPECT_NE(errorOf(h + "P1,0,463,0.031,5\n").find("t.csv:2: swing_time_s: expected 0.05 to 3"), std::string::npos)
      << "a swing time in ms is refused";
  EXPECT_NE(errorOf(h + "P1,0,9.9e37,0.031,5\n").find("swing_time_s"), std::string::npos);
  EXPECT_NE(errorOf(h + "P1,-0.01,0.4,0.031,5\n").find("t.csv:2: lowering_m"), std::string::npos);
  EXPECT_NE(errorOf(h + "P1,0,0.4,0.031,2.5\n").find("t.csv:2: n: expected a whole number"), std::string::npos);
  EXPECT_NE(errorOf(h + "P1,0,0.4,0,5\n").find("t.csv:2: sd_s"), std::string::npos);
  EXPECT_NE(errorOf(h + "P1,0,nan,0.031,5\n").find("expected a finite number (got 'nan')"), std::string::npos);
  EXPECT_NE(errorOf(h + "P1,0,0.4,0.031\n").find("t.csv:2: expected 5 comma-separated values (got 4)"),
            std::string::npos);
  EXPECT_NE(errorOf(h + ",0,0.4,0.031,5\n").find("t.csv:2: participant"), std::string::npos);
  EXPECT_NE(errorOf(h + "P1,0,0.4,0.031,5\nP1,0.0,0.41,0.031,5\n")
                .find("t.csv:3: lowering_m: participant P1 already has "
                      "a row at 0 m (line 2)"),
            std::string::npos);
  EXPECT_NE(errorOf(h).find("expected at least one row"), std::string::npos);
  EXPECT_NE(errorOf("").find("expected a header"), std::string::npos);
  EXPECT_NE(errorOf("participant,lowering_m,swing_time_s\rP1,0,0.4\r").find("t.csv:1: CR-only line ends"),
            std::string::npos);
  const std::string longHeader = "x" + std::string(100000, ',');
  EXPECT_LT(errorOf(longHeader).size(), 400u) << "a header is echoed cut, not whole";
}

TEST(SweepTimesCsv, ChecksAfterParsingNameTheRowsOwnLinePastComments) {
  const std::string text =
      "# source\nparticipant,lowering_m,swing_time_s\n# P1 first\nP1,0,0.4\n\n# again\nP1,0.6,0.4\n";
  EXPECT_EQ(errorOf(text),
            "t.csv:7: lowering_m: expected 0 to 0.5 (m below the standard knee-axis location) (got 0.6)");
  EXPECT_EQ(errorOf("# only a comment\nparticipant,lowering_m,swing_time_s\n# none\n"),
            "t.csv:2: expected at least one row after the header (got none)");
  EXPECT_EQ(errorOf("participant,lowering_m,swing_time_s,sd_s,n\nP1,0,0.4,0.03,1e3\nP2,0,0.4,0.03,1001\n"),
            "t.csv:3: n: expected a whole number of trials from 1 to 1000 (got 1001)");
}

TEST(SweepTimesCsv, SpreadsheetQuotesAroundAFieldAreNotPartOfIt) {
  const auto rows = parseSweepTimesCsv("\"participant\",\"lowering_m\",\"swing_time_s\"\n\"P1\",0,\"0.4\"\n", "t.csv");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].participant, "P1");
  EXPECT_DOUBLE_EQ(rows[0].swingTime, 0.4);
}

}  // namespace
}  // namespace swingsim
