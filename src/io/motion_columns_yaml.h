#pragma once
// The `motion_columns:` keys (model/motion_columns.h), described once for every file that
// names the columns of an OpenSim .mot/.sto: a study's motion_columns map and a
// participant's thigh_kinematics map (io/yaml_archive.h for the pattern).
#include <cmath>
#include <optional>
#include <string>

#include "io/yaml_archive.h"
#include "model/motion_columns.h"

namespace swingsim {

/// An optional number that is written only when set (no default stands for "absent").
template <class A>
void optionalSeconds(A& a, const char* key, std::optional<double>& v, const ValueCheck& check) {
  bool present = v.has_value();
  if constexpr (A::kReading) present = a.has(key);
  if (!present) return;
  double x = v.value_or(0);
  a.optionalNumber(key, x, check);
  v = x;
}

/// `swing: K`: the K-th complete swing found in a .mot/.sto (a study's record, a participant's
/// thigh_kinematics).
inline std::string mustBeSwingNumber(double v) {
  return v >= 1 && v <= 1000 && v == std::floor(v) ? ""
                                                   : "expected a whole number from 1 (the first swing in the file)";
}

inline std::string mustBeSign(double v) { return v == 1 || v == -1 ? "" : "must be 1 or -1"; }
inline std::string mustBeOffset(double deg) { return deg >= -180 && deg <= 180 ? "" : "must be in [-180, 180] deg"; }

/// The motion_columns keys: which columns of a .mot/.sto file make a swing record.
template <class A>
void serialize(A& a, MotionColumns& c) {
  a.text("hip", c.hip);
  a.text("knee", c.knee);
  a.optionalText("hip_moment", c.hipMoment);
  a.optionalText("pelvis_tilt", c.pelvisTilt);
  a.optionalText("pelvis_tx", c.pelvisTx);
  a.optionalText("pelvis_ty", c.pelvisTy);
  a.optionalText("knee_moment", c.kneeMoment);
  a.optionalNumber("hip_sign", c.hipSign, mustBeSign);
  a.optionalNumber("knee_sign", c.kneeSign, mustBeSign);
  a.optionalAngle("hip_offset_deg", c.hipOffset, mustBeOffset);
  a.optionalAngle("knee_offset_deg", c.kneeOffset, mustBeOffset);
  optionalSeconds(a, "toe_off_s", c.toeOffTime, {});
  optionalSeconds(a, "heel_contact_s", c.heelContactTime, {});
  if (c.toeOffTime && c.heelContactTime)
    a.require(*c.heelContactTime > *c.toeOffTime, "heel_contact_s",
              "must be after toe_off_s (" + formatNumber(*c.toeOffTime) + " s)",
              [&] { return formatNumber(*c.heelContactTime); });
  // 10 us to 100 ms: a bench's 100 kHz at most, and a swing of 0.4 s still gets 5 samples.
  optionalSeconds(a, "resample_s", c.resampleInterval,
                  [](double v) { return v >= 1e-5 && v <= 0.1 ? "" : "must be in [1e-5, 0.1] s"; });
}

}  // namespace swingsim
