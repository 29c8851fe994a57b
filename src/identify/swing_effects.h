#pragma once
// The swing plant's candidate effects: one record per effect (swing_effects.cpp), holding
// everything the plant needs of it: where its values live in the model, their physical
// bounds and report units, the grid value, where it acts on the leg, its physical sign rule
// and when it does not apply; first of all its descriptor, the user-facing text (name,
// sentences, parameter names, grid; identify/effect_table.h). Adding a swing candidate: its
// id, its record, its test (tests/identify/swing_effects_test.cpp). A user's effect
// (an expression in a study's candidates) is a record of the same kind, made at run time
// (identify/user_swing_effect.h).
#include <functional>
#include <string>
#include <vector>

#include "identify/effect_table.h"
#include "knee/knee_added_effects.h"
#include "model/leg_parameters.h"
#include "numerics/bounded_least_squares.h"

namespace swingsim {

/// The swing effects of a model: which are present and their values (a value of an absent
/// effect is not used).
struct SwingEffects {
  std::vector<EffectId> present;                 ///< the effects in the model, in the order added
  KneeAddedEffectsParams knee;                   ///< friction, damping, spring values; users' expressions
  double toeOffHipRate = 0, toeOffKneeRate = 0;  ///< rad/s at toe-off
  double hipMomentScale = 1;                     ///< multiplies the measured hip moment
  double shankMassScale = 1;                     ///< multiplies shank mass and inertia
  double belowKneeMassScale = 1;                 ///< multiplies shank and foot masses and inertias
  /// The socket's give on the residual limb (its rotation's stiffness and damping are
  /// fitted; the rest stays at MyoSuite's values, docs/socket.md).
  SocketCompliance socket;
  /// Whether `effect` (a swing effect of the table) is present.
  bool has(EffectId effect) const;
  /// Marks `effect` present or absent (its values are left as they are).
  void setPresent(EffectId effect, bool on);
};

/// One continuously fitted value of an effect. Bounds are physics, not data
/// (docs/diagnosis.md); `bounds.start` is the value of the effect switched on before a fit
/// (0 for a moment or a rate, 1 for a scale).
struct SwingEffectSlot {
  BoundedParameter bounds;
  double reportScale;                           ///< value times this = reported value (rad/s -> deg/s)
  std::function<double&(SwingEffects&)> value;  ///< where the value lives
};

/// One candidate effect of the swing plant. Hooks left null do nothing.
struct SwingEffectRecord {
  /// What the effect is, for users: name, sentences, parameters, grid (identify/effect_table.h).
  EffectDescriptor descriptor;
  EffectId id() const { return descriptor.id; }
  /// Continuously fitted values, in the order of the descriptor's parameters.
  std::vector<SwingEffectSlot> slots;
  /// The descriptor's grid parameter (SI), or null when it has none.
  double& (*gridValue)(SwingEffects&) = nullptr;
  /// Why the effect does not apply when the measured thigh drives the swing ("" applies).
  const char* notUnderThighDrive = "";
  /// The sign rule: true if the values are physical; `note` says the rule and the value.
  bool (*isPhysical)(const SwingEffects&, std::string& note) = nullptr;
  /// Where a participant-level effect acts (mass, toe-off rates, hip moment profile, or a
  /// socket that adds two mobilities to the leg).
  void (*applyToParticipant)(const SwingEffects&, Participant&) = nullptr;
  /// On each record's measured hip moment (N m) when it drives the swing.
  void (*applyToHipDrive)(const SwingEffects&, std::vector<double>& moments) = nullptr;
  /// On the toe-off state of a hip-moment driven swing (rates start at zero).
  void (*applyToToeOff)(const SwingEffects&, double& hipRate, double& kneeRate) = nullptr;
  /// Run when the effect is switched on or off, before its slots are set: a user's
  /// expression enters or leaves the knee's added effects.
  std::function<void(SwingEffects&, bool present)> setPresence = nullptr;
};

/// Every swing effect's record, in the effect table's order.
const std::vector<SwingEffectRecord>& swingEffectRecords();
/// The record of `effect` (the library's or a registered user's); throws
/// std::invalid_argument if it is not a swing effect.
const SwingEffectRecord& findSwingEffectRecord(EffectId effect);
/// The records of the effects present in `effects`: the library's in table order, then the
/// users' in the order added (the order of the fit's free parameters).
std::vector<const SwingEffectRecord*> presentSwingEffectRecords(const SwingEffects& effects);

/// `effects` with `effect` present at its start values (`gridValue`: its grid value, SI).
SwingEffects addSwingEffectTo(const SwingEffects& effects, EffectId effect, double gridValue);
/// `effects` without `effect`: absent, its values back at their start values.
SwingEffects removeSwingEffect(const SwingEffects& effects, EffectId effect);
/// `effects` with `effect` present and its values (fitted and grid) copied from `from`.
SwingEffects copySwingEffect(const SwingEffects& effects, const SwingEffects& from, EffectId effect);
/// The reported values of `effect`: the fitted ones in report units, then the grid value.
std::vector<double> swingEffectValues(const SwingEffects& effects, EffectId effect);

/// The participant with every present participant-level effect applied.
Participant applyParticipantEffects(const Participant& participant, const SwingEffects& effects);
/// A record's measured hip moment (N m) with every present effect on the hip drive applied.
std::vector<double> applyHipDriveEffects(const SwingEffects& effects, std::vector<double> moments);

}  // namespace swingsim
