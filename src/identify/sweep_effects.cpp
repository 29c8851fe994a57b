#include "identify/sweep_effects.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>


namespace swingsim {

namespace {

constexpr double kTempoReference = 0.1;  // m: the hip tempo's c is per 0.1 m of lowering

// The sweep effects: their assumption, range and where the range comes from. Ranges are
// physical limits wide enough to hold every published value, never fitted to Table 4.
const std::vector<SweepEffectLaw>& lawTable() {
  using E = EffectId;
  static const std::vector<SweepEffectLaw> table = {
      {E::kHipEffortAdaptation, "hip_effort_adaptation", false, -2.0, 2.0, false,
       "Hale 1990's 37-71 % effort rise for a 2.5x heavier shank is an exponent of about 0.4-0.6 on the inertia "
       "ratio; +-2 holds it with either sign"},
      {E::kHipTempoLowering, "", false, -0.5, 0.5, false,
       "Burkett 2001: 26 % faster running on the lowered knee; +-50 % per 0.1 m holds any cadence change a runner can make"},
      {E::kComRuleProportional, "com_rule", false, 1.0, 1.0, false, "a two-way choice (docs/assumptions.md)"},
      {E::kKneeFrictionScale, "knee_friction", true, 0.0, 3.0, false,
       "0 (no friction) to 3x Table 2's 5-15 N m, past any swing-phase knee's friction"},
      {E::kStopRestitution, "stop_restitution", false, 0.05, 0.95, false,
       "a coefficient of restitution lies in (0, 1); the ends are left out because the stop model needs 0 < e < 1"},
      {E::kStopStiffness, "stop_stiffness", false, 2.0e3, 2.0e5, true,
       "a decade either side of the file's 2e4 N m/rad^1.5"},
      {E::kHipExtensionRatio, "hip_extension_ratio", false, 0.1, 1.5, false,
       "from almost no terminal-swing brake to one half again as strong as the flexion drive"},
      {E::kHipFlexionDuration, "hip_flexion_duration", false, 0.10, 0.35, false,
       "half to 1.75x the assumed 0.20 s"},
      {E::kHipExtensionDuration, "hip_extension_duration", false, 0.10, 0.35, false,
       "half to 1.75x the assumed 0.20 s"},
      {E::kThighTargetFlexion, "thigh_target_flexion", false, 5.0, 35.0, false,
       "the thigh flexion at heel contact in walking and running, 15-30 deg (Winter 2009), widened by 10 deg"},
  };
  return table;
}

}  // namespace

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
  for (const auto& l : lawTable())
    if (l.id == id) return l;
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
