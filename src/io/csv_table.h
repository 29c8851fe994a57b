#pragma once
// CSV tables: a header row of column names, then rows of numbers (and of text in the
// columns a reader declares text). Reading is strict (file:line: column: what is wrong)
// and accepts what lab software really writes: a UTF-8 byte-order mark, CRLF line ends,
// blank lines, and (when the reader allows them) `#` comment lines. Each row keeps its
// source line, so a reader can name `file:line:` for a check it makes after parsing.
#include <cstddef>
#include <string>
#include <vector>

#include "core/plausible_ranges.h"

namespace swingsim {

/// Column-major table with named columns: numeric columns in `names`/`columns`, text
/// columns (CsvSpec::text) in `textNames`/`textColumns`, each in the spec's order.
struct CsvTable {
  std::string path;
  std::vector<std::string> names;  ///< numeric columns read
  std::vector<std::vector<double>> columns;
  std::vector<std::string> textNames;  ///< text columns read (cells trimmed, quotes removed)
  std::vector<std::vector<std::string>> textColumns;
  /// Source line of each row (the file's first line is 1; comment and blank lines count).
  std::vector<int> lines;
  int headerLine = 1;  ///< source line of the header row
  /// Columns present in the file that the reader was not asked for (ignored, noted).
  std::vector<std::string> ignored;

  std::size_t rows() const { return lines.size(); }
  /// Index of a numeric column; throws InputError naming the file if it is absent.
  std::size_t index(const std::string& name) const;
  const std::vector<double>& column(const std::string& name) const;
  /// A text column; throws InputError naming the file if it is absent.
  const std::vector<std::string>& text(const std::string& name) const;
};

/// What a reader requires of a CSV file.
struct CsvSpec {
  std::vector<std::string> required;  ///< columns that must be present
  std::vector<std::string> optional;  ///< columns read if present
  /// Columns among required/optional read as text, not numbers (an empty cell is "").
  std::vector<std::string> text;
  /// If not empty, the header must be one of these, column for column (a reader whose
  /// format fixes the order); otherwise any order, and unknown columns are ignored.
  std::vector<std::vector<std::string>> allowedHeaders;
  /// Lines whose first non-blank character is '#' are comments, skipped (also before the
  /// header); without this, such a line is read as a header or a row.
  bool comments = false;
  std::string strictlyIncreasing;  ///< column that must strictly increase ("" = none)
  /// Least step of the strictlyIncreasing column, in its unit (0: any step > 0).
  double minStep = 0;
  /// A column's plausible range (core/plausible_ranges.h), checked on every value read:
  /// `what` names the quantity in the message ("a force").
  struct ColumnRange {
    std::string column;
    PlausibleRange range;
    std::string what;
  };
  std::vector<ColumnRange> ranges;
  std::size_t minRows = 1;
  /// Refuse files with more rows than this: 2,000,000 rows of 3 columns is 48 MB. Files
  /// are read line by line, so a larger file is refused after maxRows rows, at about that
  /// memory, never loaded whole.
  std::size_t maxRows = 2000000;
  /// Refuse a line longer than this (a file without line breaks is read no further).
  std::size_t maxLineBytes = std::size_t{1} << 20;
  /// Refuse a file larger than this (2,000,000 rows of 3 numbers fit).
  std::size_t maxBytes = std::size_t{128} << 20;
};

/// Reads `path` according to `spec`. Throws InputError with `path:line: column: ...`.
/// Blank lines are skipped anywhere, also before the header.
CsvTable readCsv(const std::string& path, const CsvSpec& spec);
/// Same, from text already in memory (tests, fuzzers).
CsvTable parseCsv(const std::string& text, const std::string& path, const CsvSpec& spec);

/// Formats a table as CSV text with `%.10g` numbers.
std::string formatCsv(const std::vector<std::string>& names, const std::vector<std::vector<double>>& columns);

}  // namespace swingsim
