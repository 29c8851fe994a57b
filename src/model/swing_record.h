#pragma once
// One measured swing, in SI units and radians.
#include <string>
#include <vector>

namespace swingsim {

/// One measured swing (Swing kinematics CSV: time_s, hip_flexion_deg, knee_flexion_deg,
/// hip_moment_Nm). Time from toe-off (the first row is toe-off), s; angles rad; moment N m.
struct SwingRecord {
  std::string path, stem;
  std::vector<double> time, hipFlexion, kneeFlexion, hipMoment;
};

}  // namespace swingsim
