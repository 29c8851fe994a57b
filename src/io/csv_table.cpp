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
#include <utility>

#include "core/input_error.h"
#include "core/output_files.h"

namespace swingsim {

std::size_t CsvTable::index(const std::string& name) const {
  auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end())
    throw InputError(path + ":" + std::to_string(headerLine) + ": " + name + ": column is missing");
  return static_cast<std::size_t>(it - names.begin());
}

const std::vector<double>& CsvTable::column(const std::string& name) const { return columns[index(name)]; }

const std::vector<std::string>& CsvTable::text(const std::string& name) const {
  auto it = std::find(textNames.begin(), textNames.end(), name);
  if (it == textNames.end())
    throw InputError(path + ":" + std::to_string(headerLine) + ": " + name + ": column is missing");
  return textColumns[static_cast<std::size_t>(it - textNames.begin())];
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

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// Reads lines from a stream (a file or text in memory), one at a time, so a file is never
// held in memory twice and an oversized file is refused as soon as it passes maxRows.
class LineReader {
 public:
  LineReader(std::istream& in, const std::string& path, const CsvSpec& spec) : in_(in), path_(path), spec_(spec) {}

  /// The next line without its line end; false at the end of the stream.
  bool next(std::string& out) {
    // std::getline would read an endless line (a file with no newline) whole: read at most
    // spec.maxLineBytes, and at most spec.maxBytes in all.
    out.clear();
    std::streambuf* buffer = in_.rdbuf();
    bool any = false;
    for (int c = buffer->sbumpc(); c != std::char_traits<char>::eof(); c = buffer->sbumpc()) {
      any = true;
      if (c == '\n') break;
      out.push_back(static_cast<char>(c));
      if (out.size() > spec_.maxLineBytes)
        throw InputError(path_ + ":" + std::to_string(lineNo_ + 1) + ": line longer than " +
                         formatByteCount(spec_.maxLineBytes) +
                         (out.find('\r') != std::string::npos
                              ? " (the limit; the file has CR-only line ends: save it with LF or CRLF line ends)"
                              : " (the limit; is this a CSV file with line breaks?)"));
    }
    if (!any) return false;
    ++lineNo_;
    bytesRead_ += out.size() + 1;
    if (bytesRead_ > spec_.maxBytes)
      throw InputError(path_ + ": larger than " + formatByteCount(spec_.maxBytes) +
                       " (the limit; split the file or resample it)");
    if (lineNo_ == 1 && out.size() >= 3 && out.compare(0, 3, "\xEF\xBB\xBF") == 0) out.erase(0, 3);
    if (out.find('\0') != std::string::npos) throw notText(path_);
    if (!out.empty() && out.back() == '\r') out.pop_back();
    // A classic Mac OS export ends lines with CR alone: the whole file reads as one line.
    if (out.find('\r') != std::string::npos)
      throw InputError(
          path_ + ":" + std::to_string(lineNo_) +
          ": CR-only line ends (a carriage return inside a line): save the file with LF or CRLF line ends");
    return true;
  }

  /// The next line that is neither blank nor (if the spec allows them) a comment.
  bool nextContent(std::string& out) {
    while (next(out)) {
      const auto first = out.find_first_not_of(" \t");
      if (first == std::string::npos || (spec_.comments && out[first] == '#')) continue;
      return true;
    }
    return false;
  }

  int lineNo() const { return lineNo_; }

  static InputError notText(const std::string& path) {
    return InputError(path + ": not a text CSV file (contains NUL bytes)");
  }

 private:
  std::istream& in_;
  const std::string& path_;
  const CsvSpec& spec_;
  std::size_t bytesRead_ = 0;
  int lineNo_ = 0;
};

// 'a,b' or 'a,b,c' for a message.
std::string describeHeaders(const std::vector<std::vector<std::string>>& headers) {
  std::string out;
  for (std::size_t i = 0; i < headers.size(); ++i) {
    out += i == 0 ? "'" : i + 1 == headers.size() ? " or '" : ", '";
    for (std::size_t j = 0; j < headers[i].size(); ++j) out += (j ? "," : "") + headers[i][j];
    out += "'";
  }
  return out;
}

// Where each cell of a row goes: a numeric column, a text column, or nowhere (-1).
struct ColumnTarget {
  int numeric = -1;
  int text = -1;
  const CsvSpec::ColumnRange* range = nullptr;
};

// Checks the header row and sets up the table's columns; returns each file column's target.
std::vector<ColumnTarget> readHeader(const std::string& line, const std::vector<std::string>& header,
                                     const CsvSpec& spec, CsvTable& table) {
  const std::string& path = table.path;
  const std::string at = path + ":" + std::to_string(table.headerLine) + ": ";
  if (!spec.allowedHeaders.empty() &&
      std::find(spec.allowedHeaders.begin(), spec.allowedHeaders.end(), header) == spec.allowedHeaders.end()) {
    constexpr std::size_t kEchoedHeader = 120;  // characters of a wrong header echoed in the message
    throw InputError(at + "header: expected " + describeHeaders(spec.allowedHeaders) + " (got '" +
                     (line.size() > kEchoedHeader ? line.substr(0, kEchoedHeader) + "..." : line) + "')");
  }
  // One pass with a hash set: a header of millions of columns is checked in linear time.
  std::unordered_set<std::string> seenColumns;
  for (const auto& name : header)
    if (!seenColumns.insert(name).second) throw InputError(at + name + ": column appears twice in the header");
  std::vector<ColumnTarget> target(header.size());
  auto wanted = spec.required;
  wanted.insert(wanted.end(), spec.optional.begin(), spec.optional.end());
  for (const auto& name : wanted) {
    auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) {
      if (contains(spec.required, name))
        throw InputError(at + name + ": required column is missing (got header '" + line + "')" +
                         (line.find(';') != std::string::npos ? "; is the file separated by semicolons?" : ""));
      continue;
    }
    auto& t = target[static_cast<std::size_t>(it - header.begin())];
    auto& names = contains(spec.text, name) ? table.textNames : table.names;
    (contains(spec.text, name) ? t.text : t.numeric) = static_cast<int>(names.size());
    names.push_back(name);
  }
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (target[i].numeric < 0 && target[i].text < 0) table.ignored.push_back(header[i]);
    for (const auto& r : spec.ranges)
      if (target[i].numeric >= 0 && header[i] == r.column) target[i].range = &r;
  }
  table.columns.assign(table.names.size(), {});
  table.textColumns.assign(table.textNames.size(), {});
  return target;
}

// One number of a row, checked (finite, in range, increasing if asked).
double readNumber(const std::string& s, const std::string& column, const ColumnTarget& target,
                  const std::vector<double>& col, const CsvSpec& spec, const std::string& at) {
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size()) throw InputError(at + column + ": expected a number (got '" + s + "')");
  if (!std::isfinite(v)) throw InputError(at + column + ": expected a finite number (got '" + s + "')");
  if ((v != 0 || errno == ERANGE) && std::fabs(v) < kSmallestMagnitude)
    throw InputError(at + column + ": " + kTooSmallMessage + " (got '" + s + "')");
  if (target.range)
    if (const std::string bad = checkPlausible(v, target.range->range, target.range->what); !bad.empty())
      throw InputError(at + column + ": " + bad + " (got " + s + ")");
  if (column == spec.strictlyIncreasing && !col.empty() && !(v > col.back()))
    throw InputError(at + column + ": must be strictly increasing (got " + s + " after " + formatNumber(col.back()) +
                     ")");
  if (column == spec.strictlyIncreasing && !col.empty() && v - col.back() < spec.minStep)
    throw InputError(at + column + ": expected steps of at least " + formatNumber(spec.minStep) + " (got " + s +
                     " after " + formatNumber(col.back()) + ", a step of " + formatNumber(v - col.back()) + ")");
  return v;
}

void readRow(const std::string& line, int lineNo, const std::vector<std::string>& header,
             const std::vector<ColumnTarget>& target, const CsvSpec& spec, CsvTable& table) {
  const std::string at = table.path + ":" + std::to_string(lineNo) + ": ";
  auto cells = splitLine(line);
  if (cells.size() != header.size())
    throw InputError(at + "expected " + std::to_string(header.size()) + " comma-separated values (got " +
                     std::to_string(cells.size()) + ")" +
                     (cells.size() > header.size() ? "; is the decimal separator a comma?" : ""));
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (target[i].text >= 0) {
      table.textColumns[static_cast<std::size_t>(target[i].text)].push_back(std::move(cells[i]));
    } else if (target[i].numeric >= 0) {
      auto& col = table.columns[static_cast<std::size_t>(target[i].numeric)];
      col.push_back(readNumber(cells[i], header[i], target[i], col, spec, at));
    }
  }
  table.lines.push_back(lineNo);
}

CsvTable readCsvStream(std::istream& in, const std::string& path, const CsvSpec& spec, std::size_t sizeHint) {
  CsvTable table;
  table.path = path;
  // Binary files (a spreadsheet's .xlsx, UTF-16 text) show NUL bytes at once: look at the
  // start before taking the first line for a header.
  char probe[4096];
  in.read(probe, sizeof probe);
  if (std::find(probe, probe + in.gcount(), '\0') != probe + in.gcount()) throw LineReader::notText(path);
  in.clear();
  in.seekg(0);

  LineReader reader(in, path, spec);
  std::string line;
  if (!reader.nextContent(line)) {
    if (in.bad()) throw InputError(path + ": read error");
    throw InputError(path + ":1: empty file (expected a header row: " +
                     (!spec.allowedHeaders.empty() ? describeHeaders(spec.allowedHeaders)
                      : spec.required.empty()      ? std::string("column names")
                                                   : spec.required.front() + ",...") +
                     ")");
  }
  table.headerLine = reader.lineNo();
  const std::vector<std::string> header = splitLine(line);
  const std::vector<ColumnTarget> target = readHeader(line, header, spec, table);
  // Reserve from an upper bound of the row count (a row takes at least 2 bytes a column),
  // never more than maxRows.
  const std::size_t estimate = std::min(spec.maxRows, sizeHint / (2 * header.size()) + 1);
  for (auto& c : table.columns) c.reserve(estimate);
  table.lines.reserve(estimate);

  while (reader.nextContent(line)) {
    if (table.rows() + 1 > spec.maxRows)
      throw InputError(path + ": too many rows (more than " + std::to_string(spec.maxRows) +
                       ", the limit; split the file or resample it)");
    readRow(line, reader.lineNo(), header, target, spec, table);
  }
  if (in.bad()) throw InputError(path + ": read error");
  if (table.rows() < spec.minRows) {
    throw InputError(path + ": too few data rows (got " + std::to_string(table.rows()) + ", need at least " +
                     std::to_string(spec.minRows) + ")");
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

std::string formatCsv(const std::vector<std::string>& names, const std::vector<std::vector<double>>& columns) {
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
