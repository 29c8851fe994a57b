// libFuzzer target: the CSV reader with each spec the program uses (bench data, Winter knee
// angles, swing kinematics), and the measured sweep times reader. The first byte picks the
// reader and a small row limit half the time, so the too-many-rows path is exercised too.
#include "fuzz_common.h"
#include "io/csv_table.h"
#include "io/sweep_times_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace swingsim;
  if (size == 0) return 0;
  if (data[0] % 4 == 3) {
    fuzz::expectOnlyInputErrors([&] { parseSweepTimesCsv(fuzz::asText(data + 1, size - 1), "fuzz.csv"); });
    return 0;
  }
  CsvSpec spec;
  switch (data[0] % 4) {
    case 0:
      spec.required = {"time_s", "position_m", "force_N"};
      spec.strictlyIncreasing = "time_s";
      spec.minRows = 3;
      spec.minStep = kMinSampleStep;  // as readBenchCsv
      spec.ranges = {{"time_s", kRecordTimeRange, "a sample time"}, {"force_N", kForceRange, "a force"}};
      break;
    case 1:
      spec.required = {"frame", "knee_deg"};
      spec.strictlyIncreasing = "frame";
      break;
    default:
      spec.required = {"time_s", "hip_flexion_deg", "knee_flexion_deg"};
      spec.optional = {"hip_moment_Nm", "knee_moment_Nm"};
      spec.strictlyIncreasing = "time_s";
      spec.minStep = kMinSampleStep;  // as readSwingRecord
      spec.ranges = {{"knee_flexion_deg", kJointAngleRange, "a knee angle"},
                     {"hip_moment_Nm", kJointMomentRange, "a hip moment"}};
      break;
  }
  if (data[0] & 0x80) spec.maxRows = 8;
  fuzz::expectOnlyInputErrors([&] {
    const CsvTable table = parseCsv(fuzz::asText(data + 1, size - 1), "fuzz.csv", spec);
    for (const auto& name : spec.required) table.column(name);
  });
  return 0;
}
