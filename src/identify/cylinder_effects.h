#pragma once
// The cylinder plant's candidate effects: one record per effect (cylinder_effects.cpp),
// holding everything the plant needs of it: whether a model has it, how it is switched on and
// off, its values, its regression columns, its physical sign rule, when it does not apply and
// whether its acceptance frees the switch constants. The effect's law is the Mauch cylinder's
// (knee/mauch_cylinder.h); its user-facing text (name, sentences, parameter names, grid) is
// its descriptor in model/effect_table.cpp. Adding a cylinder candidate: its law, its
// descriptor, its record, its test (tests/identify/cylinder_effects_test.cpp).
#include <optional>
#include <string>
#include <vector>

#include "identify/bench_data.h"
#include "knee/mauch_cylinder.h"
#include "model/effect_table.h"

namespace swingsim {

/// What accepting an effect does to the switch constants (CylinderPlant::refitAccepted).
enum class CylinderRefit {
  kNone,            ///< a linear effect: its candidate fit is already joint
  kSwitches,        ///< one joint fit of the coefficients, switch widths and xhy
  kSwitchesLatch,   ///< as kSwitches, and the latch rate too
};

/// One candidate effect of the cylinder plant. Hooks left null take the default named.
struct CylinderEffectRecord {
  EffectId id;
  /// Whether a model has the effect.
  bool (*has)(const MauchCylinderParams&);
  /// Switches it on: its linear coefficients 0 until fitted, its grid value set (SI).
  void (*add)(MauchCylinderParams&, double gridValue);
  /// Switches it off (for the effect size: the model without it).
  void (*remove)(MauchCylinderParams&);
  /// Its reported values, in the descriptor's parameter order.
  std::vector<double> (*values)(const MauchCylinderParams&);
  /// The sign rule on a fitted model; `train` gives the recorded stroke. `note` says the
  /// rule and the value.
  bool (*isPhysical)(const MauchCylinderParams&, const std::vector<BenchData>& train, std::string& note);
  /// Regression columns it adds (MauchCylinder::calcRegressorRow) and their place among the
  /// added effects' columns (0 first); -1: no column.
  int columns = 0;
  int columnRank = -1;
  /// Why it cannot be added to a model (""), checked before "already in the model"; null: none.
  std::string (*notApplicable)(const MauchCylinderParams&) = nullptr;
  /// `model` with b's effect taken from `fromB`; null: add it at b's grid value (or 0).
  void (*combine)(MauchCylinderParams& model, const MauchCylinderParams& fromB) = nullptr;
  CylinderRefit refit = CylinderRefit::kNone;
  /// A larger model that nests the accepted one, tried after the joint refit; null: none.
  std::optional<MauchCylinderParams> (*nestingModel)(const MauchCylinderParams&) = nullptr;
};

/// Every cylinder effect's record, in the effect table's order.
const std::vector<CylinderEffectRecord>& cylinderEffectRecords();
/// The record of `effect`; throws std::invalid_argument if it is not a cylinder effect.
const CylinderEffectRecord& findCylinderEffectRecord(EffectId effect);
/// Regression columns of `effect` in `p` (after the 3 coefficients of each phase); empty if
/// the model does not have it.
std::vector<int> cylinderEffectColumns(const MauchCylinderParams& p, EffectId effect);

}  // namespace swingsim
