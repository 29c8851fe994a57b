#include "io/csv_table.h"

#include <gtest/gtest.h>

#include <string>

#include "core/input_error.h"

namespace swingsim {
namespace {

// The message of the InputError `parse` throws; "" if it throws none.
template <class F>
std::string inputErrorOf(F parse) {
  try {
    parse();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

CsvSpec timeAndForce() {
  CsvSpec spec;
  spec.required = {"time_s", "force_N"};
  spec.optional = {"position_m"};
  spec.strictlyIncreasing = "time_s";
  return spec;
}

TEST(CsvTable, ReadsRequiredAndOptionalColumnsInSpecOrder) {
  // Columns in another order in the file, one not asked for, a BOM, CRLF and a blank tail.
  const std::string text =
      "\xEF\xBB\xBF"
      "force_N,comment_code,time_s,position_m\r\n10,1,0,0.5\r\n20,2,0.1,0.4\r\n\r\n";
  const CsvTable t = parseCsv(text, "bench.csv", timeAndForce());
  EXPECT_EQ(t.names, (std::vector<std::string>{"time_s", "force_N", "position_m"}));
  EXPECT_EQ(t.ignored, std::vector<std::string>{"comment_code"});
  ASSERT_EQ(t.rows(), 2u);
  EXPECT_EQ(t.column("time_s"), (std::vector<double>{0, 0.1}));
  EXPECT_EQ(t.column("force_N"), (std::vector<double>{10, 20}));
  EXPECT_EQ(t.index("position_m"), 2u);
}

TEST(CsvTable, AbsentOptionalColumnIsNotATableColumn) {
  const CsvTable t = parseCsv("time_s,force_N\n0,1\n", "a.csv", timeAndForce());
  EXPECT_EQ(t.names.size(), 2u);
  EXPECT_EQ(inputErrorOf([&] { t.index("position_m"); }), "a.csv:1: position_m: column is missing");
}

TEST(CsvTable, BadInputNamesFileLineAndColumn) {
  const CsvSpec spec = timeAndForce();
  EXPECT_EQ(inputErrorOf([&] { parseCsv("time_s,force_N\n0,1\n0.1,x\n", "b.csv", spec); }),
            "b.csv:3: force_N: expected a number (got 'x')");
  EXPECT_EQ(inputErrorOf([&] { parseCsv("time_s,force_N\n0,1\n0,2\n", "b.csv", spec); }),
            "b.csv:3: time_s: must be strictly increasing (got 0 after 0)");
  EXPECT_EQ(inputErrorOf([&] { parseCsv("time_s,force_N\n0,1,2\n", "b.csv", spec); }),
            "b.csv:2: expected 2 comma-separated values (got 3); is the decimal separator a comma?");
  EXPECT_EQ(inputErrorOf([&] { parseCsv("time_s;force_N\n0;1\n", "b.csv", spec); }),
            "b.csv:1: time_s: required column is missing (got header 'time_s;force_N'); is the file separated by "
            "semicolons?");
  EXPECT_EQ(inputErrorOf([&] { parseCsv("time_s,time_s\n", "b.csv", spec); }),
            "b.csv:1: time_s: column appears twice in the header");
  EXPECT_EQ(inputErrorOf([&] { parseCsv("time_s,force_N\n", "b.csv", spec); }),
            "b.csv: too few data rows (got 0, need at least 1)");
  EXPECT_EQ(inputErrorOf([&] { parseCsv("time_s,force_N\n0,1e999\n", "b.csv", spec); }),
            "b.csv:2: force_N: expected a finite number (got '1e999')");
}

CsvSpec participantAndTime() {
  CsvSpec spec;
  spec.required = {"participant", "swing_time_s"};
  spec.optional = {"note"};
  spec.text = {"participant", "note"};
  return spec;
}

TEST(CsvTable, TextColumnsKeepTheirCellsAndAreNotParsedAsNumbers) {
  const CsvTable t =
      parseCsv("swing_time_s,participant,note\n0.4,\"P 1\",  left heel \n0.5,2,\n", "p.csv", participantAndTime());
  EXPECT_EQ(t.names, std::vector<std::string>{"swing_time_s"});
  EXPECT_EQ(t.textNames, (std::vector<std::string>{"participant", "note"}));
  EXPECT_EQ(t.text("participant"), (std::vector<std::string>{"P 1", "2"})) << "quotes and blanks around a cell go";
  EXPECT_EQ(t.text("note"), (std::vector<std::string>{"left heel", ""})) << "an empty text cell is read as \"\"";
  EXPECT_EQ(t.column("swing_time_s"), (std::vector<double>{0.4, 0.5}));
  EXPECT_EQ(t.rows(), 2u);
  EXPECT_EQ(inputErrorOf([&] { t.text("swing_time_s"); }), "p.csv:1: swing_time_s: column is missing")
      << "a numeric column is not a text column";
  EXPECT_EQ(inputErrorOf([&] { t.index("participant"); }), "p.csv:1: participant: column is missing");
  EXPECT_EQ(inputErrorOf([&] { parseCsv("participant,swing_time_s\nP1,fast\n", "p.csv", participantAndTime()); }),
            "p.csv:2: swing_time_s: expected a number (got 'fast')")
      << "the numeric column beside a text column is still checked";
}

TEST(CsvTable, RowsKeepTheirSourceLinesPastCommentsAndBlankLines) {
  CsvSpec spec = participantAndTime();
  spec.comments = true;
  const std::string text =
      "# measured 2004\n\n  # indented comment\nparticipant,swing_time_s\nP1,0.4\n\n# P2 lost\nP3,0.5\n";
  const CsvTable t = parseCsv(text, "c.csv", spec);
  EXPECT_EQ(t.headerLine, 4);
  EXPECT_EQ(t.lines, (std::vector<int>{5, 8}));
  EXPECT_EQ(t.text("participant"), (std::vector<std::string>{"P1", "P3"}));
  EXPECT_EQ(inputErrorOf([&] { t.index("speed"); }), "c.csv:4: speed: column is missing") << "names the header's line";
  EXPECT_EQ(inputErrorOf([&] { parseCsv("# a\nparticipant,swing_time_s\n# b\nP1,x\n", "c.csv", spec); }),
            "c.csv:4: swing_time_s: expected a number (got 'x')");
}

TEST(CsvTable, WithoutCommentsAHashLineIsData) {
  // A reader that does not allow comments sees '#' lines as a header or a row, as before.
  EXPECT_EQ(inputErrorOf([&] { parseCsv("# note\nparticipant,swing_time_s\n", "h.csv", participantAndTime()); }),
            "h.csv:1: participant: required column is missing (got header '# note')");
  EXPECT_EQ(inputErrorOf([&] { parseCsv("time_s,force_N\n0,1\n# x,2\n", "h.csv", timeAndForce()); }),
            "h.csv:3: time_s: expected a number (got '# x')");
  // Blank lines before the header are skipped; the rows keep their lines.
  const CsvTable t = parseCsv("\n\ntime_s,force_N\n0,1\n", "h.csv", timeAndForce());
  EXPECT_EQ(t.headerLine, 3);
  EXPECT_EQ(t.lines, std::vector<int>{4});
}

TEST(CsvTable, AllowedHeadersFixTheColumnsAndTheirOrder) {
  CsvSpec spec = participantAndTime();
  spec.allowedHeaders = {{"participant", "swing_time_s"}, {"participant", "swing_time_s", "note"}};
  EXPECT_EQ(parseCsv("participant,swing_time_s,note\nP1,0.4,ok\n", "a.csv", spec).text("note"),
            std::vector<std::string>{"ok"});
  EXPECT_EQ(inputErrorOf([&] { parseCsv("swing_time_s,participant\n0.4,P1\n", "a.csv", spec); }),
            "a.csv:1: header: expected 'participant,swing_time_s' or 'participant,swing_time_s,note' (got "
            "'swing_time_s,participant')")
      << "another order is refused";
  EXPECT_EQ(
      inputErrorOf([&] { parseCsv("", "a.csv", spec); }),
      "a.csv:1: empty file (expected a header row: 'participant,swing_time_s' or 'participant,swing_time_s,note')");
  const std::string longHeader = "participant," + std::string(500, 'x');
  EXPECT_EQ(
      inputErrorOf([&] { parseCsv(longHeader, "a.csv", spec); }).size(),
      std::string("a.csv:1: header: expected 'participant,swing_time_s' or 'participant,swing_time_s,note' (got '")
              .size() +
          120 + 5)
      << "a long header is echoed cut to 120 characters and '...'";
}

TEST(CsvTable, FormatReadsBack) {
  const std::vector<std::string> names = {"time_s", "force_N"};
  const std::vector<std::vector<double>> columns = {{0, 0.1, 0.2}, {1.5, -2.25, 1e-7}};
  const std::string text = formatCsv(names, columns);
  EXPECT_EQ(text, "time_s,force_N\n0,1.5\n0.1,-2.25\n0.2,1e-07\n");
  const CsvTable t = parseCsv(text, "round.csv", timeAndForce());
  EXPECT_EQ(t.columns, columns);
}

}  // namespace
}  // namespace swingsim
