#include "identify/swing_model.h"

#include <cmath>
#include <stdexcept>

#include "core/input_error.h"
#include "core/units.h"
#include "swing/knee_setup.h"
#include "swing/reference_swing.h"

namespace swingsim {

ThighKinematics thighKinematicsOf(const SwingRecord& r, bool movingHip) {
  ThighKinematics t;
  t.path = r.path;
  t.time = r.time;
  t.hipFlexion = r.hipFlexion;
  if (movingHip) {
    t.pelvisX = r.pelvisX;
    t.pelvisY = r.pelvisY;
    t.pelvisTilt = r.pelvisTilt;
  }
  return t;
}

std::optional<HipPath> hipPathOf(const SwingBase& base, const ThighKinematics& thigh) {
  if (base.drive != SwingDrive::kThighKinematics || !HipPath::hasPelvis(thigh)) return std::nullopt;
  return HipPath(thigh, base.participant.hipOffsetInPelvis, base.participant.path);
}

SwingModelParams addSwingEffect(const SwingModelParams& params, EffectId effect, double gridValue) {
  SwingModelParams p = params;
  p.effects = addSwingEffectTo(params.effects, effect, gridValue);
  return p;
}

KneeLawSum makeSwingKneeLaw(const SwingBase& base, const SwingModelParams& params) {
  // The model's law: its resisting parts scaled, then added effects, its stop, then Tc.
  const KneeLawSum& model = base.knee.law;
  KneeLawSum law;
  for (std::size_t i = 0; i + 1 < model.size(); ++i)
    law.add(std::make_unique<ScaledKneeLaw>(model.part(i), params.kneeModelScale));
  if (params.effects.knee.any()) law.add(std::make_unique<KneeAddedEffects>(params.effects.knee));
  addKneeExpressionLaws(law, params.effects.knee);
  if (model.size() > 0) law.add(model.part(model.size() - 1).clone());
  KneeModel stopless;  // makeKneeLaw adds the participant's Tc
  stopless.law = law;
  return makeKneeLaw(base.participant, stopless);
}

SwingPrediction predictSwing(const SwingBase& base, const SwingModelParams& params, const SwingRecord& record,
                             double hipPose, double kneePose, double tolerance, const ThighMotion* thigh,
                             const HipPath* hip) {
  const auto& e = params.effects;
  const Participant participant = applyParticipantEffects(base.participant, e);
  const LegGeometry geometry = calcLegGeometry(participant, 0.0);
  const KneeLawSum law = makeSwingKneeLaw(base, params);
  InitialConditions initial;
  std::optional<ReferenceSwing> swing;
  std::optional<ThighMotion> ownThigh;
  std::optional<HipPath> ownHip;
  if (base.drive == SwingDrive::kThighKinematics) {
    if (thigh == nullptr) {
      const ThighKinematics kinematics = thighKinematicsOf(record, base.movingHip);
      thigh = &ownThigh.emplace(kinematics);
      ownHip = hipPathOf(base, kinematics);
      if (ownHip) hip = &*ownHip;
    }
    initial.kneeFlexion = kneePose;
    initial.kneeFlexionRate = hipPose;  // the knee's toe-off rate (the hip's is the thigh's)
    if (hip != nullptr)
      swing.emplace(geometry, law, *thigh, *hip);
    else
      swing.emplace(geometry, law, *thigh);
  } else {
    HipMomentProfile drive;
    drive.kind = HipMomentProfile::Kind::kTable;
    drive.times = record.time;
    drive.moments = applyHipDriveEffects(e, record.hipMoment);
    initial.hipFlexion = hipPose;
    initial.kneeFlexion = kneePose;
    initial.hipFlexionRate = 0.0;
    initial.kneeFlexionRate = 0.0;
    for (const auto& r : swingEffectRecords())
      if (r.applyToToeOff && e.has(r.id())) r.applyToToeOff(e, initial.hipFlexionRate, initial.kneeFlexionRate);
    swing.emplace(geometry, law, drive, participant.hipRange);
  }
  ReferenceTrajectory tr;
  try {
    tr = swing->integrate(initial, record.time, tolerance, tolerance);
  } catch (const std::runtime_error& ex) {
    throw RunError(std::string("swing model along ") + record.stem + ": " + ex.what());
  }
  // With a compliant socket a lab's thigh is the socket's: its markers sit on it, not on the
  // residual limb inside (docs/socket.md). The knee is the knee's own, socket to shank.
  std::vector<double> labThigh = tr.hipFlexion;
  for (std::size_t i = 0; i < tr.socket.size(); ++i) labThigh[i] = tr.socket[i].calcSocketAngle(tr.hipFlexion[i]);
  return {labThigh, tr.kneeFlexion, tr.kneeFlexionRate, tr.hipMoment, tr.kneeMoment};
}

std::vector<std::string> swingPhaseNames() { return {"early flexion", "late extension", "terminal/stop contact"}; }

double calcSwingEffectRms(const SwingBase& base, const SwingModelParams& truth, EffectId effect,
                          const SwingRecord& record) {
  SwingModelParams without = truth;
  without.effects = removeSwingEffect(truth.effects, effect);
  const auto& init = base.participant.initial;
  const double first = base.drive == SwingDrive::kThighKinematics ? init.kneeFlexionRate : init.hipFlexion;
  const auto a = predictSwing(base, truth, record, first, init.kneeFlexion);
  const auto b = predictSwing(base, without, record, first, init.kneeFlexion);
  double s = 0;
  for (std::size_t i = 0; i < a.kneeFlexion.size(); ++i)
    s += std::pow((a.kneeFlexion[i] - b.kneeFlexion[i]) * kRadToDeg, 2);
  return std::sqrt(s / static_cast<double>(a.kneeFlexion.size()));
}

}  // namespace swingsim
