#include "io/sweep_times_csv.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "core/input_error.h"
#include "core/output_files.h"
#include "io/csv_table.h"

namespace swingsim {

namespace {

// Plausibility ranges (docs/formats.md): a knee axis cannot move half a metre; a swing of a
// prosthetic leg lasts 0.3-0.6 s (Burkett 2004 Tables 3-4), so 0.05-3 s only refuses
// nonsense (a time in ms, a missing-data marker); a trial SD is a fraction of the swing.
constexpr double kMaxLowering = 0.5;                       // m
constexpr double kMinSwingTime = 0.05, kMaxSwingTime = 3;  // s
constexpr double kMaxSd = 1;                               // s
constexpr int kMaxTrials = 1000;

CsvSpec sweepTimesSpec() {
  CsvSpec spec;
  spec.required = {"participant", "lowering_m", "swing_time_s"};
  spec.optional = {"sd_s", "n"};
  spec.text = {"participant"};
  spec.allowedHeaders = {spec.required, {"participant", "lowering_m", "swing_time_s", "sd_s", "n"}};
  spec.comments = true;
  spec.minRows = 0;  // checked below, naming the header's line
  return spec;
}

std::string at(const CsvTable& table, std::size_t row, const std::string& column) {
  return table.path + ":" + std::to_string(table.lines[row]) + ": " + column + ": ";
}

void checkRange(const std::string& where, double v, double lo, double hi, const std::string& why) {
  if (!(v >= lo && v <= hi))
    throw InputError(where + "expected " + formatNumber(lo) + " to " + formatNumber(hi) + " (" + why + ") (got " +
                     formatNumber(v) + ")");
}

// One row of the table, checked against the plausibility ranges.
MeasuredSwingTime readRow(const CsvTable& table, std::size_t row) {
  MeasuredSwingTime r;
  r.line = table.lines[row];
  r.participant = table.text("participant")[row];
  if (r.participant.empty())
    throw InputError(at(table, row, "participant") + "expected a participant name (got an empty field)");
  r.lowering = table.column("lowering_m")[row];
  checkRange(at(table, row, "lowering_m"), r.lowering, 0, kMaxLowering, "m below the standard knee-axis location");
  r.swingTime = table.column("swing_time_s")[row];
  checkRange(at(table, row, "swing_time_s"), r.swingTime, kMinSwingTime, kMaxSwingTime,
             "s; a swing time in ms would be refused here");
  const bool hasTrials = std::find(table.names.begin(), table.names.end(), "sd_s") != table.names.end();
  if (hasTrials) {
    r.sd = table.column("sd_s")[row];
    if (!(r.sd > 0 && r.sd <= kMaxSd))
      throw InputError(at(table, row, "sd_s") + "expected a trial-to-trial SD above 0 and at most 1 s (got " +
                       formatNumber(r.sd) + ")");
    const double n = table.column("n")[row];
    if (!(n >= 1 && n <= kMaxTrials && n == std::floor(n)))
      throw InputError(at(table, row, "n") + "expected a whole number of trials from 1 to 1000 (got " +
                       formatNumber(n) + ")");
    r.trials = static_cast<int>(n);
  }
  return r;
}

}  // namespace

std::vector<MeasuredSwingTime> parseSweepTimesCsv(const std::string& text, const std::string& path) {
  const CsvTable table = parseCsv(text, path, sweepTimesSpec());
  if (table.rows() == 0)
    throw InputError(path + ":" + std::to_string(table.headerLine) +
                     ": expected at least one row after the header (got none)");
  std::vector<MeasuredSwingTime> rows;
  // One mean per (participant, lowering to the micrometre): a map keeps the check n log n.
  std::map<std::pair<std::string, long long>, int> seen;
  for (std::size_t i = 0; i < table.rows(); ++i) {
    MeasuredSwingTime r = readRow(table, i);
    const auto [it, fresh] = seen.emplace(std::make_pair(r.participant, std::llround(r.lowering * 1e6)), r.line);
    if (!fresh)
      throw InputError(at(table, i, "lowering_m") + "participant " + r.participant + " already has a row at " +
                       formatNumber(r.lowering) + " m (line " + std::to_string(it->second) +
                       "); expected one mean per participant and lowering");
    rows.push_back(std::move(r));
  }
  return rows;
}

std::vector<MeasuredSwingTime> readSweepTimesCsv(const std::string& path) {
  return parseSweepTimesCsv(readFile(path), path);
}

}  // namespace swingsim
