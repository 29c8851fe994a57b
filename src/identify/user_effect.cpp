#include "identify/user_effect.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/input_error.h"

namespace swingsim {

KneeExpressionParams UserEffect::startLaw() const {
  KneeExpressionParams law{name, expression, {}};
  for (const auto& q : parameters) law.parameters.push_back({q.name, q.unit, q.start});
  return law;
}

void checkUserEffect(const UserEffect& effect, PlantKind plant) {
  const EffectDescriptor* known = findEffect(plant, effect.name);
  if (known && !isUserEffect(known->id))
    throw std::invalid_argument(effect.name + ": the name of a library effect; give your effect another name");
  for (const auto& q : effect.parameters) {
    const std::string where = effect.name + ": parameter '" + q.name + "': ";
    if (!std::isfinite(q.min) || !std::isfinite(q.max) || !std::isfinite(q.start))
      throw std::invalid_argument(where + "min, max and start must be finite numbers");
    if (!(q.min < q.max)) throw std::invalid_argument(where + "expected min < max");
    if (q.start < q.min || q.start > q.max) throw std::invalid_argument(where + "expected start within [min, max]");
  }
  if (effect.parameters.empty())
    throw std::invalid_argument(
        effect.name + ": expected at least one parameter to fit (parameters: {NAME: {unit, min, max, start}})");
}

EffectDescriptor describeUserEffect(const UserEffect& effect, PlantKind plant, const std::string& quantity) {
  EffectDescriptor d{};
  d.plant = plant;
  d.name = effect.name;
  d.sentence = "a user's " + quantity + ": " + effect.expression;
  d.mechanism = "written by the user in the study (no library effect); its bounds are its physical rule:";
  for (const auto& q : effect.parameters)
    d.mechanism += " " + q.name + " in [" + formatNumber(q.min) + ", " + formatNumber(q.max) + "] from " +
                   formatNumber(q.start) + ";";
  d.separatedBy = "records that reach the states where the expression acts";
  for (const auto& q : effect.parameters) d.parameters.push_back(q.name + (q.unit.empty() ? "" : " (" + q.unit + ")"));
  d.fittedParameters = static_cast<int>(effect.parameters.size());
  return d;
}

BoundedParameter userEffectBound(const UserEffect& effect, std::size_t j) {
  const auto& q = effect.parameters.at(j);
  const double typical = std::max({std::abs(q.start), std::abs(q.min), std::abs(q.max)}) * 0.1;
  return {q.name, q.start, q.min, q.max, false, typical > 0 ? typical : 1.0};
}

}  // namespace swingsim
