#include "io/csv_table.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "io/input_error.h"

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

CsvTable parseCsv(const std::string& text, const std::string& path, const CsvSpec& spec) {
  CsvTable table;
  table.path = path;
  std::size_t pos = 0;
  if (text.size() >= 3 && text.compare(0, 3, "\xEF\xBB\xBF") == 0) pos = 3;
  if (text.find('\0') != std::string::npos) {
    throw InputError(path + ": not a text CSV file (contains NUL bytes)");
  }

  auto nextLine = [&](std::string& line) {
    if (pos >= text.size()) return false;
    auto nl = text.find('\n', pos);
    if (nl == std::string::npos) nl = text.size();
    line.assign(text, pos, nl - pos);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    pos = nl + 1;
    return true;
  };

  std::string line;
  if (!nextLine(line) || line.find_first_not_of(" \t") == std::string::npos) {
    throw InputError(path + ":1: empty file (expected a header row: " +
                     (spec.required.empty() ? std::string("column names") : spec.required.front() + ",...") + ")");
  }
  std::vector<std::string> header = splitLine(line);
  // Which file column feeds which table column.
  std::vector<int> target(header.size(), -1);
  auto wanted = spec.required;
  wanted.insert(wanted.end(), spec.optional.begin(), spec.optional.end());
  for (std::size_t i = 0; i < header.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (header[j] == header[i]) {
        throw InputError(path + ":1: " + header[i] + ": column appears twice in the header");
      }
    }
  }
  for (const auto& name : wanted) {
    auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) {
      if (std::find(spec.required.begin(), spec.required.end(), name) != spec.required.end()) {
        throw InputError(path + ":1: " + name + ": required column is missing (got header '" +
                         line + "')");
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
  // Reserve from a cheap estimate of the row count, bounded by maxRows.
  std::size_t estimate = static_cast<std::size_t>(std::count(text.begin() + static_cast<long>(pos), text.end(), '\n')) + 1;
  if (estimate > spec.maxRows + 1) {
    throw InputError(path + ": too many rows (got about " + std::to_string(estimate) +
                     ", the limit is " + std::to_string(spec.maxRows) +
                     "; split the file or resample it)");
  }
  for (auto& c : table.columns) c.reserve(estimate);

  int lineNo = 1;
  while (nextLine(line)) {
    ++lineNo;
    if (line.find_first_not_of(" \t") == std::string::npos) continue;  // blank line
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
      auto& col = table.columns[static_cast<std::size_t>(target[i])];
      if (header[i] == spec.strictlyIncreasing && !col.empty() && !(v > col.back())) {
        throw InputError(path + ":" + std::to_string(lineNo) + ": " + header[i] +
                         ": must be strictly increasing (got " + s + " after " +
                         formatNumber(col.back()) + ")");
      }
      col.push_back(v);
    }
  }
  if (table.rows() < spec.minRows) {
    throw InputError(path + ": too few data rows (got " + std::to_string(table.rows()) +
                     ", need at least " + std::to_string(spec.minRows) + ")");
  }
  return table;
}

CsvTable readCsv(const std::string& path, const CsvSpec& spec) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open file");
  in.seekg(0, std::ios::end);
  auto size = static_cast<std::size_t>(in.tellg());
  // 40 bytes a row is generous for three numbers; refuse before reading it all.
  if (size > spec.maxRows * 200) {
    throw InputError(path + ": file too large (" + std::to_string(size / 1000000) +
                     " MB, at most " + std::to_string(spec.maxRows) + " rows are read)");
  }
  in.seekg(0);
  std::string text(size, '\0');
  in.read(&text[0], static_cast<std::streamsize>(size));
  return parseCsv(text, path, spec);
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
