#include "io/csv_table.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <istream>
#include <sstream>
#include <unordered_set>

#include "core/input_error.h"
#include "core/output_files.h"

namespace swingsim {

std::size_t CsvTable::index(const std::string& name) const {
  auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) throw InputError(path + ":1: " + name + ": column is missing");
  return static_cast<std::size_t>(it - names.begin());
}

const std::vector<double>& CsvTable::column(const std::string& name) const {
  return columns[index(name)];
}

namespace {

std::vector<std::string> splitLine(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  for (char c : line) {
    if (c == ',') {
      cells.push_back(cell);
      cell.clear();
    } else {
      cell.push_back(c);
    }
  }
  cells.push_back(cell);
  for (auto& s : cells) {
    auto b = s.find_first_not_of(" \t\"");
    auto e = s.find_last_not_of(" \t\"");
    s = b == std::string::npos ? "" : s.substr(b, e - b + 1);
  }
  return cells;
}

}  // namespace

namespace {

// Reads lines from a stream (a file or text in memory), one at a time, so a file is never
// held in memory twice and an oversized file is refused as soon as it passes maxRows.
CsvTable readCsvStream(std::istream& in, const std::string& path, const CsvSpec& spec, std::size_t sizeHint) {
  CsvTable table;
  table.path = path;
  const auto notText = [&] { return InputError(path + ": not a text CSV file (contains NUL bytes)"); };

  // Binary files (a spreadsheet's .xlsx, UTF-16 text) show NUL bytes at once: look at the
  // start before taking the first line for a header.
  char probe[4096];
  in.read(probe, sizeof probe);
  if (std::find(probe, probe + in.gcount(), '\0') != probe + in.gcount()) throw notText();
  in.clear();
  in.seekg(0);

  std::string line;
  bool first = true;
  std::size_t bytesRead = 0;
  int linesRead = 0;
  auto nextLine = [&](std::string& out) {
    // std::getline would read an endless line (a file with no newline) whole: read at most
    // spec.maxLineBytes, and at most spec.maxBytes in all.
    out.clear();
    std::streambuf* buffer = in.rdbuf();
    bool any = false;
    for (int c = buffer->sbumpc(); c != std::char_traits<char>::eof(); c = buffer->sbumpc()) {
      any = true;
      if (c == '\n') break;
      out.push_back(static_cast<char>(c));
      if (out.size() > spec.maxLineBytes)
        throw InputError(path + ":" + std::to_string(linesRead + 1) + ": line longer than " + formatByteCount(spec.maxLineBytes) +
                         (out.find('\r') != std::string::npos ? " (the limit; the file has CR-only line ends: save it with LF or CRLF line ends)"
                                                              : " (the limit; is this a CSV file with line breaks?)"));
    }
    if (!any) return false;
    ++linesRead;
    bytesRead += out.size() + 1;
    if (bytesRead > spec.maxBytes)
      throw InputError(path + ": larger than " + formatByteCount(spec.maxBytes) + " (the limit; split the file or resample it)");
    if (first && out.size() >= 3 && out.compare(0, 3, "\xEF\xBB\xBF") == 0) out.erase(0, 3);
    first = false;
    if (out.find('\0') != std::string::npos) throw notText();
    if (!out.empty() && out.back() == '\r') out.pop_back();
    // A classic Mac OS export ends lines with CR alone: the whole file reads as one line.
    if (out.find('\r') != std::string::npos)
      throw InputError(path + ":" + std::to_string(linesRead) +
                       ": CR-only line ends (a carriage return inside a line): save the file with LF or CRLF line ends");
    return true;
  };

  if (!nextLine(line) || line.find_first_not_of(" \t") == std::string::npos) {
    if (in.bad()) throw InputError(path + ": read error");
    throw InputError(path + ":1: empty file (expected a header row: " +
                     (spec.required.empty() ? std::string("column names") : spec.required.front() + ",...") + ")");
  }
  std::vector<std::string> header = splitLine(line);
  // Which file column feeds which table column.
  std::vector<int> target(header.size(), -1);
  auto wanted = spec.required;
  wanted.insert(wanted.end(), spec.optional.begin(), spec.optional.end());
  // One pass with a hash set: a header of millions of columns is checked in linear time.
  std::unordered_set<std::string> seenColumns;
  for (const auto& name : header)
    if (!seenColumns.insert(name).second) throw InputError(path + ":1: " + name + ": column appears twice in the header");
  for (const auto& name : wanted) {
    auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) {
      if (std::find(spec.required.begin(), spec.required.end(), name) != spec.required.end()) {
        throw InputError(path + ":1: " + name + ": required column is missing (got header '" + line + "')" +
                         (line.find(';') != std::string::npos ? "; is the file separated by semicolons?" : ""));
      }
      continue;
    }
    target[static_cast<std::size_t>(it - header.begin())] = static_cast<int>(table.names.size());
    table.names.push_back(name);
  }
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (target[i] < 0) table.ignored.push_back(header[i]);
  }
  table.columns.assign(table.names.size(), {});
  std::vector<const CsvSpec::ColumnRange*> rangeOf(header.size(), nullptr);
  for (const auto& r : spec.ranges)
    for (std::size_t i = 0; i < header.size(); ++i)
      if (target[i] >= 0 && header[i] == r.column) rangeOf[i] = &r;
  // Reserve from an upper bound of the row count (a row takes at least 2 bytes a column),
  // never more than maxRows.
  const std::size_t estimate = std::min(spec.maxRows, sizeHint / (2 * header.size()) + 1);
  for (auto& c : table.columns) c.reserve(estimate);

  int lineNo = 1;
  std::size_t rows = 0;
  while (nextLine(line)) {
    ++lineNo;
    if (line.find_first_not_of(" \t") == std::string::npos) continue;  // blank line
    if (++rows > spec.maxRows) {
      throw InputError(path + ": too many rows (more than " + std::to_string(spec.maxRows) +
                       ", the limit; split the file or resample it)");
    }
    auto cells = splitLine(line);
    if (cells.size() != header.size()) {
      throw InputError(path + ":" + std::to_string(lineNo) + ": expected " +
                       std::to_string(header.size()) + " comma-separated values (got " +
                       std::to_string(cells.size()) + ")" +
                       (cells.size() > header.size() ? "; is the decimal separator a comma?" : ""));
    }
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (target[i] < 0) continue;
      const std::string& s = cells[i];
      errno = 0;
      char* end = nullptr;
      double v = std::strtod(s.c_str(), &end);
      if (s.empty() || end != s.c_str() + s.size()) {
        throw InputError(path + ":" + std::to_string(lineNo) + ": " + header[i] +
                         ": expected a number (got '" + s + "')");
      }
      if (!std::isfinite(v) || errno == ERANGE) {
        throw InputError(path + ":" + std::to_string(lineNo) + ": " + header[i] +
                         ": expected a finite number (got '" + s + "')");
      }
      if (rangeOf[i])
        if (const std::string bad = checkPlausible(v, rangeOf[i]->range, rangeOf[i]->what); !bad.empty())
          throw InputError(path + ":" + std::to_string(lineNo) + ": " + header[i] + ": " + bad + " (got " + s + ")");
      auto& col = table.columns[static_cast<std::size_t>(target[i])];
      if (header[i] == spec.strictlyIncreasing && !col.empty() && !(v > col.back())) {
        throw InputError(path + ":" + std::to_string(lineNo) + ": " + header[i] +
                         ": must be strictly increasing (got " + s + " after " +
                         formatNumber(col.back()) + ")");
      }
      if (header[i] == spec.strictlyIncreasing && !col.empty() && v - col.back() < spec.minStep)
        throw InputError(path + ":" + std::to_string(lineNo) + ": " + header[i] + ": expected steps of at least " +
                         formatNumber(spec.minStep) + " (got " + s + " after " + formatNumber(col.back()) +
                         ", a step of " + formatNumber(v - col.back()) + ")");
      col.push_back(v);
    }
  }
  if (in.bad()) throw InputError(path + ": read error");
  if (table.rows() < spec.minRows) {
    throw InputError(path + ": too few data rows (got " + std::to_string(table.rows()) +
                     ", need at least " + std::to_string(spec.minRows) + ")");
  }
  return table;
}

}  // namespace

CsvTable parseCsv(const std::string& text, const std::string& path, const CsvSpec& spec) {
  std::istringstream in(text);
  return readCsvStream(in, path, spec, text.size());
}

CsvTable readCsv(const std::string& path, const CsvSpec& spec) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": is a directory, not a CSV file");
  // A FIFO or a device: read without blocking (readFile waits a bounded time for a writer).
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec)) {
    constexpr std::size_t kMaxStreamedCsvBytes = std::size_t{256} << 20;  // a 10-million-row bench record
    return parseCsv(readFile(path, kMaxStreamedCsvBytes), path, spec);
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open file");
  const auto size = std::filesystem::file_size(path, ec);
  return readCsvStream(in, path, spec, ec ? 0 : static_cast<std::size_t>(size));
}

std::string formatCsv(const std::vector<std::string>& names,
                      const std::vector<std::vector<double>>& columns) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) out += (i ? "," : "") + names[i];
  out += "\n";
  std::size_t rows = columns.empty() ? 0 : columns.front().size();
  char buf[32];
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      std::snprintf(buf, sizeof buf, "%.10g", columns[c][r]);
      if (c) out += ',';
      out += buf;
    }
    out += '\n';
  }
  return out;
}

}  // namespace swingsim
