#pragma once
// The swing model along one measured record, as the swing plant (identify/swing_plant.h)
// refits it: participant and knee model (SwingBase), the knee model's scale and the added
// effects (SwingModelParams, identify/swing_effects.h), and the reference swing from a
// toe-off pose driven by the record's hip moment or its measured thigh.
#include <optional>
#include <string>
#include <vector>

#include "identify/swing_effects.h"
#include "knee/knee_law.h"
#include "leg/hip_path.h"
#include "leg/thigh_motion.h"
#include "model/knee_model.h"
#include "model/leg_parameters.h"
#include "model/swing_record.h"

namespace swingsim {

/// The swing model: participant + knee model, with its free parameters.
struct SwingModelParams {
  /// The base model's free parameter: a scale on the knee model's resisting law (the
  /// damping table or cylinder; not the stop, not Tc). Burkett's damping table is an
  /// assumption, so a user rarely knows it; refitted with every candidate.
  double kneeModelScale = 1.0;
  SwingEffects effects;
};

/// Everything fixed: the participant (geometry, Tc, hip range, zone of stability) and the
/// knee model.
struct SwingBase {
  Participant participant;
  KneeModel knee;
  /// kHipMoment: each record's measured hip moment drives the leg (the record must have
  /// one). kThighKinematics: each record's measured hip angle is prescribed on the hip
  /// (measured thigh drive); the hip then fits exactly, so the likelihood uses the knee only, and
  /// each record's free toe-off state is the knee's angle and rate (the hip's come from
  /// the measured thigh).
  SwingDrive drive = SwingDrive::kHipMoment;
  /// Warnings about the records found while reading them (a flipped knee sign, a pelvis
  /// tilt left unread), each naming the key that fixes it: the plant's warnings().
  std::vector<std::string> notes;
  /// Thigh drive: a record with the measured pelvis moves the hip along it (the participant's
  /// hip_offset_in_pelvis_m places the hip in the pelvis); false pins the hip in space.
  bool movingHip = true;
};

/// `params` with `effect` switched on (value 0 or scale 1; `gridValue`: the friction
/// smoothing, rad/s).
SwingModelParams addSwingEffect(const SwingModelParams& params, EffectId effect, double gridValue);

/// Knee law of the model: scaled model law + added effects + stop + participant Tc.
KneeLawSum makeSwingKneeLaw(const SwingBase& base, const SwingModelParams& params);

/// Model hip and knee flexion (rad) at the record's times (with a compliant socket the hip's
/// is the socket's angle, where a lab's thigh markers are) from toe-off pose `hipPose`,
/// `kneePose` (rad), driven by the record's hip moment, or with base.drive ==
/// kThighKinematics by its hip angle (`thigh`: that angle's spline, made from the record if
/// null; `hipPose` is then the knee's toe-off rate, rad/s). `tolerance`: the reference
/// integrator's relative and absolute tolerance. Throws RunError if the integration fails.
struct SwingPrediction {
  std::vector<double> hipFlexion, kneeFlexion, kneeFlexionRate;
  std::vector<double> hipMoment,
      kneeMoment;  ///< N m, + = flexion: the drive's (or the one the thigh needs) and the knee law's
};
SwingPrediction predictSwing(const SwingBase& base, const SwingModelParams& params, const SwingRecord& record,
                             double hipPose, double kneePose, double tolerance = 1e-8,
                             const ThighMotion* thigh = nullptr, const HipPath* hip = nullptr);

/// Phases from the swing events of the model's knee: early flexion (toe-off to peak knee
/// flexion), late extension (peak to entering the zone of stability), terminal/stop contact.
std::vector<std::string> swingPhaseNames();

/// Knee flexion RMS (deg) of `effect` in `truth` along a record: truth minus truth without
/// it, same pose. The "effect size" of a hidden effect.
double calcSwingEffectRms(const SwingBase& base, const SwingModelParams& truth, EffectId effect,
                          const SwingRecord& record);

/// The measured thigh of a record, as the thigh drive prescribes it; with `movingHip`, the
/// measured pelvis too (the hip then follows it).
ThighKinematics thighKinematicsOf(const SwingRecord& record, bool movingHip);
/// The hip path of a record's thigh under the thigh drive; nullopt: the hip is fixed.
std::optional<HipPath> hipPathOf(const SwingBase& base, const ThighKinematics& thigh);

}  // namespace swingsim
