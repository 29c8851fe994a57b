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
  const std::string text = "\xEF\xBB\xBF" "force_N,comment_code,time_s,position_m\r\n10,1,0,0.5\r\n20,2,0.1,0.4\r\n\r\n";
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
