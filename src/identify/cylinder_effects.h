#pragma once
// The cylinder plant's candidate effects: one record per effect (cylinder_effects.cpp),
// holding everything the plant needs of it: whether a model has it, how it is switched on and
// off, its values, its regression columns, its physical sign rule, when it does not apply and
// whether its acceptance frees the switch constants. The effect's law is the Mauch cylinder's
// (knee/mauch_cylinder.h); its user-facing text (name, sentences, parameter names, grid) is
// its descriptor, the record's first part (identify/effect_table.h). Adding a cylinder
// candidate: its law, its id, its record, its test (tests/identify/cylinder_effects_test.cpp). A user's effect
// (a cylinder_force_N expression in a study's candidates) is a record of the same kind, made
// at run time (identify/user_cylinder_effect.h).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "identify/bench_data.h"
#include "identify/effect_table.h"
#include "knee/mauch_cylinder.h"
#include "numerics/bounded_least_squares.h"

namespace swingsim {

/// What accepting an effect does to the switch constants (CylinderPlant::refitAccepted).
enum class CylinderRefit {
  kNone,           ///< a linear effect: its candidate fit is already joint
  kSwitches,       ///< one joint fit of the coefficients, switch widths and xhy
  kSwitchesLatch,  ///< as kSwitches, and the latch rate too
};

/// One candidate effect of the cylinder plant. Hooks left null take the default named.
struct CylinderEffectRecord {
  /// What the effect is, for users: name, sentences, parameters, grid (identify/effect_table.h).
  EffectDescriptor descriptor;
  EffectId id() const { return descriptor.id; }
  /// Whether a model has the effect.
  std::function<bool(const MauchCylinderParams&)> has = nullptr;
  /// Switches it on: its linear coefficients 0 until fitted, its grid value set (SI).
  std::function<void(MauchCylinderParams&, double gridValue)> add = nullptr;
  /// Switches it off (for the effect size: the model without it).
  std::function<void(MauchCylinderParams&)> remove = nullptr;
  /// Its reported values, in the descriptor's parameter order.
  std::function<std::vector<double>(const MauchCylinderParams&)> values = nullptr;
  /// The sign rule on a fitted model; `train` gives the recorded stroke. `note` says the
  /// rule and the value.
  std::function<bool(const MauchCylinderParams&, const std::vector<BenchData>& train, std::string& note)> isPhysical =
      nullptr;
  /// Regression columns it adds (MauchCylinder::calcRegressorRow) and their place among the
  /// added effects' columns (0 first); -1: no column.
  int columns = 0;
  int columnRank = -1;
  /// Why it cannot be added to a model (""), checked before "already in the model"; null: none.
  std::function<std::string(const MauchCylinderParams&)> notApplicable = nullptr;
  /// `model` with b's effect taken from `fromB`; null: add it at b's grid value (or 0).
  std::function<void(MauchCylinderParams& model, const MauchCylinderParams& fromB)> combine = nullptr;
  CylinderRefit refit = CylinderRefit::kNone;
  /// A larger model that nests the accepted one, tried after the joint refit; null: none.
  std::function<std::optional<MauchCylinderParams>(const MauchCylinderParams&)> nestingModel = nullptr;
  /// A user's effect: the bounds of its expression's parameters, in their order, fitted
  /// around the regression (CylinderPlant::fit); empty for the library's.
  std::vector<BoundedParameter> expressionBounds = {};
};

/// Every library cylinder effect's record, in the effect table's order.
const std::vector<CylinderEffectRecord>& cylinderEffectRecords();
/// The record of `effect` (the library's or a registered user's,
/// identify/user_cylinder_effect.h); throws std::invalid_argument if it is not a cylinder effect.
const CylinderEffectRecord& findCylinderEffectRecord(EffectId effect);
/// Regression columns of `effect` in `p` (after the 3 coefficients of each phase); empty if
/// the model does not have it.
std::vector<int> cylinderEffectColumns(const MauchCylinderParams& p, EffectId effect);

}  // namespace swingsim
