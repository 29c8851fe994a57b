#include "model/effect_table.h"

#include <deque>
#include <mutex>
#include <stdexcept>

#include "core/units.h"

namespace swingsim {

const std::vector<EffectDescriptor>& effectTable() {
  using P = PlantKind;
  static const std::vector<EffectDescriptor> table = {
      // ---- Cylinder bench --------------------------------------------------------------
      {EffectId::kCoulombFriction, P::kCylinder, "coulomb_friction",
       "a seal friction force of constant size that always opposes the piston's motion",
       "Chien 2014 tried a Coulomb term opposing motion (it made their fit worse)",
       "records at several speeds (its size does not grow with speed)",
       {"force_N", "width_m_per_s"}, 1,
       // tanh width Fc tanh(xd / w), m/s
       {0.002, 0.005, 0.01, 0.02, 0.05}, 1.0, false},
      {EffectId::kOrificeQuadratic, P::kCylinder, "orifice_quadratic",
       "extra resistance growing with the square of piston speed: turbulent flow through the orifices",
       "Chien 2014: slow gait fits worst, likely non-linear flow through cylinder, orifices and valve",
       "records at clearly different speeds (slow and fast walking)",
       {"coefficient_Ns2_per_m2"}, 1, {}, 1.0, false},
      {EffectId::kInertia, P::kCylinder, "inertia",
       "a force proportional to piston acceleration: the moving mass of piston, rod and oil",
       "Chien 2014 tried an acceleration term (it did not help on their data)",
       "records with different frequency content (another cadence or a sine sweep)",
       {"mass_kg"}, 1, {}, 1.0, false},
      {EffectId::kPositionDependentDamping, P::kCylinder, "position_dependent_damping",
       "damping that changes along the stroke (metering grooves, valve opening with position)",
       "Chien 2014's phases have constant damping; the valve geometry varies along the stroke",
       "records with different knee-angle amplitudes",
       {"coefficient_Ns_per_m2"}, 1, {}, 1.0, false},
      {EffectId::kHyperextensionPhase, P::kCylinder, "hyperextension_phase",
       "a separate force law while the piston is hyperextended (Chien's 4th phase)",
       "Chien 2014 Eq. 11: the 4-phase model adds hyperextension to the 2-phase model",
       "records with longer or deeper hyperextension",
       {"f_N", "k_N_per_m", "c_Ns_per_m"}, 3, {}, 1.0, false},
      {EffectId::kSwitchDelay, P::kCylinder, "switch_delay",
       "the valve latch (balance wheel) needs time to turn: swing flexion starts partly with stance resistance",
       "Chien 2014 discussion: the balance-wheel release timing (about 0.1 s) is not reproduced by fast switches",
       "records with longer hyperextension holds (a slow latch completes given time)",
       {"time_constant_s"}, 0,
       // latch time constant 1/k, s (Chien 2014: the balance-wheel delay is "about 0.1 s")
       {0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1}, 1.0, false},
      // ---- Swing -------------------------------------------------------------------------
      {EffectId::kKneeCoulombFriction, P::kSwing, "knee_coulomb_friction",
       "a friction moment of constant size that opposes knee motion over the whole range (not only below 4 deg like Tc)",
       "Burkett 2004 applies friction Tc only near extension; bearings and seals rub everywhere",
       "swings at several speeds (friction does not grow with knee speed)",
       {"moment_Nm", "smoothing_deg_s"}, 1,
       // tanh smoothing rate of the friction, rad/s (reported in deg/s). Bearing and seal
       // friction reverses within a few deg/s (an assumption: no knee's was measured; a
       // Stribeck speed of 1e-3..1e-2 m/s on a 1-2 cm bearing radius is 0.05-1 rad/s), so the
       // grid reaches 0.1 rad/s, where the swing's integration still follows it (the
       // calibration study in docs/diagnosis.md measured the cost); between grid values the
       // profile's best is refined (identify/candidate_score.cpp).
       {0.1, 0.2, 0.5, 1.0, 2.0, 5.0}, kRadToDeg, false},
      {EffectId::kKneeViscousDamping, P::kSwing, "knee_viscous_damping",
       "extra knee damping proportional to knee speed (a stiffer hydraulic setting than the model's)",
       "swing-phase control knees resist in proportion to speed; the damping table is an assumption",
       "swings at several speeds (damping grows with knee speed)",
       {"damping_Nm_s_per_rad"}, 1, {}, 1.0, false},
      {EffectId::kExtensionAssistSpring, P::kSwing, "extension_assist_spring",
       "a spring that pulls the knee towards extension, as many prosthetic knees have",
       "extension assist springs are a common prosthetic knee feature, absent from the model",
       "swings with different peak knee flexion (the spring grows with the angle)",
       {"stiffness_Nm_per_rad"}, 1, {}, 1.0, false},
      {EffectId::kToeOffVelocity, P::kSwing, "toe_off_velocity",
       "the hip and knee already move at toe-off: energy released by the prosthetic foot",
       "Burkett 2004 assumed zero velocities at toe-off and names the foot's energy as future work",
       "swings with different initial conditions, or a measured toe-off velocity",
       {"hip_rate_deg_s", "knee_rate_deg_s"}, 2, {}, 1.0, true},
      {EffectId::kHipMomentScale, P::kSwing, "hip_moment_scale",
       "the hip moment that really drives the swing is larger or smaller than the measured one (calibration)",
       "the hip moment comes from a dynamometer or inverse dynamics, both with gain errors",
       "a measured hip moment with independent calibration, or swings with different hip effort",
       {"scale"}, 1, {}, 1.0, true},
      {EffectId::kShankMassScale, P::kSwing, "shank_mass_scale",
       "the shank is heavier or lighter than the model's (mass and inertia scaled together)",
       "segment masses come from a table (Burkett 2004 Table 2) and change with the prosthesis build",
       "weighing the shank, or swings with an added mass (Bach 1994)",
       {"scale"}, 1, {}, 1.0, true},
      {EffectId::kBelowKneeMassScale, P::kSwing, "below_knee_mass_scale",
       "everything below the knee (shank, foot, shoe) is heavier or lighter than the model's (masses and inertias scaled together)",
       "a prosthesis is weighed whole below the knee more often than by segment; the shoe is rarely in the table",
       "weighing the prosthesis below the knee with its shoe, or swings with an added mass (Bach 1994)",
       {"scale"}, 1, {}, 1.0, true},
      // ---- Sweep: one value shared by every participant, so a held-out participant is
      // predicted from the others (identify/sweep_effects.cpp holds the laws and ranges) ------
      {EffectId::kHipEffortAdaptation, P::kSweep, "hip_effort_adaptation",
       "the hip moment changes with the knee-axis lowering in proportion to (I_knee(d) / I_knee(0))^a, "
       "I_knee the shank + foot inertia about the knee (a < 0: more effort on the lighter-feeling lowered shank)",
       "Hale 1990 (Prosthet Orthot Int 14:125): amputees raised hip effort 37-71 % for a heavier shank; either sign",
       "the hip moment measured at each lowering (dynamometer or inverse dynamics)",
       {"exponent"}, 1, {}, 1.0, false},
      {EffectId::kHipTempoLowering, P::kSweep, "hip_tempo_lowering",
       "the hip drive's timing changes with the lowering: time scale x (1 + c d / 0.1 m)",
       "Burkett, Smeathers & Barker 2001 (Prosthet Orthot Int 25:210): running speed rose 26 % on the lowered knee; "
       "a faster cadence shortens the hip drive (c < 0)",
       "the stride time or cadence measured at each lowering",
       {"change_per_100mm"}, 1, {}, 1.0, false},
      {EffectId::kComRuleProportional, P::kSweep, "com_rule_proportional",
       "the segment COMs move in proportion to the new lengths when the knee is lowered (the other reading of Burkett)",
       "Burkett 2004's sentence on the COMs allows both readings (docs/assumptions.md, COM rule)",
       "the segment COMs measured (balance board) on the lowered build",
       {"proportional"}, 0, {1.0}, 1.0, false},
      {EffectId::kKneeFrictionScale, P::kSweep, "knee_friction_scale",
       "the knee friction near extension (Tc) is larger or smaller than Burkett's Table 2 in every knee, by one factor",
       "Burkett 2004 Table 2 gives Tc per knee to the nearest 5 N m ('L5' for P4)",
       "the friction moment measured on the knee (a spring balance at the shank, near extension)",
       {"scale"}, 1, {}, 1.0, false},
      {EffectId::kStopRestitution, P::kSweep, "stop_restitution",
       "the hyperextension bumper returns a different share of the impact speed (coefficient of restitution e)",
       "no published bumper restitution (docs/assumptions.md prior 0.3-0.5)",
       "the knee's rebound off the stop filmed, or a drop test of the bumper",
       {"restitution"}, 1, {}, 1.0, false},
      {EffectId::kStopStiffness, P::kSweep, "stop_stiffness",
       "the hyperextension bumper is stiffer or softer (Hunt-Crossley stiffness)",
       "no published bumper stiffness (docs/assumptions.md)",
       "a static load test of the bumper",
       {"stiffness_Nm_per_rad1p5"}, 1, {}, 1.0, false},
      {EffectId::kHipExtensionRatio, P::kSweep, "hip_extension_ratio",
       "the terminal-swing hip extension moment is a different share of the flexion moment",
       "not published (Burkett measured it per participant); terminal-swing hip torques rise most with running speed "
       "(Schache 2011, Dorn 2012)",
       "the hip moment measured by inverse dynamics",
       {"ratio"}, 1, {}, 1.0, false},
      {EffectId::kHipFlexionDuration, P::kSweep, "hip_flexion_duration",
       "the hip flexion half-sine lasts longer or shorter than the assumed 0.20 s",
       "not published; the dynamometer's flexion half-cycle at 150 deg/s over 30-40 deg of hip motion",
       "the hip moment measured by inverse dynamics",
       {"duration_s"}, 1, {}, 1.0, false},
      {EffectId::kHipExtensionDuration, P::kSweep, "hip_extension_duration",
       "the hip extension half-sine lasts longer or shorter than the assumed 0.20 s",
       "not published; as the flexion duration",
       "the hip moment measured by inverse dynamics",
       {"duration_s"}, 1, {}, 1.0, false},
      {EffectId::kThighTargetFlexion, P::kSweep, "thigh_target_flexion",
       "the swing ended at a different thigh flexion than the assumed 20 deg (Burkett's 'defined position of flexion')",
       "Burkett 2004 does not give the thigh angle that ends a swing",
       "the thigh angle at heel contact measured (motion capture)",
       {"flexion_deg"}, 1, {}, 1.0, false},
  };
  return table;
}

namespace {

// Users' effects: append-only, so references handed out stay valid.
struct UserEffects {
  std::mutex mutex;
  std::deque<EffectDescriptor> descriptors;
};
UserEffects& userEffects() {
  static UserEffects registry;
  return registry;
}

}  // namespace

EffectId registerUserEffect(EffectDescriptor descriptor) {
  UserEffects& r = userEffects();
  std::lock_guard<std::mutex> lock(r.mutex);
  for (const auto& d : r.descriptors)
    if (d.plant == descriptor.plant && d.name == descriptor.name && d.sentence == descriptor.sentence &&
        d.mechanism == descriptor.mechanism &&
        d.parameters == descriptor.parameters)
      return d.id;
  descriptor.id = static_cast<EffectId>(kFirstUserEffectId + static_cast<int>(r.descriptors.size()));
  r.descriptors.push_back(std::move(descriptor));
  return r.descriptors.back().id;
}

const EffectDescriptor& describeEffect(EffectId id) {
  if (isUserEffect(id)) {
    UserEffects& r = userEffects();
    std::lock_guard<std::mutex> lock(r.mutex);
    const auto i = static_cast<std::size_t>(static_cast<int>(id) - kFirstUserEffectId);
    if (i < r.descriptors.size()) return r.descriptors[i];
  }
  for (const auto& e : effectTable())
    if (e.id == id) return e;
  throw std::logic_error("effect missing from the effect table");
}

std::vector<std::string> effectNames(PlantKind plant) {
  std::vector<std::string> names;
  for (const auto& e : effectTable())
    if (e.plant == plant) names.push_back(e.name);
  return names;
}

const EffectDescriptor* findEffect(PlantKind plant, const std::string& name) {
  for (const auto& e : effectTable())
    if (e.plant == plant && e.name == name) return &e;
  UserEffects& r = userEffects();
  std::lock_guard<std::mutex> lock(r.mutex);
  for (auto it = r.descriptors.rbegin(); it != r.descriptors.rend(); ++it)
    if (it->plant == plant && it->name == name) return &*it;
  return nullptr;
}

std::string plantName(PlantKind plant) {
  switch (plant) {
    case PlantKind::kCylinder:
      return "cylinder";
    case PlantKind::kSwing:
      return "swing";
    case PlantKind::kSweep:
      return "sweep";
  }
  return "cylinder";
}

}  // namespace swingsim
