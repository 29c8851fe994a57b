#include "knee/knee_added_effects.h"

#include <cmath>
#include <stdexcept>

namespace swingsim {

KneeAddedEffects::KneeAddedEffects(const KneeAddedEffectsParams& params) : p_(params) {
  if (!std::isfinite(p_.coulombMoment) || !std::isfinite(p_.viscousDamping) || !std::isfinite(p_.assistStiffness))
    throw std::invalid_argument("added knee effects: moments, damping and stiffness must be finite");
  if (!(p_.coulombSmoothingRate > 0) || !std::isfinite(p_.coulombSmoothingRate))
    throw std::invalid_argument("added knee effects: friction smoothing rate must be > 0 rad/s");
}

double KneeAddedEffects::calcMoment(const KneeKinematics& knee, const double* /*z*/) const {
  return -p_.coulombMoment * std::tanh(knee.flexionRate / p_.coulombSmoothingRate) -
         p_.viscousDamping * knee.flexionRate - p_.assistStiffness * knee.flexion;
}

void addKneeExpressionLaws(KneeLawSum& law, const KneeAddedEffectsParams& params) {
  for (const auto& x : params.expressions) law.add(std::make_unique<KneeExpressionMoment>(x));
}

ScaledKneeLaw::ScaledKneeLaw(const KneeLaw& law, double scale) : law_(law.clone()), scale_(scale) {
  if (!std::isfinite(scale)) throw std::invalid_argument("scaled knee law: scale must be finite");
}

}  // namespace swingsim
