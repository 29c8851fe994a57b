#include "knee/pneumatic_cylinder.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace swingsim {

namespace {
constexpr double kMinVolumeFraction = 0.02;  // V / V0 below this is held there (a piston at its end)
}  // namespace

PneumaticCylinder::PneumaticCylinder(PneumaticCylinderParams params) : p_(params) {
  const auto positive = [](double v, const char* what) {
    if (!(v > 0) || !std::isfinite(v))
      throw std::invalid_argument(std::string("pneumatic cylinder: ") + what + " must be positive");
  };
  positive(p_.bore, "the bore");
  positive(p_.leverArm, "the lever arm");
  positive(p_.chamberLength, "the chamber length");
  positive(p_.flexionValveTime, "the flexion valve time");
  positive(p_.extensionValveTime, "the extension valve time");
  positive(p_.ambientPressure, "the ambient pressure");
  positive(p_.valveSwitchWidth, "the valve switch width");
  if (!(p_.chamberLength > p_.leverArm * PneumaticCylinderParams::kFullFlexion))
    throw std::invalid_argument(
        "pneumatic cylinder: the chamber must be longer than the piston travels to 150 deg of flexion");
}

double PneumaticCylinder::area() const { return kPi * p_.bore * p_.bore / 4; }

double PneumaticCylinder::volumeFraction(double flexion) const {
  return std::max(1.0 - p_.leverArm * flexion / p_.chamberLength, kMinVolumeFraction);
}

double PneumaticCylinder::calcPressureRatio(double flexion, double gasContent) const {
  return gasContent / volumeFraction(flexion);
}

double PneumaticCylinder::calcMoment(const KneeKinematics& knee, const double* z) const {
  return -p_.ambientPressure * area() * p_.leverArm * (calcPressureRatio(knee.flexion, z[0]) - 1);
}

void PneumaticCylinder::calcStateDerivatives(const KneeKinematics& knee, const double* z, double* zdot) const {
  const double excess = calcPressureRatio(knee.flexion, z[0]) - 1;
  const double out = 1 / p_.flexionValveTime, in = 1 / p_.extensionValveTime;
  const double rate = 0.5 * (out + in) + 0.5 * (out - in) * std::tanh(excess / p_.valveSwitchWidth);
  zdot[0] = -excess * rate;
}

double PneumaticCylinder::calcStoredEnergy(const KneeKinematics& knee, const double* z) const {
  const double ratio = std::max(calcPressureRatio(knee.flexion, z[0]), 1e-300);
  const double volume = area() * p_.chamberLength * volumeFraction(knee.flexion);
  return p_.ambientPressure * volume * (ratio * std::log(ratio) - ratio + 1);
}

std::unique_ptr<KneeLaw> PneumaticCylinder::clone() const { return std::make_unique<PneumaticCylinder>(*this); }

}  // namespace swingsim
