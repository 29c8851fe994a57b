#include "identify/user_swing_effect.h"

#include <algorithm>
#include <stdexcept>

#include "core/input_error.h"

namespace swingsim {

namespace {

UserRecordRegistry<SwingEffectRecord>& registry() {
  static UserRecordRegistry<SwingEffectRecord> r;
  return r;
}

KneeExpressionParams* findExpression(SwingEffects& e, const std::string& name) {
  for (auto& x : e.knee.expressions)
    if (x.name == name) return &x;
  return nullptr;
}

bool boundsAreTheRule(const SwingEffects&, std::string& note) {
  note = "a user's effect: its parameters' bounds are its physical rule";
  return true;
}

SwingEffectRecord makeRecord(EffectId id, const UserSwingEffect& effect) {
  SwingEffectRecord r{describeEffect(id), {}};
  for (std::size_t j = 0; j < effect.parameters.size(); ++j) {
    r.slots.push_back({userEffectBound(effect, j), 1.0, [name = effect.name, j](SwingEffects& e) -> double& {
                         KneeExpressionParams* x = findExpression(e, name);
                         if (!x) throw std::logic_error(name + ": a user's effect read while absent");
                         return x->parameters[j].value;
                       }});
  }
  r.isPhysical = boundsAreTheRule;
  r.setPresence = [law = effect.startLaw()](SwingEffects& e, bool present) {
    auto& list = e.knee.expressions;
    list.erase(
        std::remove_if(list.begin(), list.end(), [&](const KneeExpressionParams& x) { return x.name == law.name; }),
        list.end());
    if (present) list.push_back(law);
  };
  return r;
}

}  // namespace

EffectId registerUserSwingEffect(const UserSwingEffect& effect) {
  checkUserEffect(effect, PlantKind::kSwing);
  checkKneeExpression(effect.startLaw());
  const EffectId id =
      registerUserEffect(describeUserEffect(effect, PlantKind::kSwing, "knee moment (N m, + = flexion)"));
  registry().add(id, [&] { return makeRecord(id, effect); });
  return id;
}

const SwingEffectRecord* findUserSwingEffectRecord(EffectId id) { return registry().find(id); }

}  // namespace swingsim
