#pragma once
// Which columns of an OpenSim motion file make a swing record, and how: the study's
// `motion_columns:` map and a participant's `thigh_kinematics:` map (read in io/).
#include <optional>
#include <string>

namespace swingsim {

/// Which columns of a motion file make a swing record, and how (the study's
/// `motion_columns:` map). Clinical flexion = sign * value + offset, value in the file's unit.
struct MotionColumns {
  std::string hip, knee;  ///< hip and knee flexion angle labels (required)
  std::string hipMoment;  ///< hip flexion moment label, N m ("" = not read)
  /// Pelvis labels ("" = not read): tilt (angle, the file's unit; added to the hip angle to
  /// give the thigh's angle in space) and translations (m, whatever inDegrees says).
  std::string pelvisTilt, pelvisTx, pelvisTy;
  std::string kneeMoment;                  ///< knee moment label in an inverse-dynamics .sto ("" = not read)
  double hipSign = 1, kneeSign = 1;        ///< +1 or -1
  double hipOffset = 0, kneeOffset = 0;    ///< rad (degrees in the file: *_offset_deg)
  std::optional<double> toeOffTime;        ///< s, file time; default the first row
  std::optional<double> heelContactTime;   ///< s, file time; default the last row
  std::optional<double> resampleInterval;  ///< s; linear interpolation; default: the file's rows
};

}  // namespace swingsim
