#pragma once
// Swing events (toe-off, heel contact) found in a recording: from the vertical ground
// reaction force of an OpenSim GRF .mot where it covers the time, else from the kinematics
// (the rule is documented in docs/measured-data.md and in swing_events.cpp).
#include <optional>
#include <string>
#include <vector>

#include "io/motion_file.h"

namespace swingsim {

/// How to read one foot's vertical force in an OpenSim GRF .mot (the study's `grf:` map).
struct GrfSettings {
  std::string path;                                 ///< resolved GRF .mot
  std::string verticalForce = "ground_force_vy";   ///< column label of this foot's vertical force, N
  double thresholdN = 20;                           ///< N: below it the foot is in the air
};

/// One swing found in a recording, in the file's own time, s.
struct FoundSwing {
  double toeOff = 0, heelContact = 0;
  /// Where each event came from: "grf" or "kinematics".
  std::string toeOffSource, heelContactSource;
  double duration() const { return heelContact - toeOff; }
};

/// Every complete swing of the foot whose kinematics `columns` names (hip and knee labels,
/// signs, offsets) in `kinematics`, in time order. Events come from `grf` where its time
/// covers them, from the kinematics elsewhere. Throws InputError (file, key, what was
/// expected, what was found) for a missing column or a GRF file without the named column.
std::vector<FoundSwing> findSwings(const MotionTable& kinematics, const MotionColumns& columns,
                                   const std::optional<GrfSettings>& grf);

}  // namespace swingsim
