#include "io/swing_record_csv.h"

#include <algorithm>

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/units.h"
#include "io/csv_table.h"

namespace swingsim {

namespace {

CsvSpec swingRecordSpec() {
  CsvSpec spec;
  spec.required = {"time_s", "hip_flexion_deg", "knee_flexion_deg"};
  spec.optional = {"hip_moment_Nm", "knee_moment_Nm"};
  spec.strictlyIncreasing = "time_s";
  spec.minRows = 10;
  spec.minStep = kMinSampleStep;
  spec.ranges = {{"time_s", kRecordTimeRange, "a sample time"},
                 {"hip_flexion_deg", kJointAngleRange, "a hip angle"},
                 {"knee_flexion_deg", kJointAngleRange, "a knee angle"},
                 {"hip_moment_Nm", kJointMomentRange, "a hip moment"},
                 {"knee_moment_Nm", kJointMomentRange, "a knee moment"}};
  return spec;
}

SwingRecord recordFromTable(const CsvTable& t, const std::string& path) {
  SwingRecord r;
  r.path = path;
  r.stem = fileStem(path);
  // A swing flexes the knee by some 60 deg; a whole record within a few "degrees" is one
  // written in radians (1.1 rad = 63 deg), which read as degrees would be a knee that
  // hardly moves.
  constexpr double kMinKneeRangeDeg = 3;
  const auto [kneeMin, kneeMax] =
      std::minmax_element(t.column("knee_flexion_deg").begin(), t.column("knee_flexion_deg").end());
  if (*kneeMax - *kneeMin < kMinKneeRangeDeg)
    throw InputError(path + ": knee_flexion_deg: the knee moves through only " + formatNumber(*kneeMax - *kneeMin) +
                     " deg over the whole record (from " + formatNumber(*kneeMin) + " to " + formatNumber(*kneeMax) +
                     "; a swing flexes it by tens of degrees): the column looks like radians, expected degrees");
  const auto& time = t.column("time_s");
  const double t0 = time.front();
  // One swing lasts well under 2 s; a record timed in ms spans hundreds of "seconds" and sent
  // a diagnosis integrating for minutes.
  constexpr double kMaxSwingRecordSpanS = 10;
  if (time.back() - t0 > kMaxSwingRecordSpanS)
    throw InputError(path + ": time_s: expected one swing in seconds, spanning at most " +
                     formatNumber(kMaxSwingRecordSpanS) + " s (got " + formatNumber(time.back() - t0) +
                     " s from the first sample to the last" + (time.back() - t0 < 1e4 ? ": in ms?" : "") + ")");
  for (double v : time) r.time.push_back(v - t0);
  for (double v : t.column("hip_flexion_deg")) r.hipFlexion.push_back(v * kDegToRad);
  for (double v : t.column("knee_flexion_deg")) r.kneeFlexion.push_back(v * kDegToRad);
  const auto has = [&](const char* name) { return std::find(t.names.begin(), t.names.end(), name) != t.names.end(); };
  if (has("hip_moment_Nm")) r.hipMoment = t.column("hip_moment_Nm");
  if (has("knee_moment_Nm")) r.kneeMoment = t.column("knee_moment_Nm");
  return r;
}

}  // namespace

SwingRecord readSwingRecord(const std::string& path) { return recordFromTable(readCsv(path, swingRecordSpec()), path); }

SwingRecord parseSwingRecordCsv(const std::string& text, const std::string& source) {
  return recordFromTable(parseCsv(text, source, swingRecordSpec()), source);
}

std::string formatSwingRecordCsv(const SwingRecord& r) {
  std::vector<double> hip, knee;
  for (double v : r.hipFlexion) hip.push_back(v * kRadToDeg);
  for (double v : r.kneeFlexion) knee.push_back(v * kRadToDeg);
  std::vector<std::string> names = {"time_s", "hip_flexion_deg", "knee_flexion_deg"};
  std::vector<std::vector<double>> columns = {r.time, hip, knee};
  if (!r.hipMoment.empty()) names.push_back("hip_moment_Nm"), columns.push_back(r.hipMoment);
  if (!r.kneeMoment.empty()) names.push_back("knee_moment_Nm"), columns.push_back(r.kneeMoment);
  return formatCsv(names, columns);
}

}  // namespace swingsim
