#include "swing/knee_climb.h"

#include <algorithm>
#include <cmath>

namespace swingsim {

KneeClimb::KneeClimb(const KneeLaw& law) { collect(law); }

void KneeClimb::collect(const KneeLaw& law) {
  if (const auto* sum = dynamic_cast<const KneeLawSum*>(&law)) {
    for (std::size_t i = 0; i < sum->size(); ++i) collect(sum->part(i));
    return;
  }
  if (const auto* stop = dynamic_cast<const JointStop*>(&law)) {
    if (stop_ == nullptr) {
      stop_ = stop;
      return;
    }
  }
  if (law.numStates() == 0) {
    others_.push_back(&law);
    othersPassive_ = othersPassive_ && law.isPassive();
  }
}

double KneeClimb::calcOtherMoment(double flexion, double rate) const {
  double m = 0;
  for (const KneeLaw* part : others_) m += part->calcMoment({flexion, rate}, nullptr);
  return m;
}

bool KneeClimb::canReach(double flexion, double rate, double edge, double mu, double hold, double trusted) const {
  if (!(flexion < edge)) return true;
  double energy = 0.5 * rate * rate + (stop_ ? mu * stop_->calcJointStoredEnergy(flexion) : 0.0);
  if (othersPassive_) {
    // Passive other parts give back at most what they store: with it, losing the trusted
    // hold all the way is the cheap answer most step ends get.
    double stored = 0;
    for (const KneeLaw* part : others_) stored += part->calcStoredEnergy({flexion, rate}, nullptr);
    if (energy + mu * stored < trusted * hold * (edge - flexion)) return false;
  }
  const auto slope = [&](double q, double e) {
    const double m = calcOtherMoment(q, std::sqrt(2 * std::max(e, 0.0)));
    return -trusted * hold + mu * (trusted * std::min(m, 0.0) + std::max(m, 0.0));
  };
  const int steps = std::max(1, static_cast<int>(std::ceil((edge - flexion) / kClimbStep)));
  const double dq = (edge - flexion) / steps;
  double q = flexion;
  for (int i = 0; i < steps; ++i) {
    const double half = energy + 0.5 * dq * slope(q, energy);
    energy += dq * slope(q + 0.5 * dq, half);
    q += dq;
    if (!(energy > 0)) return false;
  }
  return true;
}

}  // namespace swingsim
