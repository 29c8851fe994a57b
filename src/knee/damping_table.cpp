#include "knee/damping_table.h"

#include "numerics/monotone_cubic.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace swingsim {

DampingTable::DampingTable(DampingTableParams params) : p_(std::move(params)) {
  if (p_.flexion.size() < 2 || p_.flexion.size() != p_.moment.size())
    throw std::invalid_argument("damping table: need at least 2 angles and one moment per angle");
  for (std::size_t i = 1; i < p_.flexion.size(); ++i)
    if (!(p_.flexion[i] > p_.flexion[i - 1]))
      throw std::invalid_argument("damping table: flexion angles must strictly increase");
  for (double m : p_.moment)
    if (!(m >= 0) || !std::isfinite(m))
      throw std::invalid_argument("damping table: moments must be finite and not negative");
  if (!(p_.referenceRate > 0)) throw std::invalid_argument("damping table: reference speed must be positive");
  if (!(p_.extensionFactor >= 0)) throw std::invalid_argument("damping table: extension factor must not be negative");
  if (!(p_.smoothingRate > 0)) throw std::invalid_argument("damping table: smoothing rate must be positive");
}

double DampingTable::calcTableMoment(double flexion) const {
  return interpolateMonotoneCubic(p_.flexion, p_.moment, flexion, MonotoneCubicEnds::kFlat);
}

double DampingTable::calcMoment(const KneeKinematics& knee, const double*) const {
  const double magnitude = calcTableMoment(knee.flexion);
  const double factor = knee.flexionRate < 0 ? p_.extensionFactor : 1.0;
  if (p_.speedRule == DampingSpeedRule::kLinear) {
    return -factor * magnitude * knee.flexionRate / p_.referenceRate;
  }
  return -factor * magnitude * std::tanh(knee.flexionRate / p_.smoothingRate);
}

}  // namespace swingsim
