#pragma once
// One measured swing, in SI units and radians.
#include <string>
#include <vector>

namespace swingsim {

/// One measured swing (Swing kinematics CSV: time_s, hip_flexion_deg, knee_flexion_deg,
/// optional hip_moment_Nm and knee_moment_Nm). Time from toe-off (the first row is
/// toe-off), s; angles rad; moments N m, + = flexion.
struct SwingRecord {
  std::string path, stem;
  std::vector<double> time, hipFlexion, kneeFlexion;
  std::vector<double> hipMoment;  ///< the measured drive; empty if not measured
  /// A knee moment measured independently (inverse dynamics), never fitted: compared with
  /// the model's after a diagnosis (HeldBackComparison). Empty if not given.
  std::vector<double> kneeMoment;
  /// The measured pelvis (OpenSim pelvis_tx, pelvis_ty, pelvis_tilt): translation in the
  /// ground frame, m (x forward, y up), tilt about +z, rad. When pelvisTilt is given,
  /// hipFlexion is the thigh's angle in space (hip flexion + pelvis tilt). Empty if not given.
  std::vector<double> pelvisX, pelvisY, pelvisTilt;
};

}  // namespace swingsim
