#pragma once
// A user's cylinder effect: a cylinder force written as an expression in the piston's
// position and speed (knee/cylinder_expression.h) with its parameters' bounds, made a
// candidate of the cylinder diagnosis beside the library's. It is a record of the same kind
// as the library's (identify/cylinder_effects.h): fitted, scored, accepted and given
// intervals by the same rules, and saved into the knee model's cylinder `effects:
// expressions:` list, so every command that runs the cylinder applies it.
#include "identify/cylinder_effects.h"
#include "identify/user_effect.h"

namespace swingsim {

/// Checks `effect` (its expression parses as a cylinder force with its parameters; bounds
/// ordered and finite, start within them; the name is not the library's) and registers it as
/// a cylinder effect; returns its id (the same for the same definition). Throws
/// KneeExpressionError for the expression and std::invalid_argument for the rest.
EffectId registerUserCylinderEffect(const UserEffect& effect);
/// The record of a registered user's cylinder effect; nullptr if `id` is not one.
const CylinderEffectRecord* findUserCylinderEffectRecord(EffectId id);

}  // namespace swingsim
