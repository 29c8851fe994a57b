#include "knee/joint_stop.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace swingsim {

JointStop::JointStop(JointStopParams params) : p_(params) {
  if (!(p_.upper > p_.lower)) throw std::invalid_argument("joint stop: upper limit must exceed lower limit");
  if (!(p_.stiffness > 0)) throw std::invalid_argument("joint stop: stiffness must be positive");
  if (!(p_.dissipation >= 0)) throw std::invalid_argument("joint stop: dissipation must not be negative");
}

double JointStop::calcJointMoment(double angle, double rate) const {
  if (angle < p_.lower) {
    const double p = p_.lower - angle;
    const double pdot = -rate;
    return std::max(0.0, p_.stiffness * p * std::sqrt(p) * (1.0 + 1.5 * p_.dissipation * pdot));
  }
  if (angle > p_.upper) {
    const double p = angle - p_.upper;
    const double pdot = rate;
    return -std::max(0.0, p_.stiffness * p * std::sqrt(p) * (1.0 + 1.5 * p_.dissipation * pdot));
  }
  return 0.0;
}

}  // namespace swingsim
