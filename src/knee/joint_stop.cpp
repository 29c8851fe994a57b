#include "knee/joint_stop.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace swingsim {

JointStop::JointStop(JointStopParams params) : p_(params) {
  if (p_.upper && !(*p_.upper > p_.lower))
    throw std::invalid_argument("joint stop: upper limit must exceed lower limit");
  if (!(p_.stiffness > 0)) throw std::invalid_argument("joint stop: stiffness must be positive");
  if (!(p_.restitution >= 0 && p_.restitution <= 1))
    throw std::invalid_argument("joint stop: restitution must be in [0, 1]");
  if (!(p_.switchRate > 0)) throw std::invalid_argument("joint stop: switch rate must be positive");
}

double JointStop::calcPushingMoment(double p, double pdot) const {
  const double unloading = 0.5 * (1.0 - std::tanh(pdot / p_.switchRate));
  const double e2 = p_.restitution * p_.restitution;
  return p_.stiffness * p * std::sqrt(p) * (1.0 - (1.0 - e2) * unloading);
}

double JointStop::calcJointMoment(double angle, double rate) const {
  if (angle < p_.lower) return calcPushingMoment(p_.lower - angle, -rate);
  if (p_.upper && angle > *p_.upper) return -calcPushingMoment(angle - *p_.upper, rate);
  return 0.0;
}

double JointStop::calcJointStoredEnergy(double angle) const {
  const double p = angle < p_.lower ? p_.lower - angle : p_.upper && angle > *p_.upper ? angle - *p_.upper : 0.0;
  const double e2 = p_.restitution * p_.restitution;
  return 0.5 * (1.0 + e2) * p_.stiffness * p * p * std::sqrt(p) / 2.5;
}

}  // namespace swingsim
