#include "identify/user_swing_effect.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <mutex>
#include <stdexcept>

#include "core/input_error.h"

namespace swingsim {

KneeExpressionParams UserSwingEffect::startLaw() const {
  KneeExpressionParams law{name, expression, {}};
  for (const auto& q : parameters) law.parameters.push_back({q.name, q.unit, q.start});
  return law;
}

namespace {

struct Registered {
  EffectId id;
  SwingEffectRecord record;
};

struct Registry {
  std::mutex mutex;
  std::deque<Registered> entries;  // append-only: records handed out stay valid
};
Registry& registry() {
  static Registry r;
  return r;
}

KneeExpressionParams* findExpression(SwingEffects& e, const std::string& name) {
  for (auto& x : e.knee.expressions)
    if (x.name == name) return &x;
  return nullptr;
}

void checkBounds(const UserSwingEffect& effect) {
  for (const auto& q : effect.parameters) {
    const std::string where = effect.name + ": parameter '" + q.name + "': ";
    if (!std::isfinite(q.min) || !std::isfinite(q.max) || !std::isfinite(q.start))
      throw std::invalid_argument(where + "min, max and start must be finite numbers");
    if (!(q.min < q.max)) throw std::invalid_argument(where + "expected min < max");
    if (q.start < q.min || q.start > q.max) throw std::invalid_argument(where + "expected start within [min, max]");
  }
  if (effect.parameters.empty())
    throw std::invalid_argument(effect.name + ": expected at least one parameter to fit (parameters: {NAME: {unit, min, max, start}})");
}

// "a user's expression: <expression>" and its parameters named with their units.
EffectDescriptor describeUserEffect(const UserSwingEffect& effect) {
  EffectDescriptor d{};
  d.plant = PlantKind::kSwing;
  d.name = effect.name;
  d.sentence = "a user's knee moment (N m, + = flexion): " + effect.expression;
  d.mechanism = "written by the user in the study (no library effect); its bounds are its physical rule:";
  for (const auto& q : effect.parameters)
    d.mechanism += " " + q.name + " in [" + formatNumber(q.min) + ", " + formatNumber(q.max) + "] from " + formatNumber(q.start) + ";";
  d.separatedBy = "records that reach the states where the expression acts";
  for (const auto& q : effect.parameters) d.parameters.push_back(q.name + (q.unit.empty() ? "" : " (" + q.unit + ")"));
  d.fittedParameters = static_cast<int>(effect.parameters.size());
  return d;
}

bool boundsAreTheRule(const SwingEffects&, std::string& note) {
  note = "a user's effect: its parameters' bounds are its physical rule";
  return true;
}

SwingEffectRecord makeRecord(EffectId id, const UserSwingEffect& effect) {
  SwingEffectRecord r{id, {}};
  for (std::size_t j = 0; j < effect.parameters.size(); ++j) {
    const auto& q = effect.parameters[j];
    const double typical = std::max({std::abs(q.start), std::abs(q.min), std::abs(q.max)}) * 0.1;
    BoundedParameter b{q.name, q.start, q.min, q.max, false, typical > 0 ? typical : 1.0};
    r.slots.push_back({b, 1.0, [name = effect.name, j](SwingEffects& e) -> double& {
                         KneeExpressionParams* x = findExpression(e, name);
                         if (!x) throw std::logic_error(name + ": a user's effect read while absent");
                         return x->parameters[j].value;
                       }});
  }
  r.isPhysical = boundsAreTheRule;
  r.setPresence = [law = effect.startLaw()](SwingEffects& e, bool present) {
    auto& list = e.knee.expressions;
    list.erase(std::remove_if(list.begin(), list.end(), [&](const KneeExpressionParams& x) { return x.name == law.name; }),
               list.end());
    if (present) list.push_back(law);
  };
  return r;
}

}  // namespace

EffectId registerUserSwingEffect(const UserSwingEffect& effect) {
  const EffectDescriptor* known = findEffect(PlantKind::kSwing, effect.name);
  if (known && !isUserEffect(known->id))
    throw std::invalid_argument(effect.name + ": the name of a library effect; give your effect another name");
  checkBounds(effect);
  checkKneeExpression(effect.startLaw());
  const EffectId id = registerUserEffect(describeUserEffect(effect));
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  for (const auto& e : r.entries)
    if (e.id == id) return id;
  r.entries.push_back({id, makeRecord(id, effect)});
  return id;
}

const SwingEffectRecord* findUserSwingEffectRecord(EffectId id) {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  for (const auto& e : r.entries)
    if (e.id == id) return &e.record;
  return nullptr;
}

}  // namespace swingsim
