#include "identify/swing_effects.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "core/units.h"
#include "identify/user_swing_effect.h"

namespace swingsim {

namespace {

std::string fmt(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// Bounds are physics, not data: a friction, damper or assist spring cannot push the wrong
// way (lower bound 0); scales of a gain or a mass stay positive and within 10x (log-scaled);
// toe-off rates within 20 rad/s (about 3x the peak swing knee rate). docs/diagnosis.md.
BoundedParameter linear(double lower, double upper, double typical) { return {"", 0.0, lower, upper, false, typical}; }
BoundedParameter logScaled(double lower, double upper) { return {"", 1.0, lower, upper, true, 1.0}; }

}  // namespace

// The records, in the effect table's order (the order of the fit's free parameters).
const std::vector<SwingEffectRecord>& swingEffectRecords() {
  using E = EffectId;
  using P = PlantKind;
  static const std::vector<SwingEffectRecord> table = {
      {{E::kKneeCoulombFriction,
        P::kSwing,
        "knee_coulomb_friction",
        "a friction moment of constant size that opposes knee motion over the whole range (not only below 4 deg like "
        "Tc)",
        "Burkett 2004 applies friction Tc only near extension; bearings and seals rub everywhere",
        "swings at several speeds (friction does not grow with knee speed)",
        {"moment_Nm", "smoothing_deg_s"},
        1,
        // tanh smoothing rate of the friction, rad/s (reported in deg/s). Bearing and seal
        // friction reverses within a few deg/s (an assumption: no knee's was measured; a
        // Stribeck speed of 1e-3..1e-2 m/s on a 1-2 cm bearing radius is 0.05-1 rad/s), so the
        // grid reaches 0.1 rad/s, where the swing's integration still follows it (the
        // calibration study in docs/diagnosis.md measured the cost); between grid values the
        // profile's best is refined (identify/candidate_score.cpp).
        {0.1, 0.2, 0.5, 1.0, 2.0, 5.0},
        kRadToDeg,
        false},
       {{linear(0.0, 50.0, 1.0), 1.0, [](SwingEffects& e) -> double& { return e.knee.coulombMoment; }}},
       [](SwingEffects& e) -> double& { return e.knee.coulombSmoothingRate; },
       "",
       [](const SwingEffects& e, std::string& note) {
         note = "friction must oppose knee motion (moment_Nm > 0): " + fmt(e.knee.coulombMoment) + " N m";
         return e.knee.coulombMoment > 0;
       }},
      {{E::kKneeViscousDamping,
        P::kSwing,
        "knee_viscous_damping",
        "extra knee damping proportional to knee speed (a stiffer hydraulic setting than the model's)",
        "swing-phase control knees resist in proportion to speed; the damping table is an assumption",
        "swings at several speeds (damping grows with knee speed)",
        {"damping_Nm_s_per_rad"},
        1,
        {},
        1.0,
        false},
       {{linear(0.0, 50.0, 0.5), 1.0, [](SwingEffects& e) -> double& { return e.knee.viscousDamping; }}},
       nullptr,
       "",
       [](const SwingEffects& e, std::string& note) {
         note = "a passive damper must resist knee motion (> 0): " + fmt(e.knee.viscousDamping) + " N m s/rad";
         return e.knee.viscousDamping > 0;
       }},
      {{E::kExtensionAssistSpring,
        P::kSwing,
        "extension_assist_spring",
        "a spring that pulls the knee towards extension, as many prosthetic knees have",
        "extension assist springs are a common prosthetic knee feature, absent from the model",
        "swings with different peak knee flexion (the spring grows with the angle)",
        {"stiffness_Nm_per_rad"},
        1,
        {},
        1.0,
        false},
       {{linear(0.0, 500.0, 5.0), 1.0, [](SwingEffects& e) -> double& { return e.knee.assistStiffness; }}},
       nullptr,
       "",
       [](const SwingEffects& e, std::string& note) {
         note = "the spring must pull towards extension (stiffness > 0): " + fmt(e.knee.assistStiffness) + " N m/rad";
         return e.knee.assistStiffness > 0;
       }},
      {{E::kToeOffVelocity,
        P::kSwing,
        "toe_off_velocity",
        "the hip and knee already move at toe-off: energy released by the prosthetic foot",
        "Burkett 2004 assumed zero velocities at toe-off and names the foot's energy as future work",
        "swings with different initial conditions, or a measured toe-off velocity",
        {"hip_rate_deg_s", "knee_rate_deg_s"},
        2,
        {},
        1.0,
        true},
       {{linear(-20.0, 20.0, 1.0), kRadToDeg, [](SwingEffects& e) -> double& { return e.toeOffHipRate; }},
        {linear(-20.0, 20.0, 1.0), kRadToDeg, [](SwingEffects& e) -> double& { return e.toeOffKneeRate; }}},
       nullptr,
       "the measured thigh drives the swing: its toe-off rate is measured and the knee's is fitted per record",
       [](const SwingEffects& e, std::string& note) {
         note = "energy released by the foot must flex the knee (knee rate > 0): " + fmt(e.toeOffKneeRate * kRadToDeg) +
                " deg/s";
         return e.toeOffKneeRate > 0;
       },
       [](const SwingEffects& e, Participant& p) {
         p.initial.hipFlexionRate = e.toeOffHipRate;
         p.initial.kneeFlexionRate = e.toeOffKneeRate;
       },
       nullptr,
       [](const SwingEffects& e, double& hipRate, double& kneeRate) {
         hipRate = e.toeOffHipRate;
         kneeRate = e.toeOffKneeRate;
       }},
      {{E::kHipMomentScale,
        P::kSwing,
        "hip_moment_scale",
        "the hip moment that really drives the swing is larger or smaller than the measured one (calibration)",
        "the hip moment comes from a dynamometer or inverse dynamics, both with gain errors",
        "a measured hip moment with independent calibration, or swings with different hip effort",
        {"scale"},
        1,
        {},
        1.0,
        true},
       {{logScaled(0.1, 10.0), 1.0, [](SwingEffects& e) -> double& { return e.hipMomentScale; }}},
       nullptr,
       "the measured thigh drives the swing: no hip moment to scale",
       [](const SwingEffects& e, std::string& note) {
         note = "a gain error cannot reverse the moment (scale > 0): " + fmt(e.hipMomentScale);
         return e.hipMomentScale > 0;
       },
       [](const SwingEffects& e, Participant& p) {
         p.hipMoment.flexionAmplitude *= e.hipMomentScale;
         p.hipMoment.extensionAmplitude *= e.hipMomentScale;
         for (double& m : p.hipMoment.moments) m *= e.hipMomentScale;
       },
       [](const SwingEffects& e, std::vector<double>& moments) {
         for (double& m : moments) m *= e.hipMomentScale;
       }},
      {{E::kShankMassScale,
        P::kSwing,
        "shank_mass_scale",
        "the shank is heavier or lighter than the model's (mass and inertia scaled together)",
        "segment masses come from a table (Burkett 2004 Table 2) and change with the prosthesis build",
        "weighing the shank, or swings with an added mass (Bach 1994)",
        {"scale"},
        1,
        {},
        1.0,
        true},
       {{logScaled(0.1, 10.0), 1.0, [](SwingEffects& e) -> double& { return e.shankMassScale; }}},
       nullptr,
       "",
       [](const SwingEffects& e, std::string& note) {
         note = "mass must stay positive (scale > 0): " + fmt(e.shankMassScale);
         return e.shankMassScale > 0;
       },
       [](const SwingEffects& e, Participant& p) {
         p.shank.mass *= e.shankMassScale;
         p.shank.inertia *= e.shankMassScale;
       }},
      {{E::kBelowKneeMassScale,
        P::kSwing,
        "below_knee_mass_scale",
        "everything below the knee (shank, foot, shoe) is heavier or lighter than the model's (masses and inertias "
        "scaled together)",
        "a prosthesis is weighed whole below the knee more often than by segment; the shoe is rarely in the table",
        "weighing the prosthesis below the knee with its shoe, or swings with an added mass (Bach 1994)",
        {"scale"},
        1,
        {},
        1.0,
        true},
       {{logScaled(0.1, 10.0), 1.0, [](SwingEffects& e) -> double& { return e.belowKneeMassScale; }}},
       nullptr,
       "",
       [](const SwingEffects& e, std::string& note) {
         note = "mass must stay positive (scale > 0): " + fmt(e.belowKneeMassScale);
         return e.belowKneeMassScale > 0;
       },
       [](const SwingEffects& e, Participant& p) {
         p.shank.mass *= e.belowKneeMassScale;
         p.shank.inertia *= e.belowKneeMassScale;
         p.foot.mass *= e.belowKneeMassScale;
         p.foot.inertia *= e.belowKneeMassScale;
       }},
      // A leg-level candidate: it adds the socket's two mobilities (docs/socket.md) to the
      // leg the refits integrate (the reference integrator's four-coordinate leg) and to the
      // Simbody check; its values are the socket rotation's spring and damper, started at
      // MyoSuite's (MyoHub/myo_sim@2cef885, socket_rotation_1). Bounds (an assumption; no
      // published range of sockets): springs 35x softer to 10x stiffer; dampers up to
      // MyoSuite's, which already holds P1's socket within 0.42 deg over a swing (below a
      // lab's noise: a more damped socket is the rigid leg), down to 350x less.
      {{E::kSocketCompliance,
        P::kSwing,
        "socket_compliance",
        "the socket gives on the residual limb: it turns (and pistons) on soft tissue, so the hip's drive reaches the "
        "prosthesis through a spring and a damper",
        "Burkett 2004's thigh is rigid from hip to knee; a residual limb in a socket is not (MyoSuite's transfemoral "
        "leg models its rotation and pistoning)",
        "the socket's angle measured against the femur (fluoroscopy), or swings with different hip effort",
        {"rotation_stiffness_Nm_per_rad", "rotation_damping_Nm_s_per_rad"},
        2,
        {},
        1.0,
        true},
       {{{"", 350.0, 10.0, 3500.0, true, 1.0},
         1.0,
         [](SwingEffects& e) -> double& { return e.socket.rotationStiffness; }},
        {{"", 175.0, 0.5, 175.0, true, 1.0}, 1.0, [](SwingEffects& e) -> double& { return e.socket.rotationDamping; }}},
       nullptr,
       "the measured thigh drives the swing: its markers sit on the socket, so the prescribed thigh already "
       "carries the socket's rotation",
       [](const SwingEffects& e, std::string& note) {
         note = "a socket's spring and damper must hold it on the limb (both > 0): " + fmt(e.socket.rotationStiffness) +
                " N m/rad, " + fmt(e.socket.rotationDamping) + " N m s/rad";
         return e.socket.rotationStiffness > 0 && e.socket.rotationDamping > 0;
       },
       [](const SwingEffects& e, Participant& p) {
         if (!p.socket) p.socket = e.socket;
         p.socket->rotationStiffness = e.socket.rotationStiffness;
         p.socket->rotationDamping = e.socket.rotationDamping;
       }},
  };
  return table;
}

const SwingEffectRecord& findSwingEffectRecord(EffectId effect) {
  for (const auto& r : swingEffectRecords())
    if (r.id() == effect) return r;
  if (const SwingEffectRecord* user = findUserSwingEffectRecord(effect)) return *user;
  throw std::invalid_argument("not a swing effect: " + describeEffect(effect).name);
}

std::vector<const SwingEffectRecord*> presentSwingEffectRecords(const SwingEffects& effects) {
  std::vector<const SwingEffectRecord*> out;
  for (const auto& r : swingEffectRecords())
    if (effects.has(r.id())) out.push_back(&r);
  for (EffectId id : effects.present)
    if (isUserEffect(id)) out.push_back(&findSwingEffectRecord(id));
  return out;
}

bool SwingEffects::has(EffectId effect) const {
  return std::find(present.begin(), present.end(), effect) != present.end();
}

void SwingEffects::setPresent(EffectId effect, bool on) {
  if (on && !has(effect)) present.push_back(effect);
  if (!on) present.erase(std::remove(present.begin(), present.end(), effect), present.end());
}

SwingEffects addSwingEffectTo(const SwingEffects& effects, EffectId effect, double gridValue) {
  const SwingEffectRecord& r = findSwingEffectRecord(effect);
  SwingEffects e = effects;
  e.setPresent(effect, true);
  if (r.setPresence) r.setPresence(e, true);
  for (const auto& slot : r.slots) slot.value(e) = slot.bounds.start;
  if (r.gridValue) r.gridValue(e) = gridValue;
  return e;
}

SwingEffects removeSwingEffect(const SwingEffects& effects, EffectId effect) {
  const SwingEffectRecord& r = findSwingEffectRecord(effect);
  SwingEffects e = effects;
  e.setPresent(effect, false);
  if (r.setPresence) {
    r.setPresence(e, false);
    return e;  // its values left with it
  }
  for (const auto& slot : r.slots) slot.value(e) = slot.bounds.start;
  return e;
}

SwingEffects copySwingEffect(const SwingEffects& effects, const SwingEffects& from, EffectId effect) {
  const SwingEffectRecord& r = findSwingEffectRecord(effect);
  SwingEffects e = effects;
  SwingEffects source = from;  // the accessors take a writable model
  e.setPresent(effect, true);
  if (r.setPresence) r.setPresence(e, true);
  for (const auto& slot : r.slots) slot.value(e) = slot.value(source);
  if (r.gridValue) r.gridValue(e) = r.gridValue(source);
  return e;
}

std::vector<double> swingEffectValues(const SwingEffects& effects, EffectId effect) {
  const SwingEffectRecord& r = findSwingEffectRecord(effect);
  SwingEffects e = effects;  // the accessors take a writable model
  std::vector<double> out;
  for (const auto& slot : r.slots) out.push_back(slot.value(e) * slot.reportScale);
  if (r.gridValue) out.push_back(r.gridValue(e) * describeEffect(effect).gridReportScale);
  return out;
}

Participant applyParticipantEffects(const Participant& participant, const SwingEffects& effects) {
  Participant p = participant;
  for (const auto& r : swingEffectRecords())
    if (r.applyToParticipant && effects.has(r.id())) r.applyToParticipant(effects, p);
  return p;
}

std::vector<double> applyHipDriveEffects(const SwingEffects& effects, std::vector<double> moments) {
  for (const auto& r : swingEffectRecords())
    if (r.applyToHipDrive && effects.has(r.id())) r.applyToHipDrive(effects, moments);
  return moments;
}

}  // namespace swingsim
