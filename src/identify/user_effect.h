#pragma once
// What a user's effect is, whichever plant it belongs to: a name, an expression and the bounds
// of its parameters, as a diagnosis study states it in its `candidates:` list. The swing's
// (a knee moment, identify/user_swing_effect.h) and the cylinder's (a cylinder force,
// identify/user_cylinder_effect.h) make it a record of their plant's kind.
#include <deque>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "identify/effect_table.h"
#include "knee/expression_parser.h"
#include "numerics/bounded_least_squares.h"

namespace swingsim {

/// One parameter of a user's effect: its unit (a label), its physical bounds and the value a
/// fit starts from. The bounds are the effect's rule (as the library's sign rules are): set
/// them from physics, not from the data.
struct UserEffectParameter {
  std::string name, unit;
  double min = 0, max = 0, start = 0;
};

/// A user's effect as a study states it.
struct UserEffect {
  std::string name;        ///< a name no library effect has
  std::string expression;  ///< the swing's knee moment (N m, + = flexion) or the cylinder's force (N)
  std::vector<UserEffectParameter> parameters;
  PlantKind plant = PlantKind::kSwing;  ///< whose quantity the expression is
  /// The expression's parameters (name, unit, value) at the start values.
  KneeExpressionParams startLaw() const;
};

/// Throws std::invalid_argument if `effect` has a library effect's name on `plant`, no
/// parameter, or bounds that are not finite and ordered with the start within them.
void checkUserEffect(const UserEffect& effect, PlantKind plant);
/// The descriptor a user's effect is registered with: its sentence names `quantity` and the
/// expression; its parameters carry their units; no grid.
EffectDescriptor describeUserEffect(const UserEffect& effect, PlantKind plant, const std::string& quantity);
/// The bounded parameter of a fit for parameter `j` (its typical size a tenth of its largest
/// bound or start, for the difference step).
BoundedParameter userEffectBound(const UserEffect& effect, std::size_t j);

/// The records of registered users' effects of one plant, by id. Append-only: a record handed
/// out stays valid. Thread-safe.
template <class Record>
class UserRecordRegistry {
 public:
  /// Adds `make()` as the record of `id`, unless `id` has one.
  template <class Make>
  void add(EffectId id, Make make) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& e : entries_)
      if (e.first == id) return;
    entries_.emplace_back(id, make());
  }
  /// The record of `id`; nullptr if it has none.
  const Record* find(EffectId id) const {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& e : entries_)
      if (e.first == id) return &e.second;
    return nullptr;
  }

 private:
  mutable std::mutex mutex_;
  std::deque<std::pair<EffectId, Record>> entries_;
};

}  // namespace swingsim
