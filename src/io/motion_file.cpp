#include "io/motion_file.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <tuple>
#include <unordered_set>

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/plausible_ranges.h"
#include "core/units.h"
#include "io/swing_record_csv.h"
#include "numerics/metrics.h"

namespace swingsim {

std::size_t MotionTable::index(const std::string& label) const {
  auto it = std::find(labels.begin(), labels.end(), label);
  if (it != labels.end()) return static_cast<std::size_t>(it - labels.begin());
  // Name what is there: OpenSim files have dozens of coordinates; list at most 60.
  constexpr std::size_t kMaxListed = 60;
  std::string available;
  for (std::size_t i = 0; i < labels.size() && i < kMaxListed; ++i) available += (i ? ", " : "") + labels[i];
  if (labels.size() > kMaxListed) available += ", ... (" + std::to_string(labels.size() - kMaxListed) + " more)";
  throw InputError(path + ":" + std::to_string(labelLine) + ": " + label +
                   ": column is missing (available: " + available + ")");
}

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

bool isBlank(const std::string& s) { return s.find_first_not_of(" \t") == std::string::npos; }

std::vector<std::string> splitWhitespace(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  for (char c : line) {
    if (c == ' ' || c == '\t') {
      if (!cell.empty()) cells.push_back(cell);
      cell.clear();
    } else {
      cell.push_back(c);
    }
  }
  if (!cell.empty()) cells.push_back(cell);
  return cells;
}

/// The lines of a text one at a time, without line ends (LF or CRLF) and without a leading
/// UTF-8 BOM; `number` is the 1-based line number of the last line taken.
class LineCursor {
 public:
  LineCursor(const std::string& text, const std::string& path) : text_(text) {
    if (text.find('\0') != std::string::npos) throw InputError(path + ": not a text motion file (contains NUL bytes)");
    if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) pos_ = 3;
  }
  bool next(std::string& line) {
    if (pos_ >= text_.size()) return false;
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string::npos) end = text_.size();
    line.assign(text_, pos_, end - pos_);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    pos_ = end + 1;
    ++number;
    return true;
  }
  int number = 0;

 private:
  const std::string& text_;
  std::size_t pos_ = 0;
};

/// A whole non-negative count from a header value, or nullopt.
std::optional<std::size_t> parseCount(const std::string& s) {
  if (s.empty() || s.size() > 12 || !std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); }))
    return std::nullopt;
  return static_cast<std::size_t>(std::stoull(s));
}

/// Header key=value found on `line` (0: absent).
struct HeaderValue {
  std::string value;
  int line = 0;
};

/// "path:line: ", the start of a message about one line.
std::string lineAt(const std::string& path, int line) { return path + ":" + std::to_string(line) + ": "; }

/// The Storage header's keys that we read, and the line of its `endheader`.
struct MotionHeader {
  HeaderValue version, nRows, nColumns, inDegrees;
  int endheader = 0;
  std::optional<std::size_t> expectedRows, expectedColumns;  ///< nRows and nColumns as counts
};

/// Reads the header: everything up to `endheader`; key=value lines kept, other lines (the
/// name) ignored. Throws InputError for a key given twice or a missing `endheader`.
MotionHeader readMotionHeader(LineCursor& lines, const std::string& path) {
  MotionHeader header;
  std::string line, firstLine;
  bool ended = false;
  while (lines.next(line)) {
    if (lines.number == 1) firstLine = line;
    if (trim(line) == "endheader") {
      ended = true;
      break;
    }
    const auto eq = line.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = trim(line.substr(0, eq));
    HeaderValue* slot = key == "version"     ? &header.version
                        : key == "nRows"     ? &header.nRows
                        : key == "nColumns"  ? &header.nColumns
                        : key == "inDegrees" ? &header.inDegrees
                                             : nullptr;
    if (slot == nullptr) continue;
    if (slot->line)
      throw InputError(lineAt(path, lines.number) + key + ": appears twice in the header (first on line " +
                       std::to_string(slot->line) + ")");
    *slot = {trim(line.substr(eq + 1)), lines.number};
  }
  if (!ended)
    throw InputError(path + ":1: expected an OpenSim Storage header ending in a line 'endheader' (got none in " +
                     std::to_string(lines.number) + " lines" +
                     (lines.number == 0 ? std::string() : "; the first is '" + firstLine.substr(0, 60) + "'") + ")");
  header.endheader = lines.number;
  return header;
}

/// Checks the header's values (version 1, inDegrees yes or no, whole counts), sets the
/// table's unit from inDegrees and the header's expected counts.
void checkMotionHeader(MotionHeader& header, MotionTable& table) {
  const std::string& path = table.path;
  const HeaderValue& version = header.version;
  const HeaderValue& inDegrees = header.inDegrees;
  if (version.line && version.value != "1")
    throw InputError(path + ":" + std::to_string(version.line) + ": version: expected 1 (Storage version 1) (got '" +
                     version.value + "')");
  if (inDegrees.line) {
    if (inDegrees.value != "yes" && inDegrees.value != "no")
      throw InputError(path + ":" + std::to_string(inDegrees.line) + ": inDegrees: expected yes or no (got '" +
                       inDegrees.value + "')");
    table.inDegrees = inDegrees.value == "yes";
    table.inDegreesLine = inDegrees.line;
  }
  for (auto [key, value, expected] : {std::tuple{"nRows", &header.nRows, &header.expectedRows},
                                      std::tuple{"nColumns", &header.nColumns, &header.expectedColumns}}) {
    if (!value->line) continue;
    *expected = parseCount(value->value);
    if (!*expected)
      throw InputError(path + ":" + std::to_string(value->line) + ": " + key + ": expected a whole number (got '" +
                       value->value + "')");
  }
}

/// Reads the column labels, the first non-blank line after endheader: 'time' first, each
/// once, as many as nColumns says.
void readColumnLabels(LineCursor& lines, const MotionHeader& header, MotionTable& table) {
  const std::string& path = table.path;
  std::string line;
  bool labelled = false;
  while (!labelled && lines.next(line)) labelled = !isBlank(line);
  if (!labelled)
    throw InputError(
        lineAt(path, header.endheader) +
        "expected a line of column labels after endheader, starting with 'time' (got the end of the file)");
  table.labelLine = lines.number;
  table.labels = splitWhitespace(line);
  if (table.labels.front() != "time")
    throw InputError(lineAt(path, lines.number) + "time: expected the first column label to be 'time' (got '" +
                     table.labels.front() + "')");
  // One pass with a hash set: a header of millions of labels is checked in linear time.
  std::unordered_set<std::string> seenLabels;
  for (const auto& label : table.labels)
    if (!seenLabels.insert(label).second)
      throw InputError(lineAt(path, lines.number) + label + ": column label appears twice");
  if (header.expectedColumns && *header.expectedColumns != table.labels.size())
    throw InputError(path + ":" + std::to_string(header.nColumns.line) + ": nColumns: the header says " +
                     header.nColumns.value + " columns, time included (got " + std::to_string(table.labels.size()) +
                     " labels on line " + std::to_string(table.labelLine) + ")");
}

/// One cell of a row as a finite number; a time (column 0) must also increase by at least
/// the smallest step and be plausible. `where` starts the messages ("path:line: ").
double parseCell(const MotionTable& table, std::size_t c, const std::string& s, const std::string& where) {
  const std::vector<double>& time = table.columns.front();
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size()) throw InputError(where + table.labels[c] + ": expected a number (got '" + s + "')");
  if (!std::isfinite(v)) throw InputError(where + table.labels[c] + ": expected a finite number (got '" + s + "')");
  if ((v != 0 || errno == ERANGE) && std::fabs(v) < kSmallestMagnitude)
    throw InputError(where + table.labels[c] + ": " + kTooSmallMessage + " (got '" + s + "')");
  if (c == 0 && !time.empty() && !(v > time.back()))
    throw InputError(where + "time: must strictly increase (got " + s + " after " + formatNumber(time.back()) + ")");
  if (c == 0 && !time.empty() && v - time.back() < kMinSampleStep)
    throw InputError(where + "time: expected steps of at least " + formatNumber(kMinSampleStep) + " s (got " + s +
                     " after " + formatNumber(time.back()) + ")");
  if (c == 0)
    if (const std::string bad = checkPlausible(v, kRecordTimeRange, "a sample time"); !bad.empty())
      throw InputError(where + table.labels[c] + ": " + bad + " (got " + s + ")");
  return v;
}

/// Appends the row of numbers on line `lineNumber` to the table: one value per label.
void readRow(const std::string& line, int lineNumber, MotionTable& table) {
  const std::string where = lineAt(table.path, lineNumber);
  if (table.rows() >= kMaxMotionRows)
    throw InputError(where + "too many rows (more than " + std::to_string(kMaxMotionRows) +
                     ", the limit; cut the trial or resample it)");
  const std::vector<std::string> cells = splitWhitespace(line);
  if (cells.size() != table.labels.size())
    throw InputError(where + "expected " + std::to_string(table.labels.size()) + " values, one per label on line " +
                     std::to_string(table.labelLine) + " (got " + std::to_string(cells.size()) + ")" +
                     (line.find(',') != std::string::npos
                          ? "; is the file comma-separated, or the decimal separator a comma?"
                          : ""));
  for (std::size_t c = 0; c < cells.size(); ++c) table.columns[c].push_back(parseCell(table, c, cells[c], where));
  table.rowLines.push_back(lineNumber);
}

/// Reads the rows of numbers to the end of the text: at least one, as many as nRows says.
void readRows(LineCursor& lines, const MotionHeader& header, MotionTable& table) {
  table.columns.assign(table.labels.size(), {});
  std::string line;
  while (lines.next(line))
    if (!isBlank(line)) readRow(line, lines.number, table);
  if (table.rows() == 0)
    throw InputError(table.path + ":" + std::to_string(table.labelLine) +
                     ": expected rows of numbers after the column labels (got none)");
  if (header.expectedRows && *header.expectedRows != table.rows())
    throw InputError(table.path + ":" + std::to_string(header.nRows.line) + ": nRows: the header says " +
                     header.nRows.value + " rows (got " + std::to_string(table.rows()) + " rows of numbers)");
}

/// Frames dropped by the capture system show as one long step among even ones.
void checkDroppedFrames(const MotionTable& table) {
  if (table.rows() < 3) return;
  const std::vector<double>& time = table.columns.front();
  std::vector<double> steps;
  for (std::size_t r = 1; r < time.size(); ++r) steps.push_back(time[r] - time[r - 1]);
  const double typical = calcMedian(steps);
  for (std::size_t r = 1; r < time.size(); ++r)
    if (steps[r - 1] > kMaxStepOverMedian * typical)
      throw InputError(table.path + ":" + std::to_string(table.rowLines[r]) + ": time: a gap of " +
                       formatNumber(steps[r - 1]) + " s after " + formatNumber(time[r - 1]) + " s (more than " +
                       formatNumber(kMaxStepOverMedian) + " times the median step of " + formatNumber(typical) +
                       " s; missing frames?)");
}

}  // namespace

MotionTable parseMotionTable(const std::string& text, const std::string& path) {
  MotionTable table;
  table.path = path;
  LineCursor lines(text, path);
  MotionHeader header = readMotionHeader(lines, path);
  checkMotionHeader(header, table);
  readColumnLabels(lines, header, table);
  readRows(lines, header, table);
  checkDroppedFrames(table);
  return table;
}

MotionTable readMotionTable(const std::string& path) { return parseMotionTable(readFile(path), path); }

namespace {

/// Linear interpolation of (times, values) at increasing `at`, each within the times' range.
std::vector<double> interpolate(const std::vector<double>& times, const std::vector<double>& values,
                                const std::vector<double>& at) {
  std::vector<double> out;
  out.reserve(at.size());
  std::size_t k = 0;
  for (double t : at) {
    while (k + 2 < times.size() && times[k + 1] <= t) ++k;
    // At a row's time, that row's value exactly.
    if (t == times[k + 1]) {
      out.push_back(values[k + 1]);
      continue;
    }
    const double w = (t - times[k]) / (times[k + 1] - times[k]);
    out.push_back(values[k] + w * (values[k + 1] - values[k]));
  }
  return out;
}

/// Times closer than this are one instant (well below any capture frame step), s.
constexpr double kSameTime = 1e-9;

/// Knee range limits for the unit check: a swing flexes the knee by some 60 deg (1 rad).
constexpr double kMinKneeRangeDeg = 3;
constexpr double kMaxKneeRangeRad = 6;

void checkKneeUnit(const MotionTable& table, const std::string& label, const std::vector<double>& knee,
                   const char* over = "the swing") {
  if (knee.empty()) return;
  const auto [lo, hi] = std::minmax_element(knee.begin(), knee.end());
  const double range = *hi - *lo;
  const std::string where =
      table.path + (table.inDegreesLine ? ":" + std::to_string(table.inDegreesLine) : "") + ": " + label + ": ";
  const std::string span =
      " (from " + formatNumber(*lo) + " to " + formatNumber(*hi) + "; a swing flexes it by tens of degrees)";
  if (table.inDegrees && range < kMinKneeRangeDeg)
    throw InputError(where + "the knee moves through only " + formatNumber(range) + " deg over " + over + span +
                     ": the column looks like radians, but the header says inDegrees=yes");
  if (!table.inDegrees && range > kMaxKneeRangeRad)
    throw InputError(
        where + "the knee moves through " + formatNumber(range) + " rad over " + over + span +
        ": the column looks like degrees, but " +
        (table.inDegreesLine
             ? std::string("the header says inDegrees=no")
             : std::string(
                   "the header has no inDegrees line, read as no (radians) as OpenSim does; add inDegrees=yes")));
}

}  // namespace

MotionColumns openSimLegColumns(const MotionTable& table, const std::string& side) {
  MotionColumns c;
  c.hip = "hip_flexion_" + side;
  c.knee = "knee_angle_" + side;
  c.kneeSign = -1;  // OpenSim's knee_angle is 0 straight and negative in flexion
  c.kneeMoment = c.knee + "_moment";
  const auto has = [&](const std::string& label) {
    return std::find(table.labels.begin(), table.labels.end(), label) != table.labels.end();
  };
  // A trajectory .sto from an older `swingsim simulate` (hip_flexion, knee_flexion: flexion
  // positive, docs/formats.md) reads as it did.
  if (!has(c.hip) && !has(c.knee) && has("hip_flexion") && has("knee_flexion")) {
    c.hip = "hip_flexion";
    c.knee = "knee_flexion";
    c.kneeSign = 1;
    c.kneeMoment = "knee_moment";
  }
  if (has("pelvis_tilt")) c.pelvisTilt = "pelvis_tilt";
  if (has("pelvis_tx")) c.pelvisTx = "pelvis_tx";
  if (has("pelvis_ty")) c.pelvisTy = "pelvis_ty";
  return c;
}

namespace {

/// The inverse-dynamics knee moment at file times `at` (N m, NaN outside the .sto's time).
std::vector<double> calcKneeMoment(const MotionTable& id, const MotionColumns& columns, const std::vector<double>& at) {
  const std::string label = columns.kneeMoment.empty() ? std::string(kOpenSimKneeMoment) : columns.kneeMoment;
  const std::vector<double>& idTime = id.columns.front();
  std::size_t column = 0;
  try {
    column = id.index(label);
  } catch (const InputError& e) {
    throw InputError(
        std::string(e.what()) +
        "; inverse_dynamics: expected the knee moment column that motion_columns: knee_moment names" +
        (columns.kneeMoment.empty() ? " (default " + std::string(kOpenSimKneeMoment) + ")" : std::string()));
  }
  const std::vector<double>& values = id.columns[column];
  std::vector<double> inside;
  for (double t : at)
    if (t >= idTime.front() && t <= idTime.back()) inside.push_back(t);
  if (inside.empty() || idTime.size() < 2)
    throw InputError(id.path + ": inverse_dynamics: expected times that overlap the swing, " +
                     formatNumber(at.front()) + " to " + formatNumber(at.back()) + " s (got " +
                     formatNumber(idTime.front()) + " to " + formatNumber(idTime.back()) + " s)");
  const std::vector<double> moment = interpolate(idTime, values, inside);
  std::vector<double> out;
  std::size_t k = 0;
  for (double t : at)
    // An OpenSim generalized force acts along its coordinate, so the knee's sign applies.
    out.push_back(t >= idTime.front() && t <= idTime.back() ? columns.kneeSign * moment[k++] : std::nan(""));
  return out;
}

}  // namespace

namespace {

// Every value of `label` within `range` (given in degrees for an angle column of a file in
// radians: converted before the check); throws InputError with the row's line.
void checkColumnPlausible(const MotionTable& table, const std::string& label, const PlausibleRange& range,
                          const std::string& what, double toRangeUnit) {
  const std::vector<double>& values = table.column(label);
  for (std::size_t r = 0; r < values.size(); ++r)
    if (const std::string bad = checkPlausible(values[r] * toRangeUnit, range, what); !bad.empty())
      throw InputError(table.path + ":" + std::to_string(r < table.rowLines.size() ? table.rowLines[r] : 0) + ": " +
                       label + ": " + bad + " (got " + formatNumber(values[r]) + (toRangeUnit == 1.0 ? "" : " rad") +
                       ")");
}

/// Refuses knee flexion that is hyperextended on (nearly) every sample: a flipped sign.
void checkKneeSign(const std::string& path, const std::string& label, const std::vector<double>& flexion,
                   double kneeSign, const char* over) {
  const auto low = std::count_if(flexion.begin(), flexion.end(), [](double v) { return v < kHyperextendedKnee; });
  if (flexion.empty() || static_cast<double>(low) < kHyperextendedShare * static_cast<double>(flexion.size())) return;
  const std::string fix = formatNumber(-kneeSign);
  throw InputError(
      path + ": " + label + ": expected knee flexion, positive when bent (got " + std::to_string(low) + " of " +
      std::to_string(flexion.size()) + " samples over " + over + " below " +
      formatNumber(kHyperextendedKnee * kRadToDeg) + " deg, hyperextended, read with knee_sign " +
      formatNumber(kneeSign) + "): the sign is flipped; set knee_sign: " + fix +
      " (motion_columns, thigh_kinematics) or --knee-sign " + fix +
      " (swingsim swings). OpenSim's gait models' knee_angle is negative in flexion, Rajagopal's positive");
}

}  // namespace

void requireNamedColumns(const MotionTable& table, const MotionColumns& columns, const std::string& askedBy) {
  const std::pair<const char*, const std::string*> named[] = {{"hip", &columns.hip},
                                                              {"knee", &columns.knee},
                                                              {"hip_moment", &columns.hipMoment},
                                                              {"pelvis_tilt", &columns.pelvisTilt},
                                                              {"pelvis_tx", &columns.pelvisTx},
                                                              {"pelvis_ty", &columns.pelvisTy}};
  for (const auto& [key, label] : named) {
    if (label->empty() || std::find(table.labels.begin(), table.labels.end(), *label) != table.labels.end()) continue;
    std::string available;
    for (const std::string& l : table.labels) available += (available.empty() ? "" : ", ") + l;
    throw InputError(askedBy + "." + key + ": expected a column of " + table.path + ":" +
                     std::to_string(table.labelLine) + " (got '" + *label +
                     "', which it does not have; available: " + available + ")");
  }
}

void checkLegKinematics(const MotionTable& table, const MotionColumns& columns) {
  if (table.rows() == 0) return;
  table.column(columns.hip);  // a missing label fails here first, naming those there are
  const std::vector<double>& knee = table.column(columns.knee);
  checkKneeUnit(table, columns.knee, knee, "the file");
  const double toDeg = table.inDegrees ? 1.0 : kRadToDeg;
  checkColumnPlausible(table, columns.hip, kJointAngleRange, "a hip angle", toDeg);
  checkColumnPlausible(table, columns.knee, kJointAngleRange, "a knee angle", toDeg);
  const double toRad = table.inDegrees ? kDegToRad : 1.0;
  std::vector<double> flexion;
  for (double v : knee) flexion.push_back(columns.kneeSign * v * toRad + columns.kneeOffset);
  checkKneeSign(table.path, columns.knee, flexion, columns.kneeSign, "the file");
}

SwingRecord makeSwingRecord(const MotionTable& table, const MotionColumns& columns,
                            const MotionTable* inverseDynamics) {
  const std::vector<double>& time = table.columns.front();

  if (time.size() < kMinSwingSamples)
    throw InputError(table.path + ": expected at least " + std::to_string(kMinSwingSamples) +
                     " rows for a swing (got " + std::to_string(time.size()) + ")");
  const std::vector<double>& hipValues = table.column(columns.hip);
  const std::vector<double>& kneeValues = table.column(columns.knee);
  const std::vector<double>* momentValues = columns.hipMoment.empty() ? nullptr : &table.column(columns.hipMoment);
  for (const std::string* label : {&columns.pelvisTilt, &columns.pelvisTx, &columns.pelvisTy})
    if (!label->empty()) table.index(*label);  // a missing label fails here, naming those there are
  const std::string range =
      "the file's time runs from " + formatSeconds(time.front()) + " to " + formatSeconds(time.back()) + " s";
  const double toeOff = columns.toeOffTime.value_or(time.front());
  const double heelContact = columns.heelContactTime.value_or(time.back());
  if (toeOff < time.front() || toeOff >= time.back())
    throw InputError(table.path + ": toe_off_s: expected a time within the file, before its last row; " + range +
                     " (got " + formatSeconds(toeOff) + " s)");
  if (heelContact <= toeOff || heelContact > time.back())
    throw InputError(table.path + ": heel_contact_s: expected a time after toe-off (" + formatSeconds(toeOff) +
                     " s) and within the file; " + range + " (got " + formatSeconds(heelContact) + " s)");

  // Sample times, in file time.
  std::vector<double> at;
  if (columns.resampleInterval) {
    const double dt = *columns.resampleInterval;
    if (!(dt > 0))
      throw InputError(table.path + ": resample_s: expected a positive interval (got " + formatNumber(dt) + ")");
    const double count = std::floor((heelContact - toeOff) / dt + kSameTime) + 1;
    if (count > static_cast<double>(kMaxMotionRows))
      throw InputError(table.path + ": resample_s: " + formatNumber(dt) + " s gives more than " +
                       std::to_string(kMaxMotionRows) + " samples over the swing (the limit)");
    for (std::size_t k = 0; k < static_cast<std::size_t>(count); ++k)
      at.push_back(std::min(toeOff + static_cast<double>(k) * dt, heelContact));
  } else {
    at.push_back(toeOff);
    for (double t : time)
      if (t > toeOff + kSameTime && t < heelContact - kSameTime) at.push_back(t);
    at.push_back(heelContact);
  }
  if (at.size() < kMinSwingSamples)
    throw InputError(table.path + ": expected at least " + std::to_string(kMinSwingSamples) +
                     " samples between toe-off (" + formatSeconds(toeOff) + " s) and heel contact (" +
                     formatSeconds(heelContact) + " s) (got " + std::to_string(at.size()) + ")");

  const std::vector<double> knee = interpolate(time, kneeValues, at);
  checkKneeUnit(table, columns.knee, knee);
  // After the unit check, whose message is the better one for degrees read as radians.
  const double toDeg = table.inDegrees ? 1.0 : kRadToDeg;
  checkColumnPlausible(table, columns.hip, kJointAngleRange, "a hip angle", toDeg);
  checkColumnPlausible(table, columns.knee, kJointAngleRange, "a knee angle", toDeg);
  if (!columns.hipMoment.empty())
    checkColumnPlausible(table, columns.hipMoment, kJointMomentRange, "a hip moment", 1.0);
  const std::vector<double> hip = interpolate(time, hipValues, at);
  const double toRad = table.inDegrees ? kDegToRad : 1.0;
  SwingRecord r;
  r.path = table.path;
  r.stem = fileStem(table.path);
  for (std::size_t k = 0; k < at.size(); ++k) {
    r.time.push_back(at[k] - toeOff);
    r.hipFlexion.push_back(columns.hipSign * hip[k] * toRad + columns.hipOffset);
    r.kneeFlexion.push_back(columns.kneeSign * knee[k] * toRad + columns.kneeOffset);
  }
  checkKneeSign(table.path, columns.knee, r.kneeFlexion, columns.kneeSign, "the swing");
  if (momentValues) r.hipMoment = interpolate(time, *momentValues, at);
  if (!columns.pelvisTilt.empty()) {
    // OpenSim's pelvis_tilt and hip_flexion both turn about +z (forward tilt and flexion
    // positive), so the thigh's angle in space is their sum.
    for (double v : interpolate(time, table.column(columns.pelvisTilt), at)) r.pelvisTilt.push_back(v * toRad);
    for (std::size_t k = 0; k < at.size(); ++k) r.hipFlexion[k] += r.pelvisTilt[k];
  }
  // Translations are in metres whatever inDegrees says.
  if (!columns.pelvisTx.empty()) r.pelvisX = interpolate(time, table.column(columns.pelvisTx), at);
  if (!columns.pelvisTy.empty()) r.pelvisY = interpolate(time, table.column(columns.pelvisTy), at);
  if (inverseDynamics) r.kneeMoment = calcKneeMoment(*inverseDynamics, columns, at);
  return r;
}

std::vector<std::string> checkMotionRecord(const SwingRecord& record, const MotionTable& table,
                                           const MotionColumns& columns) {
  std::vector<std::string> out;
  const auto low = std::count_if(record.kneeFlexion.begin(), record.kneeFlexion.end(),
                                 [](double v) { return v < kHyperextendedKnee; });
  if (2 * static_cast<std::size_t>(low) > record.kneeFlexion.size())
    out.push_back(std::to_string(low) + " of " + std::to_string(record.kneeFlexion.size()) + " knee samples of " +
                  table.path + " are below " + formatNumber(kHyperextendedKnee * kRadToDeg) +
                  " deg (hyperextended): is the knee's sign "
                  "flipped? OpenSim's knee_angle is negative in flexion: set motion_columns: knee_sign: -1");
  const bool hasTilt = std::find(table.labels.begin(), table.labels.end(), "pelvis_tilt") != table.labels.end();
  if (hasTilt && columns.pelvisTilt.empty())
    out.push_back("the hip angle " + columns.hip + " of " + table.path +
                  " is read without the pelvis tilt although the file has "
                  "a pelvis_tilt column, so the thigh's angle in space misses the tilt: set motion_columns: "
                  "pelvis_tilt: pelvis_tilt");
  return out;
}

bool isMotionFile(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".mot" || ext == ".sto";
}

SwingRecord readSwingRecordFile(const std::string& path, const std::optional<MotionColumns>& columns) {
  if (!isMotionFile(path)) return readSwingRecord(path);
  if (!columns)
    throw InputError(path +
                     ": a motion file (.mot/.sto) needs motion_columns naming its hip and knee columns (got none)");
  return makeSwingRecord(readMotionTable(path), *columns);
}

}  // namespace swingsim
