#pragma once
// The sweep plant's candidate effects (identify/sweep_plant.h), one record each: its
// descriptor (identify/effect_table.h), the assumption it sets, its physical range and where
// that range comes from (sweepEffectLaws() in sweep_effects.cpp), and how a model's shared
// values act on a participant's swing.
#include <string>
#include <utility>
#include <vector>

#include "identify/diagnosis_engine.h"
#include "identify/effect_table.h"
#include "sweep/sweep_assumptions.h"

namespace swingsim {

/// A sweep model: the shared effects with their values (reported units) and, after a fit,
/// each in-model participant's calibrated time scale and each fold's shared values.
struct SweepModelParams {
  std::vector<std::pair<EffectId, double>> effects;
  std::vector<double> timeScales;  ///< per in-model participant (empty before a fit)
  /// Per in-model participant: the shared values of the fold that held it out (effect order).
  std::vector<std::vector<double>> heldOutValues;
  bool has(EffectId id) const;
  /// The value of `id` (reported unit); NaN if the model does not have it.
  double value(EffectId id) const;
};

using SweepModel = PlantModelOf<SweepModelParams>;
/// The parameters inside an engine model of the sweep plant.
const SweepModelParams& sweepParams(const PlantModel& model);

/// The range and law of one sweep effect (the table in sweep_effects.cpp).
struct SweepEffectLaw {
  /// What the effect is, for users: name, sentences, parameters (identify/effect_table.h).
  EffectDescriptor descriptor;
  EffectId id() const { return descriptor.id; }
  /// The assumption of sweepAssumptions() it sets ("" = the plant's own law: the hip tempo).
  std::string assumption;
  bool relative = false;        ///< the value multiplies each participant's own (Tc)
  double lower = 0, upper = 0;  ///< physical range of the shared value (reported unit)
  bool logScale = false;
  std::string rangeSource;  ///< why this range
};
/// Every sweep effect's law, in the effect table's order.
const std::vector<SweepEffectLaw>& sweepEffectLaws();
/// The law of a sweep effect; throws std::logic_error for another plant's effect.
const SweepEffectLaw& findSweepEffectLaw(EffectId id);
/// The assumption of sweepAssumptions() with `key`; throws std::logic_error if none.
const SweepAssumption& findSweepAssumption(const std::string& key);

/// `variant` with every shared effect of `params` that acts on the inputs applied (the
/// lowering-dependent hip tempo acts per swing: calcSweepSwingParticipant).
SweepVariant applySweepEffects(const SweepVariant& variant, const SweepModelParams& params);
/// The participant one swing at `lowering` runs: the hip-effort adaptation and the hip tempo
/// (time scale x (1 + c lowering / 0.1 m)) applied to `variant`'s participant.
Participant calcSweepSwingParticipant(const SweepVariant& variant, const SweepModelParams& params, double lowering);

}  // namespace swingsim
