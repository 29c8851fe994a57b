#pragma once
// Swing events (toe-off, heel contact) found in a recording: from the vertical ground
// reaction force of an OpenSim GRF .mot where it covers the time, else from the kinematics
// (the rules are documented in docs/swing-events.md and in swing_events.cpp).
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

/// A stance or swing shorter than this is the force hovering around the threshold, not a
/// phase: its two crossings are dropped (walking's shortest phase, swing, lasts ~0.35 s), s.
constexpr double kMinGaitPhaseS = 0.05;
/// A kinematic event this close to a force event of the same kind is that event; inside the
/// force's time by more than this, the force alone decides (the kinematic rules land within
/// 0.05 s of the force's events on the OpenSim walks; half a swing is ~0.2 s), s.
constexpr double kEventMatchS = 0.15;

/// One swing found in a recording, in the file's own time, s.
struct FoundSwing {
  double toeOff = 0, heelContact = 0;
  /// Where each event came from: "grf" or "kinematics".
  std::string toeOffSource, heelContactSource;
  double duration() const { return heelContact - toeOff; }
};

/// The events of one kind of source, each list in time order, file time, s.
struct SwingEventTimes {
  std::vector<double> toeOffs, heelContacts;
};

/// The force's events over the whole GRF file: toe-off where the vertical force falls
/// below the threshold, heel contact where it rises above it, the time interpolated
/// linearly between rows; a phase shorter than kMinGaitPhaseS is dropped (hovering).
SwingEventTimes findGrfEvents(const MotionTable& grf, const GrfSettings& settings);
/// The kinematics' events (the rules in docs/swing-events.md): every toe-off and heel
/// contact whose swing peak and search span lie inside the file.
SwingEventTimes findKinematicEvents(const MotionTable& kinematics, const MotionColumns& columns);

/// Every complete swing (toe-off and heel contact both within the kinematics' time) of the
/// foot whose kinematics `columns` names (hip and knee labels, signs, offsets; the pelvis
/// tilt if named) in `kinematics`, in time order. Events come from `grf` (read from its
/// path) where its time covers them, from the kinematics elsewhere. Throws InputError
/// (file, key, what was expected, what was found) for a missing column, a GRF file without
/// the named column, a non-positive threshold or a GRF time that misses the kinematics'.
std::vector<FoundSwing> findSwings(const MotionTable& kinematics, const MotionColumns& columns,
                                   const std::optional<GrfSettings>& grf);
/// Same, with the GRF table already read (`settings.path` is not read again).
std::vector<FoundSwing> findSwings(const MotionTable& kinematics, const MotionColumns& columns,
                                   const MotionTable& grf, const GrfSettings& settings);

}  // namespace swingsim
