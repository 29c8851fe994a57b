#include "identify/user_cylinder_effect.h"

#include <algorithm>

namespace swingsim {

namespace {

UserRecordRegistry<CylinderEffectRecord>& registry() {
  static UserRecordRegistry<CylinderEffectRecord> r;
  return r;
}

using Expressions = std::vector<KneeExpressionParams>;

Expressions::const_iterator findExpression(const Expressions& list, const std::string& name) {
  return std::find_if(list.begin(), list.end(), [&](const KneeExpressionParams& x) { return x.name == name; });
}

void removeExpression(Expressions& list, const std::string& name) {
  list.erase(std::remove_if(list.begin(), list.end(), [&](const KneeExpressionParams& x) { return x.name == name; }),
             list.end());
}

CylinderEffectRecord makeRecord(EffectId id, const UserEffect& effect) {
  using P = MauchCylinderParams;
  const std::string name = effect.name;
  CylinderEffectRecord r{describeEffect(id)};
  r.has = [name](const P& p) { return findExpression(p.effects.expressions, name) != p.effects.expressions.end(); };
  r.add = [name, law = effect.startLaw()](P& p, double) {
    removeExpression(p.effects.expressions, name);
    p.effects.expressions.push_back(law);
  };
  r.remove = [name](P& p) { removeExpression(p.effects.expressions, name); };
  r.values = [name](const P& p) {
    std::vector<double> out;
    const auto x = findExpression(p.effects.expressions, name);
    if (x != p.effects.expressions.end())
      for (const auto& q : x->parameters) out.push_back(q.value);
    return out;
  };
  r.isPhysical = [](const P&, const std::vector<BenchData>&, std::string& note) {
    note = "a user's effect: its parameters' bounds are its physical rule";
    return true;
  };
  r.combine = [name](P& model, const P& fromB) {
    removeExpression(model.effects.expressions, name);
    const auto x = findExpression(fromB.effects.expressions, name);
    if (x != fromB.effects.expressions.end()) model.effects.expressions.push_back(*x);
  };
  for (std::size_t j = 0; j < effect.parameters.size(); ++j) r.expressionBounds.push_back(userEffectBound(effect, j));
  return r;
}

}  // namespace

EffectId registerUserCylinderEffect(const UserEffect& effect) {
  checkUserEffect(effect, PlantKind::kCylinder);
  checkCylinderExpression(effect.startLaw());
  const EffectId id =
      registerUserEffect(describeUserEffect(effect, PlantKind::kCylinder, "cylinder force (N, + resists compression)"));
  registry().add(id, [&] { return makeRecord(id, effect); });
  return id;
}

const CylinderEffectRecord* findUserCylinderEffectRecord(EffectId id) { return registry().find(id); }

}  // namespace swingsim
