#pragma once
// A user's swing effect: a knee moment written as an expression (knee/knee_expression.h) with
// its parameters' bounds, made a candidate of the swing diagnosis beside the library's. It is
// a record of the same kind as the library's (identify/swing_effects.h): fitted, scored,
// accepted and given intervals by the same rules, and saved into the knee model's
// `knee_effects: expressions:` list, so every command that runs the knee applies it.
#include <string>
#include <vector>

#include "identify/swing_effects.h"
#include "knee/knee_expression.h"

namespace swingsim {

/// One parameter of a user's effect: its unit (a label), its physical bounds and the value a
/// fit starts from. The bounds are the effect's rule (as the library's sign rules are): set
/// them from physics, not from the data.
struct UserEffectParameter {
  std::string name, unit;
  double min = 0, max = 0, start = 0;
};

/// A user's effect as a study states it.
struct UserSwingEffect {
  std::string name;        ///< a name no library effect has
  std::string expression;  ///< the knee moment, N m, + = flexion
  std::vector<UserEffectParameter> parameters;
  /// The knee law's parameters (name, unit, value) at the start values.
  KneeExpressionParams startLaw() const;
};

/// Checks `effect` (its expression parses with its parameters; bounds ordered and finite,
/// start within them; the name is not the library's) and registers it as a swing effect;
/// returns its id (the same for the same definition). Throws KneeExpressionError for the
/// expression and std::invalid_argument for the rest.
EffectId registerUserSwingEffect(const UserSwingEffect& effect);
/// The record of a registered user's effect; nullptr if `id` is not one.
const SwingEffectRecord* findUserSwingEffectRecord(EffectId id);

}  // namespace swingsim
