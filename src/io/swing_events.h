#pragma once
// Swing events (toe-off, heel contact) found in a recording: from the vertical ground
// reaction force of an OpenSim GRF .mot where it covers the time, else from the kinematics
// by a rule per gait (walking, running). A force file is checked before its events are
// believed (rate, units and sign, clock) and its events against the leg's own kinematics;
// what does not hold is refused, or, where the user asks, left to the kinematics with that
// said. The rules and their measured accuracy are in docs/swing-events.md.
#include <optional>
#include <string>
#include <vector>

#include "io/motion_file.h"
#include "model/leg_parameters.h"

namespace swingsim {

/// "walking" or "running" (Gait: model/leg_parameters.h; the kinematic event rules differ,
/// docs/swing-events.md).
const char* gaitName(Gait gait);

/// How to read one foot's vertical force in an OpenSim GRF .mot (the study's `grf:` map).
struct GrfSettings {
  std::string path;                               ///< resolved GRF .mot
  std::string verticalForce = "ground_force_vy";  ///< column label of this foot's vertical force, N
  double thresholdN = 20;                         ///< N: below it the foot is in the air
  /// A force file that fails its checks gives way to the kinematics' events (said in the
  /// listing and the study's notes) instead of being refused (`fallback_to_kinematics`).
  bool fallbackToKinematics = false;
};

/// A stance or swing shorter than this is the force hovering around the threshold, not a
/// phase: its two crossings are dropped (walking's shortest phase, swing, lasts ~0.35 s), s.
constexpr double kMinGaitPhaseS = 0.05;
/// A force event and the kinematic event of its kind may differ by this much before the two
/// are taken to describe different steps, s. The kinematic rules land within 23 ms of the
/// force plates on the public walks and runs after their bias is removed (docs/swing-events.md:
/// worst 22 ms, 100 events); 50 ms is twice that and 3 frames at 60 Hz, while the other foot's
/// events lie a half stride (300-600 ms) away.
constexpr double kEventToleranceS = 0.050;
/// A stride shorter than this is running, longer walking: the public runs have 0.67-0.70 s,
/// the walks 1.22 s; fast walking stays above ~0.9 s, jogging below ~0.8 s, s.
constexpr double kRunningStrideS = 0.85;
/// With one swing in the file (no stride to measure): a swing peak of the knee above this is
/// running (public runs 102-112 deg, walks 69-70 deg), rad.
constexpr double kRunningKneePeak = 90 * kDegToRad;
/// A foot's vertical force in stance peaks at 1-3 body weights: a stance peak below this
/// (a 20 kg child's weight) is not a vertical force in newtons, N.
constexpr double kMinStancePeakN = 200;
/// ... and above this (3 body weights of a 300 kg person) neither, N.
constexpr double kMaxStancePeakN = 9000;

// Each kinematic rule's mean error against the force plates (kinematic minus force), s,
// removed from its events: measured on the public OpenSim trials (docs/swing-events.md,
// `SwingEvents.KinematicRulesAgainstTheForcePlatesPerGait`). Walking: one subject's walk seen
// through three IK pipelines (8 toe-offs, 9 heel contacts); running: two subjects (41
// toe-offs, 42 heel contacts), whose toe-off means (-3.0 and +3.9 ms) differ in sign, so that
// rule is left uncorrected.
constexpr double kWalkingToeOffBiasS = -0.0275;
constexpr double kWalkingHeelContactBiasS = -0.0248;
constexpr double kRunningToeOffBiasS = 0;
constexpr double kRunningHeelContactBiasS = -0.0076;
/// The worst disagreement with the force plates left after the correction, s (same trials).
constexpr double kWalkingAccuracyS = 0.006;
constexpr double kRunningAccuracyS = 0.022;

/// One swing found in a recording, in the file's own time, s.
struct FoundSwing {
  double toeOff = 0, heelContact = 0;
  /// Where each event came from: "grf" or "kinematics".
  std::string toeOffSource, heelContactSource;
  /// A force event minus the kinematic event of its kind, s; absent where the event is the
  /// kinematics' own or the kinematics see no event of its kind there.
  std::optional<double> toeOffDisagreement, heelContactDisagreement;
  double duration() const { return heelContact - toeOff; }
};

/// Every swing found, and how.
struct SwingList {
  std::vector<FoundSwing> swings;
  Gait gait = Gait::kWalking;
  /// How the gait was chosen: "stated", or what it was detected from.
  std::string gaitBasis;
  /// The kinematic rules' measured accuracy at this gait (worst force-plate disagreement
  /// after the bias correction), s, and whether it is more than 2 of the file's frames.
  double kinematicAccuracy = 0;
  bool kinematicAccuracyBeyondTwoFrames = false;
  /// Anything the user must know: a force file that fell back to the kinematics, and why.
  std::vector<std::string> notes;
  /// Set when the kinematics decide the first swing and the force plates might number the
  /// swings otherwise (a toe-off at the file's start): why. selectSwing then refuses `swing: K`.
  std::string numberingAmbiguity;
};

/// The events of one kind of source, each list in time order, file time, s.
struct SwingEventTimes {
  std::vector<double> toeOffs, heelContacts;
};

/// The force's events over the whole GRF file: toe-off where the vertical force falls
/// below the threshold, heel contact where it rises above it, the time interpolated
/// linearly between rows; a phase shorter than kMinGaitPhaseS is dropped (hovering).
SwingEventTimes findGrfEvents(const MotionTable& grf, const GrfSettings& settings);
/// The kinematics' events (the rules in docs/swing-events.md, bias-corrected) at `gait`,
/// detected when not given: every toe-off and heel contact whose swing peak and search span
/// lie inside the file.
SwingEventTimes findKinematicEvents(const MotionTable& kinematics, const MotionColumns& columns,
                                    std::optional<Gait> gait = std::nullopt);

/// Every complete swing (toe-off and heel contact both within the kinematics' time) of the
/// foot whose kinematics `columns` names (hip and knee labels, signs, offsets; the pelvis
/// tilt if named) in `kinematics`, in time order, at the stated `gait` or the one detected.
/// Events come from `grf` (read from its path) where its time covers them, from the
/// kinematics elsewhere. Throws InputError (file, key, what was expected, what was found)
/// for: a missing column; kinematics whose unit or knee sign is wrong (checkLegKinematics);
/// a GRF file without the named column, a non-positive threshold, a force sampled slower
/// than the kinematics, a force that is not a vertical force in newtons (stance peak outside
/// kMinStancePeakN..kMaxStancePeakN, or pulling below zero), a GRF time that misses the
/// kinematics', or force events that contradict the leg's kinematics (an event more than
/// kEventToleranceS from the kinematic one, a knee swing peak inside the force's stance):
/// the message says when the force matches the other leg instead. With
/// `fallbackToKinematics`, the last four give the kinematics' events and a note instead.
SwingList listSwings(const MotionTable& kinematics, const MotionColumns& columns, const std::optional<GrfSettings>& grf,
                     std::optional<Gait> gait = std::nullopt);
/// Same, with the GRF table already read (`settings.path` is not read again).
SwingList listSwings(const MotionTable& kinematics, const MotionColumns& columns, const MotionTable& grf,
                     const GrfSettings& settings, std::optional<Gait> gait = std::nullopt);
/// The K-th (1-based) of the swings listed from `table`, whose knee column is `knee`.
/// Throws InputError `file: swing: ...` naming the swings there are (times to 0.1 ms), or
/// that there is none and which rules found none.
FoundSwing selectSwing(const SwingList& list, const MotionTable& table, const std::string& knee, int k);

/// listSwings(...).swings.
std::vector<FoundSwing> findSwings(const MotionTable& kinematics, const MotionColumns& columns,
                                   const std::optional<GrfSettings>& grf);
std::vector<FoundSwing> findSwings(const MotionTable& kinematics, const MotionColumns& columns, const MotionTable& grf,
                                   const GrfSettings& settings);

}  // namespace swingsim
