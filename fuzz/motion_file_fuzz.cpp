// libFuzzer target: the OpenSim motion file reader (.mot/.sto Storage v1) and the cut of a
// swing record from it, then the measured thigh drive's spline over the record's hip angle
// (issue 14: a motion file with time that does not increase, gaps, NaN, wrong units, or a
// thigh too short to prescribe). The first byte picks the column map: named columns with
// or without a hip moment, signs, offsets, a toe-off/heel-contact cut and resampling.
#include "fuzz_common.h"
#include "io/motion_file.h"
#include "leg/thigh_motion.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace swingsim;
  if (size == 0) return 0;
  MotionColumns columns;
  columns.hip = "hip_flexion_r";
  columns.knee = "knee_angle_r";
  if (data[0] & 0x01) columns.hipMoment = "hip_moment";
  if (data[0] & 0x02) columns.kneeSign = -1;
  if (data[0] & 0x04) columns.hipOffset = 0.1;
  if (data[0] & 0x08) columns.toeOffTime = 0.05;
  if (data[0] & 0x10) columns.heelContactTime = 0.4;
  if (data[0] & 0x20) columns.resampleInterval = 0.005;
  fuzz::expectOnlyInputErrors([&] {
    const MotionTable table = parseMotionTable(fuzz::asText(data + 1, size - 1), "fuzz.sto");
    const SwingRecord record = makeSwingRecord(table, columns);
    if (data[0] & 0x40) ThighMotion(ThighKinematics{"fuzz.sto", record.time, record.hipFlexion});
  });
  return 0;
}
