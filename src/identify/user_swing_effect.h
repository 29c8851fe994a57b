#pragma once
// A user's swing effect: a knee moment written as an expression (knee/knee_expression.h) with
// its parameters' bounds, made a candidate of the swing diagnosis beside the library's. It is
// a record of the same kind as the library's (identify/swing_effects.h): fitted, scored,
// accepted and given intervals by the same rules, and saved into the knee model's
// `knee_effects: expressions:` list, so every command that runs the knee applies it.
#include <string>
#include <vector>

#include "identify/swing_effects.h"
#include "identify/user_effect.h"
#include "knee/knee_expression.h"

namespace swingsim {

/// A user's swing effect: its expression is a knee moment, N m, + = flexion.
using UserSwingEffect = UserEffect;

/// Checks `effect` (its expression parses with its parameters; bounds ordered and finite,
/// start within them; the name is not the library's) and registers it as a swing effect;
/// returns its id (the same for the same definition). Throws KneeExpressionError for the
/// expression and std::invalid_argument for the rest.
EffectId registerUserSwingEffect(const UserSwingEffect& effect);
/// The record of a registered user's effect; nullptr if `id` is not one.
const SwingEffectRecord* findUserSwingEffectRecord(EffectId id);

}  // namespace swingsim
