#include "identify/sweep_effects.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace swingsim {

namespace {

constexpr double kTempoReference = 0.1;  // m: the hip tempo's c is per 0.1 m of lowering

}  // namespace

// The sweep effects: their assumption, range and where the range comes from. Ranges are
// physical limits wide enough to hold every published value, never fitted to Table 4.
const std::vector<SweepEffectLaw>& sweepEffectLaws() {
  using E = EffectId;
  using P = PlantKind;
  static const std::vector<SweepEffectLaw> table = {
      {{E::kHipEffortAdaptation,
        P::kSweep,
        "hip_effort_adaptation",
        "the hip moment changes with the knee-axis lowering in proportion to (I_knee(d) / I_knee(0))^a, "
        "I_knee the shank + foot inertia about the knee (a < 0: more effort on the lighter-feeling lowered shank)",
        "Hale 1990 (Prosthet Orthot Int 14:125): amputees raised hip effort 37-71 % for a heavier shank; either sign",
        "the hip moment measured at each lowering (dynamometer or inverse dynamics)",
        {"exponent"},
        1,
        {},
        1.0,
        false},
       "hip_effort_adaptation",
       false,
       -2.0,
       2.0,
       false,
       "Hale 1990's 37-71 % effort rise for a 2.5x heavier shank is an exponent of about 0.4-0.6 on the inertia "
       "ratio; +-2 holds it with either sign"},
      {{E::kHipTempoLowering,
        P::kSweep,
        "hip_tempo_lowering",
        "the hip drive's timing changes with the lowering: time scale x (1 + c d / 0.1 m)",
        "Burkett, Smeathers & Barker 2001 (Prosthet Orthot Int 25:210): running speed rose 26 % on the lowered knee; "
        "a faster cadence shortens the hip drive (c < 0)",
        "the stride time or cadence measured at each lowering",
        {"change_per_100mm"},
        1,
        {},
        1.0,
        false},
       "",
       false,
       -0.5,
       0.5,
       false,
       "Burkett 2001: 26 % faster running on the lowered knee; +-50 % per 0.1 m holds any cadence change a runner can "
       "make"},
      {{E::kComRuleProportional,
        P::kSweep,
        "com_rule_proportional",
        "the segment COMs move in proportion to the new lengths when the knee is lowered (the other reading of "
        "Burkett)",
        "Burkett 2004's sentence on the COMs allows both readings (docs/assumptions.md, COM rule)",
        "the segment COMs measured (balance board) on the lowered build",
        {"proportional"},
        0,
        {1.0},
        1.0,
        false},
       "com_rule",
       false,
       1.0,
       1.0,
       false,
       "a two-way choice (docs/assumptions.md)"},
      {{E::kKneeFrictionScale,
        P::kSweep,
        "knee_friction_scale",
        "the knee friction near extension (Tc) is larger or smaller than Burkett's Table 2 in every knee, by one "
        "factor",
        "Burkett 2004 Table 2 gives Tc per knee to the nearest 5 N m ('L5' for P4)",
        "the friction moment measured on the knee (a spring balance at the shank, near extension)",
        {"scale"},
        1,
        {},
        1.0,
        false},
       "knee_friction",
       true,
       0.0,
       3.0,
       false,
       "0 (no friction) to 3x Table 2's 5-15 N m, past any swing-phase knee's friction"},
      {{E::kStopRestitution,
        P::kSweep,
        "stop_restitution",
        "the hyperextension bumper returns a different share of the impact speed (coefficient of restitution e)",
        "no published bumper restitution (docs/assumptions.md prior 0.3-0.5)",
        "the knee's rebound off the stop filmed, or a drop test of the bumper",
        {"restitution"},
        1,
        {},
        1.0,
        false},
       "stop_restitution",
       false,
       0.05,
       0.95,
       false,
       "a coefficient of restitution lies in (0, 1); the ends are left out because the stop model needs 0 < e < 1"},
      {{E::kStopStiffness,
        P::kSweep,
        "stop_stiffness",
        "the hyperextension bumper is stiffer or softer (Hunt-Crossley stiffness)",
        "no published bumper stiffness (docs/assumptions.md)",
        "a static load test of the bumper",
        {"stiffness_Nm_per_rad1p5"},
        1,
        {},
        1.0,
        false},
       "stop_stiffness",
       false,
       2.0e3,
       2.0e5,
       true,
       "a decade either side of the file's 2e4 N m/rad^1.5"},
      {{E::kHipExtensionRatio,
        P::kSweep,
        "hip_extension_ratio",
        "the terminal-swing hip extension moment is a different share of the flexion moment",
        "not published (Burkett measured it per participant); terminal-swing hip torques rise most with running speed "
        "(Schache 2011, Dorn 2012)",
        "the hip moment measured by inverse dynamics",
        {"ratio"},
        1,
        {},
        1.0,
        false},
       "hip_extension_ratio",
       false,
       0.1,
       1.5,
       false,
       "from almost no terminal-swing brake to one half again as strong as the flexion drive"},
      {{E::kHipFlexionDuration,
        P::kSweep,
        "hip_flexion_duration",
        "the hip flexion half-sine lasts longer or shorter than the assumed 0.20 s",
        "not published; the dynamometer's flexion half-cycle at 150 deg/s over 30-40 deg of hip motion",
        "the hip moment measured by inverse dynamics",
        {"duration_s"},
        1,
        {},
        1.0,
        false},
       "hip_flexion_duration",
       false,
       0.10,
       0.35,
       false,
       "half to 1.75x the assumed 0.20 s"},
      {{E::kHipExtensionDuration,
        P::kSweep,
        "hip_extension_duration",
        "the hip extension half-sine lasts longer or shorter than the assumed 0.20 s",
        "not published; as the flexion duration",
        "the hip moment measured by inverse dynamics",
        {"duration_s"},
        1,
        {},
        1.0,
        false},
       "hip_extension_duration",
       false,
       0.10,
       0.35,
       false,
       "half to 1.75x the assumed 0.20 s"},
      {{E::kThighTargetFlexion,
        P::kSweep,
        "thigh_target_flexion",
        "the swing ended at a different thigh flexion than the assumed 20 deg (Burkett's 'defined position of "
        "flexion')",
        "Burkett 2004 does not give the thigh angle that ends a swing",
        "the thigh angle at heel contact measured (motion capture)",
        {"flexion_deg"},
        1,
        {},
        1.0,
        false},
       "thigh_target_flexion",
       false,
       5.0,
       35.0,
       false,
       "the thigh flexion at heel contact in walking and running, 15-30 deg (Winter 2009), widened by 10 deg"},
  };
  return table;
}

bool SweepModelParams::has(EffectId id) const {
  return std::any_of(effects.begin(), effects.end(), [&](const auto& e) { return e.first == id; });
}

double SweepModelParams::value(EffectId id) const {
  for (const auto& [e, v] : effects)
    if (e == id) return v;
  return std::numeric_limits<double>::quiet_NaN();
}

const SweepAssumption& findSweepAssumption(const std::string& key) {
  for (const auto& a : sweepAssumptions())
    if (a.key == key) return a;
  throw std::logic_error("sweep plant: no assumption " + key);
}

const SweepModelParams& sweepParams(const PlantModel& model) { return plantModelParams<SweepModelParams>(model); }

const SweepEffectLaw& findSweepEffectLaw(EffectId id) {
  for (const auto& l : sweepEffectLaws())
    if (l.id() == id) return l;
  throw std::logic_error("sweep plant: effect " + describeEffect(id).name + " has no sweep law");
}

SweepVariant applySweepEffects(const SweepVariant& variant, const SweepModelParams& params) {
  SweepVariant v = variant;
  for (const auto& [id, value] : params.effects) {
    const SweepEffectLaw& law = findSweepEffectLaw(id);
    if (law.assumption.empty()) continue;  // acts per swing
    const SweepAssumption& a = findSweepAssumption(law.assumption);
    a.apply(v, law.relative ? value * a.read(variant) : value);
  }
  return v;
}

Participant calcSweepSwingParticipant(const SweepVariant& variant, const SweepModelParams& params, double lowering) {
  Participant p = calcAdaptedParticipant(variant.participant, lowering, variant.hipEffortExponent);
  const double c = params.value(EffectId::kHipTempoLowering);
  if (std::isfinite(c)) p.hipMoment.timeScale *= 1.0 + c * lowering / kTempoReference;
  return p;
}

}  // namespace swingsim
