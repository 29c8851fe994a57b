#include "knee/knee_geometry.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace swingsim {

KneeGeometry::KneeGeometry(KneeGeometryParams params) : p_(params) {
  if (!(std::isfinite(p_.ab) && p_.ab > 0) || !(std::isfinite(p_.ac) && p_.ac > 0))
    throw std::invalid_argument("KneeGeometry: ab and ac must be positive lengths in m (got ab = " +
                                std::to_string(p_.ab) + ", ac = " + std::to_string(p_.ac) + ")");
  if (p_.ab == p_.ac) throw std::invalid_argument("KneeGeometry: ab must differ from ac (bc would reach 0)");
  length0_ = calcCylinderLength(0.0);
}

double KneeGeometry::calcCylinderLength(double theta) const {
  // Chien 2014 Eq. 1, with cos(90 deg - theta) = sin(theta).
  return std::sqrt(p_.ac * p_.ac + p_.ab * p_.ab - 2.0 * p_.ac * p_.ab * std::sin(theta));
}

double KneeGeometry::calcLengthDerivative(double theta) const {
  return -p_.ac * p_.ab * std::cos(theta) / calcCylinderLength(theta);
}

double KneeGeometry::calcPistonPosition(double theta) const { return length0_ - calcCylinderLength(theta); }

double KneeGeometry::calcMomentArm(double theta) const { return -calcLengthDerivative(theta); }

double KneeGeometry::calcPistonVelocity(double theta, double thetaDot) const { return calcMomentArm(theta) * thetaDot; }

double KneeGeometry::calcFlexion(double x) const {
  const double bc = length0_ - x;
  const double s = (p_.ac * p_.ac + p_.ab * p_.ab - bc * bc) / (2.0 * p_.ac * p_.ab);
  if (!(bc > 0) || !(s >= -1.0 && s <= 1.0))
    throw std::domain_error("KneeGeometry: piston position " + std::to_string(x) + " m is out of reach");
  return std::asin(s);
}

}  // namespace swingsim
