// The pneumatic cylinder against closed forms: Boyle's law with the valves shut, the
// valves' exponential relaxation at a held angle, and its energy: the stored energy's slope
// is the moment, and the valves only ever take energy out.
#include "knee/pneumatic_cylinder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/units.h"

namespace swingsim {
namespace {

PneumaticCylinderParams defaults() { return PneumaticCylinderParams{}; }

KneeKinematics at(double flexionDeg, double rateDegS = 0) {
  KneeKinematics k;
  k.flexion = flexionDeg * kDegToRad;
  k.flexionRate = rateDegS * kDegToRad;
  return k;
}

TEST(PneumaticCylinder, ShutValvesFollowBoylesLaw) {
  const PneumaticCylinderParams p = defaults();
  const PneumaticCylinder law(p);
  const double area = kPi * p.bore * p.bore / 4;
  for (double deg : {-5.0, 0.0, 30.0, 60.0, 120.0}) {
    const double travel = p.leverArm * deg * kDegToRad;
    const double pressure = p.ambientPressure * p.chamberLength / (p.chamberLength - travel);  // p V = p_a V0
    const double expected = -(pressure - p.ambientPressure) * area * p.leverArm;
    const double z = 1;
    EXPECT_NEAR(law.calcMoment(at(deg), &z), expected, 1e-12 * std::abs(expected) + 1e-15) << deg;
  }
  const double z = 1;
  EXPECT_LT(law.calcMoment(at(60), &z), -1.0);  // resists flexion by newton metres
  EXPECT_NEAR(law.calcMoment(at(0), &z), 0, 1e-15);
}

TEST(PneumaticCylinder, ValvesRelaxThePressureExponentially) {
  // With equal valve times the handover does not matter: at a held angle the pressure
  // ratio's excess decays as exp(-t / (tau c)), c = V / V0.
  PneumaticCylinderParams p = defaults();
  p.flexionValveTime = p.extensionValveTime = 0.04;
  const PneumaticCylinder law(p);
  const KneeKinematics knee = at(50);
  const double c = 1 - p.leverArm * knee.flexion / p.chamberLength;
  double z = 1, t = 0;
  const double h = 1e-5, end = 0.05;
  auto f = [&](double zz) {
    double d = 0;
    law.calcStateDerivatives(knee, &zz, &d);
    return d;
  };
  while (t < end - 1e-12) {  // classical Runge-Kutta
    const double k1 = f(z), k2 = f(z + h / 2 * k1), k3 = f(z + h / 2 * k2), k4 = f(z + h * k3);
    z += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    t += h;
  }
  const double excess0 = 1 / c - 1;
  EXPECT_NEAR(law.calcPressureRatio(knee.flexion, z) - 1, excess0 * std::exp(-end / (0.04 * c)), 1e-10);
}

TEST(PneumaticCylinder, StoredEnergyIsTheMomentsPotentialAndTheValvesDissipate) {
  const PneumaticCylinder law(defaults());
  for (double z : {0.8, 1.0, 1.3}) {
    for (double deg : {10.0, 45.0, 90.0}) {
      // dPhi/dtheta at fixed gas content = -M (central difference).
      const double h = 1e-6;
      const double dPhi =
          (law.calcStoredEnergy(at(deg + h * kRadToDeg), &z) - law.calcStoredEnergy(at(deg - h * kRadToDeg), &z)) /
          (2 * h);
      const double m = law.calcMoment(at(deg), &z);
      EXPECT_NEAR(dPhi, -m, 1e-6 * std::abs(m) + 1e-9) << "z " << z << " deg " << deg;
      // dPhi/dz * dz/dt <= 0: the valves never give energy back.
      double zdot = 0;
      law.calcStateDerivatives(at(deg), &z, &zdot);
      const double dz = 1e-7;
      const double zp = z + dz, zm = z - dz;
      const double dPhiDz = (law.calcStoredEnergy(at(deg), &zp) - law.calcStoredEnergy(at(deg), &zm)) / (2 * dz);
      EXPECT_LE(dPhiDz * zdot, 1e-12) << "z " << z << " deg " << deg;
      EXPECT_GE(law.calcStoredEnergy(at(deg), &z), 0);
    }
  }
  EXPECT_TRUE(law.isPassive());
}

TEST(PneumaticCylinder, RefusesAChamberThePistonWouldReach) {
  PneumaticCylinderParams p = defaults();
  p.chamberLength = p.leverArm * 2.0;  // the piston reaches the end at 115 deg
  EXPECT_THROW(PneumaticCylinder{p}, std::invalid_argument);
  p = defaults();
  p.flexionValveTime = 0;
  EXPECT_THROW(PneumaticCylinder{p}, std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
