#pragma once
// Numeric CSV tables: a header row of column names, then rows of numbers.
// Reading is strict (file:line: column: what is wrong) and accepts what lab software
// really writes: a UTF-8 byte-order mark, CRLF line ends, blank trailing lines.
#include <cstddef>
#include <string>
#include <vector>

#include "core/plausible_ranges.h"

namespace swingsim {

/// Column-major numeric table with named columns.
struct CsvTable {
  std::string path;
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
  /// Columns present in the file that the reader was not asked for (ignored, noted).
  std::vector<std::string> ignored;

  std::size_t rows() const { return columns.empty() ? 0 : columns.front().size(); }
  /// Index of a column; throws InputError naming the file if it is absent.
  std::size_t index(const std::string& name) const;
  const std::vector<double>& column(const std::string& name) const;
};

/// What a reader requires of a CSV file.
struct CsvSpec {
  std::vector<std::string> required;  ///< columns that must be present
  std::vector<std::string> optional;  ///< columns read if present
  std::string strictlyIncreasing;     ///< column that must strictly increase ("" = none)
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
CsvTable readCsv(const std::string& path, const CsvSpec& spec);
/// Same, from text already in memory (tests, fuzzers).
CsvTable parseCsv(const std::string& text, const std::string& path, const CsvSpec& spec);

/// Formats a table as CSV text with `%.10g` numbers.
std::string formatCsv(const std::vector<std::string>& names,
                      const std::vector<std::vector<double>>& columns);

}  // namespace swingsim
