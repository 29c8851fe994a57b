#include "identify/effect_table.h"

#include <deque>
#include <mutex>
#include <stdexcept>

#include "identify/cylinder_effects.h"
#include "identify/sweep_effects.h"
#include "identify/swing_effects.h"

namespace swingsim {

const std::vector<EffectDescriptor>& effectTable() {
  // Each effect's descriptor is the first part of its plant's record, in the plants' order.
  static const std::vector<EffectDescriptor> table = [] {
    std::vector<EffectDescriptor> t;
    for (const auto& r : cylinderEffectRecords()) t.push_back(r.descriptor);
    for (const auto& r : swingEffectRecords()) t.push_back(r.descriptor);
    for (const auto& r : sweepEffectLaws()) t.push_back(r.descriptor);
    return t;
  }();
  return table;
}

namespace {

// Users' effects: append-only, so references handed out stay valid.
struct UserEffects {
  std::mutex mutex;
  std::deque<EffectDescriptor> descriptors;
};
UserEffects& userEffects() {
  static UserEffects registry;
  return registry;
}

}  // namespace

EffectId registerUserEffect(EffectDescriptor descriptor) {
  UserEffects& r = userEffects();
  std::lock_guard<std::mutex> lock(r.mutex);
  for (const auto& d : r.descriptors)
    if (d.plant == descriptor.plant && d.name == descriptor.name && d.sentence == descriptor.sentence &&
        d.mechanism == descriptor.mechanism && d.parameters == descriptor.parameters)
      return d.id;
  descriptor.id = static_cast<EffectId>(kFirstUserEffectId + static_cast<int>(r.descriptors.size()));
  r.descriptors.push_back(std::move(descriptor));
  return r.descriptors.back().id;
}

const EffectDescriptor& describeEffect(EffectId id) {
  if (isUserEffect(id)) {
    UserEffects& r = userEffects();
    std::lock_guard<std::mutex> lock(r.mutex);
    const auto i = static_cast<std::size_t>(static_cast<int>(id) - kFirstUserEffectId);
    if (i < r.descriptors.size()) return r.descriptors[i];
  }
  for (const auto& e : effectTable())
    if (e.id == id) return e;
  throw std::logic_error("effect missing from the effect table");
}

std::vector<std::string> effectNames(PlantKind plant) {
  std::vector<std::string> names;
  for (const auto& e : effectTable())
    if (e.plant == plant) names.push_back(e.name);
  return names;
}

const EffectDescriptor* findEffect(PlantKind plant, const std::string& name) {
  for (const auto& e : effectTable())
    if (e.plant == plant && e.name == name) return &e;
  UserEffects& r = userEffects();
  std::lock_guard<std::mutex> lock(r.mutex);
  for (auto it = r.descriptors.rbegin(); it != r.descriptors.rend(); ++it)
    if (it->plant == plant && it->name == name) return &*it;
  return nullptr;
}

std::string plantName(PlantKind plant) {
  switch (plant) {
    case PlantKind::kCylinder:
      return "cylinder";
    case PlantKind::kSwing:
      return "swing";
    case PlantKind::kSweep:
      return "sweep";
  }
  return "cylinder";
}

}  // namespace swingsim
