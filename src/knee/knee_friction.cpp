#include "knee/knee_friction.h"

#include <cmath>
#include <stdexcept>

namespace swingsim {

KneeFriction::KneeFriction(KneeFrictionParams params) : p_(params) {
  if (!(p_.frictionMoment >= 0) || !std::isfinite(p_.frictionMoment))
    throw std::invalid_argument("knee friction: Tc must be finite and not negative");
  if (!(p_.angleWidth > 0) || !(p_.smoothingRate > 0))
    throw std::invalid_argument("knee friction: smoothing widths must be positive");
}

double KneeFriction::calcGate(double flexion) const {
  return 0.5 * (1.0 - std::tanh((flexion - p_.activeBelow) / p_.angleWidth));
}

double KneeFriction::calcMoment(const KneeKinematics& knee, const double*) const {
  return -p_.frictionMoment * calcGate(knee.flexion) * std::tanh(knee.flexionRate / p_.smoothingRate);
}

}  // namespace swingsim
