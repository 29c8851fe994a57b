#include "io/swing_record_csv.h"

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/units.h"
#include "io/csv_table.h"

namespace swingsim {

SwingRecord readSwingRecord(const std::string& path) {
  CsvSpec spec;
  spec.required = {"time_s", "hip_flexion_deg", "knee_flexion_deg", "hip_moment_Nm"};
  spec.strictlyIncreasing = "time_s";
  spec.minRows = 10;
  const CsvTable t = readCsv(path, spec);
  SwingRecord r;
  r.path = path;
  r.stem = fileStem(path);
  const auto& time = t.column("time_s");
  const double t0 = time.front();
  for (double v : time) r.time.push_back(v - t0);
  for (double v : t.column("hip_flexion_deg")) r.hipFlexion.push_back(v * kDegToRad);
  for (double v : t.column("knee_flexion_deg")) r.kneeFlexion.push_back(v * kDegToRad);
  r.hipMoment = t.column("hip_moment_Nm");
  return r;
}

std::string formatSwingRecordCsv(const SwingRecord& r) {
  std::vector<double> hip, knee;
  for (double v : r.hipFlexion) hip.push_back(v * kRadToDeg);
  for (double v : r.kneeFlexion) knee.push_back(v * kRadToDeg);
  return formatCsv({"time_s", "hip_flexion_deg", "knee_flexion_deg", "hip_moment_Nm"}, {r.time, hip, knee, r.hipMoment});
}

}  // namespace swingsim
