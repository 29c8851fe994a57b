#include "study/swing_kinematics_study.h"

#include <cmath>

#include "core/input_error.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "model/effect_table.h"
#include "io/yaml_archive.h"
#include "io/yaml_reader.h"

namespace swingsim {

// ---- The swing-kinematics study format, described once ------------------------------------

namespace {

struct CoulombOf {};
struct ViscousOf {};
struct AssistOf {};
struct ToeOffOf {};
struct HipScaleOf {};
struct ShankScaleOf {};
struct BelowKneeScaleOf {};

}  // namespace

template <class A>
void serialize(A& a, SwingHiddenEffects& h, CoulombOf) {
  a.optionalAngle("smoothing_deg_s", h.coulombSmoothingRate, mustBePositive);
  a.number("moment_Nm", h.coulombMoment, mustBeNonNegative);
}
template <class A>
void serialize(A& a, SwingHiddenEffects& h, ViscousOf) { a.number("damping_Nm_s_per_rad", h.viscousDamping, mustBeNonNegative); }
template <class A>
void serialize(A& a, SwingHiddenEffects& h, AssistOf) { a.number("stiffness_Nm_per_rad", h.assistStiffness, mustBeNonNegative); }
template <class A>
void serialize(A& a, SwingHiddenEffects& h, ToeOffOf) {
  a.angle("hip_rate_deg_s", h.toeOffHipRate, mustBePlausible(kJointRateRange, "a hip rate"));
  a.angle("knee_rate_deg_s", h.toeOffKneeRate, mustBePlausible(kJointRateRange, "a knee rate"));
}
template <class A>
void serialize(A& a, SwingHiddenEffects& h, HipScaleOf) { a.number("scale", h.hipScale, mustBePlausible(kAmplitudeScaleRange, "a scale")); }
template <class A>
void serialize(A& a, SwingHiddenEffects& h, ShankScaleOf) { a.number("scale", h.shankScale, mustBePlausible(kAmplitudeScaleRange, "a scale")); }
template <class A>
void serialize(A& a, SwingHiddenEffects& h, BelowKneeScaleOf) { a.number("scale", h.belowKneeScale, mustBePlausible(kAmplitudeScaleRange, "a scale")); }

template <class A>
void serialize(A& a, SwingHiddenEffects& h) {
  a.optionalMap("knee_coulomb_friction", h, h.kneeCoulombFriction, CoulombOf{});
  a.optionalMap("knee_viscous_damping", h, h.kneeViscousDamping, ViscousOf{});
  a.optionalMap("extension_assist_spring", h, h.extensionAssistSpring, AssistOf{});
  a.optionalMap("toe_off_velocity", h, h.toeOffVelocity, ToeOffOf{});
  a.optionalMap("hip_moment_scale", h, h.hipMomentScale, HipScaleOf{});
  a.optionalMap("shank_mass_scale", h, h.shankMassScale, ShankScaleOf{});
  a.optionalMap("below_knee_mass_scale", h, h.belowKneeMassScale, BelowKneeScaleOf{});
}

template <class A>
void serialize(A& a, SwingCondition& c) {
  a.text("name", c.name);
  a.optionalNumber("time_scale", c.timeScale, mustBePlausible(kTimeScaleRange, "a time scale"));
  a.optionalNumber("amplitude_scale", c.amplitudeScale, mustBePlausible(kAmplitudeScaleRange, "an amplitude scale"));
}

template <class A>
void serialize(A& a, SwingKinematicsStudy& s) {
  std::string kind = "swing-kinematics";
  a.choice("kind", kind, {{"swing-kinematics", std::string("swing-kinematics")}});
  // The reader loads each file as it is met (their errors come first).
  a.path("participant", s.participantPath);
  if constexpr (A::kReading) s.base.participant = loadParticipant(s.participantPath);
  a.path("model", s.modelPath);
  if constexpr (A::kReading) s.base.knee = loadKneeModel(s.modelPath);
  a.optionalText("name", s.name);
  a.optionalText("description", s.description);
  a.number("noise_deg", s.noiseDeg, mustBePlausible(kAngleNoiseRange, "an angle noise"));
  double seed = static_cast<double>(s.seed);
  a.optionalNumber("seed", seed, [](double v) {
    return v >= 0 && v < 9e15 && v == std::floor(v) ? "" : "must be a whole number >= 0";
  });
  s.seed = static_cast<std::uint64_t>(seed);
  a.optionalNumber("sample_interval_s", s.sampleInterval,
                   [](double v) { return v >= 1e-4 && v <= 0.02 ? "" : "must be in [0.0001, 0.02] s"; });
  a.path("output_dir", s.outputDir);
  a.mapList("conditions", s.conditions);
  a.require(!s.conditions.empty(), "conditions", "expected at least one condition",
            [] { return std::string("an empty list"); });
  a.optionalMap("hidden_effects", s.hidden, s.hasHiddenEffects);
}

SwingKinematicsStudy readSwingKinematicsStudy(YamlMap& yaml) {
  SwingKinematicsStudy s;
  s.path = yaml.path();
  YamlReadArchive a(yaml);
  serialize(a, s);
  yaml.finish();
  return s;
}

std::string formatSwingKinematicsStudyYaml(const SwingKinematicsStudy& study, const std::string& baseDir) {
  return writeYamlDocument(study, baseDir, "");
}

SwingModelParams makeHiddenTruth(const SwingHiddenEffects& h, std::vector<std::string>& names) {
  SwingModelParams truth;
  // One hidden effect: added to the truth at `grid`, then its values set.
  auto add = [&](bool present, const char* name, double grid) {
    if (present) {
      truth = addSwingEffect(truth, findEffect(PlantKind::kSwing, name)->id, grid);
      names.push_back(name);
    }
    return present;
  };
  auto& e = truth.effects;
  if (add(h.kneeCoulombFriction, "knee_coulomb_friction", h.coulombSmoothingRate)) e.knee.coulombMoment = h.coulombMoment;
  if (add(h.kneeViscousDamping, "knee_viscous_damping", 0)) e.knee.viscousDamping = h.viscousDamping;
  if (add(h.extensionAssistSpring, "extension_assist_spring", 0)) e.knee.assistStiffness = h.assistStiffness;
  if (add(h.toeOffVelocity, "toe_off_velocity", 0)) {
    e.toeOffHipRate = h.toeOffHipRate;
    e.toeOffKneeRate = h.toeOffKneeRate;
  }
  if (add(h.hipMomentScale, "hip_moment_scale", 0)) e.hipMomentScale = h.hipScale;
  if (add(h.shankMassScale, "shank_mass_scale", 0)) e.shankMassScale = h.shankScale;
  if (add(h.belowKneeMassScale, "below_knee_mass_scale", 0)) e.belowKneeMassScale = h.belowKneeScale;
  return truth;
}

}  // namespace swingsim
