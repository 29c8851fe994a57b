#include "io/sweep_times_csv.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>
#include <utility>
#include <sstream>

#include "core/input_error.h"
#include "core/output_files.h"

namespace swingsim {

namespace {

// Plausibility ranges (docs/formats.md): a knee axis cannot move half a metre; a swing of a
// prosthetic leg lasts 0.3-0.6 s (Burkett 2004 Tables 3-4), so 0.05-3 s only refuses
// nonsense (a time in ms, a missing-data marker); a trial SD is a fraction of the swing.
constexpr double kMaxLowering = 0.5;                     // m
constexpr double kMinSwingTime = 0.05, kMaxSwingTime = 3;  // s
constexpr double kMaxSd = 1;                             // s
constexpr int kMaxTrials = 1000;

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) {
    const auto first = field.find_first_not_of(" \t");
    const auto last = field.find_last_not_of(" \t");
    std::string f = first == std::string::npos ? "" : field.substr(first, last - first + 1);
    // A spreadsheet's quoted field ("P1"): the quotes are not part of the value.
    if (f.size() >= 2 && f.front() == '"' && f.back() == '"') f = f.substr(1, f.size() - 2);
    out.push_back(f);
  }
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

struct Where {
  const std::string& path;
  int line;
  std::string at(const std::string& column) const { return path + ":" + std::to_string(line) + ": " + column + ": "; }
};

double parseNumber(const Where& w, const std::string& column, const std::string& text) {
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v))
    throw InputError(w.at(column) + "expected a finite number (got '" + text + "')");
  return v;
}

void checkRange(const Where& w, const std::string& column, double v, double lo, double hi, const std::string& why) {
  if (!(v >= lo && v <= hi))
    throw InputError(w.at(column) + "expected " + formatNumber(lo) + " to " + formatNumber(hi) + " (" + why + ") (got " +
                     formatNumber(v) + ")");
}

}  // namespace

std::vector<MeasuredSwingTime> parseSweepTimesCsv(const std::string& text, const std::string& path) {
  std::vector<std::string> lines;
  {
    std::string body = text.rfind("\xEF\xBB\xBF", 0) == 0 ? text.substr(3) : text;
    std::istringstream in(body);
    std::string l;
    while (std::getline(in, l)) {
      if (!l.empty() && l.back() == '\r') l.pop_back();
      if (l.find('\r') != std::string::npos)
        throw InputError(path + ":" + std::to_string(lines.size() + 1) +
                         ": CR-only line ends (a carriage return inside a line): save the file with LF or CRLF line ends");
      lines.push_back(l);
    }
  }
  std::vector<std::string> header;
  int headerLine = 0;
  std::vector<MeasuredSwingTime> rows;
  std::map<std::pair<std::string, long long>, int> seen;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& l = lines[i];
    const Where w{path, static_cast<int>(i + 1)};
    if (l.find_first_not_of(" \t") == std::string::npos || l[l.find_first_not_of(" \t")] == '#') continue;
    if (header.empty()) {
      header = splitFields(l);
      headerLine = w.line;
      const std::vector<std::string> plain{"participant", "lowering_m", "swing_time_s"};
      const std::vector<std::string> full{"participant", "lowering_m", "swing_time_s", "sd_s", "n"};
      if (header != plain && header != full)
        throw InputError(w.at("header") + "expected 'participant,lowering_m,swing_time_s' or "
                         "'participant,lowering_m,swing_time_s,sd_s,n' (got '" + (l.size() > 120 ? l.substr(0, 120) + "..." : l) + "')");
      continue;
    }
    const std::vector<std::string> f = splitFields(l);
    if (f.size() != header.size())
      throw InputError(w.at("row") + "expected " + std::to_string(header.size()) + " comma-separated fields (got " +
                       std::to_string(f.size()) + ")");
    MeasuredSwingTime r;
    r.line = w.line;
    r.participant = f[0];
    if (r.participant.empty()) throw InputError(w.at("participant") + "expected a participant name (got an empty field)");
    r.lowering = parseNumber(w, "lowering_m", f[1]);
    checkRange(w, "lowering_m", r.lowering, 0, kMaxLowering, "m below the standard knee-axis location");
    r.swingTime = parseNumber(w, "swing_time_s", f[2]);
    checkRange(w, "swing_time_s", r.swingTime, kMinSwingTime, kMaxSwingTime, "s; a swing time in ms would be refused here");
    if (f.size() == 5) {
      r.sd = parseNumber(w, "sd_s", f[3]);
      if (!(r.sd > 0 && r.sd <= kMaxSd))
        throw InputError(w.at("sd_s") + "expected a trial-to-trial SD above 0 and at most 1 s (got " + formatNumber(r.sd) + ")");
      const double n = parseNumber(w, "n", f[4]);
      if (!(n >= 1 && n <= kMaxTrials && n == std::floor(n)))
        throw InputError(w.at("n") + "expected a whole number of trials from 1 to 1000 (got " + f[4] + ")");
      r.trials = static_cast<int>(n);
    }
    // One mean per (participant, lowering to the micrometre): a set keeps the check linear.
    const auto [it, fresh] = seen.emplace(std::make_pair(r.participant, std::llround(r.lowering * 1e6)), r.line);
    if (!fresh)
      throw InputError(w.at("lowering_m") + "participant " + r.participant + " already has a row at " +
                       formatNumber(r.lowering) + " m (line " + std::to_string(it->second) +
                       "); expected one mean per participant and lowering");
    rows.push_back(r);
  }
  if (header.empty()) throw InputError(path + ": expected a header 'participant,lowering_m,swing_time_s[,sd_s,n]' (got an empty file)");
  if (rows.empty())
    throw InputError(path + ":" + std::to_string(headerLine) + ": expected at least one row after the header (got none)");
  return rows;
}

std::vector<MeasuredSwingTime> readSweepTimesCsv(const std::string& path) {
  return parseSweepTimesCsv(readFile(path), path);
}

}  // namespace swingsim
