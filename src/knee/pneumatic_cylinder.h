#pragma once
// A pneumatic swing-control knee: an air cylinder whose piston the knee drives (flexion
// compresses the chamber) and whose air leaks to the ambient through a flexion valve (out)
// and an extension valve (in). The compressed air resists flexion and gives some of its
// work back in extension; the valves dissipate. Docs: docs/formats.md "Knee model,
// pneumatic".
//
// Isothermal ideal gas (the chamber's wall exchanges heat faster than a swing, an
// assumption: Tsai & Mansour 1986 modelled the controller's thermodynamics in full). With
// x = r theta the piston's travel, L0 the air column at full extension and A the piston's
// area, the chamber's volume is V = A (L0 - r theta). The state is the chamber's gas content
// z = n / n0, n0 the gas that fills V(0) at ambient pressure p_a; the pressure ratio is
// pi = p / p_a = z L0 / (L0 - r theta). Then
//   M = -(p - p_a) A r = -p_a A r (pi - 1)            (knee moment, flexion +)
//   dz/dt = -(pi - 1) / tau(pi)                       (laminar valve flow)
// with tau = tau_f while air leaves (pi > 1) and tau_e while it enters, blended by
// tanh((pi - 1) / w). The gas holds Phi = p_a V (pi ln pi - pi + 1) >= 0, and
// dPhi/dt = -M theta_dot + p_a V0 ln(pi) dz/dt, whose last term is never positive: the law
// is passive.
#include <memory>
#include <string>

#include "core/units.h"
#include "knee/knee_law.h"

namespace swingsim {

struct PneumaticCylinderParams {
  double bore = 0.035;               ///< m, the piston's diameter (> 0)
  double leverArm = 0.035;           ///< r, m: piston travel per radian of knee flexion (> 0)
  double chamberLength = 0.11;       ///< L0, m: the air column at full extension (> r x 150 deg)
  double flexionValveTime = 0.05;    ///< tau_f, s: air leaving (> 0)
  double extensionValveTime = 0.02;  ///< tau_e, s: air entering (> 0)
  double ambientPressure = 101325;   ///< p_a, Pa (> 0)
  double valveSwitchWidth = 0.01;    ///< w: pressure ratio over which the valves hand over (> 0)
  /// The knee flexion the chamber must allow, rad: the piston may not reach the chamber's end
  /// before it (150 deg, a knee's full flexion).
  static constexpr double kFullFlexion = 150 * kDegToRad;
};

/// The pneumatic cylinder as a knee law. One state: the gas content z (1 at rest at full
/// extension; the knee flexed before toe-off without the time to leak, an assumption).
/// Throws std::invalid_argument on bad params.
class PneumaticCylinder final : public KneeLaw {
 public:
  explicit PneumaticCylinder(PneumaticCylinderParams params);
  const PneumaticCylinderParams& params() const { return p_; }

  std::string name() const override { return "pneumatic cylinder"; }
  int numStates() const override { return 1; }
  void initialStates(double* z) const override { z[0] = 1.0; }
  double calcMoment(const KneeKinematics& knee, const double* z) const override;
  void calcStateDerivatives(const KneeKinematics& knee, const double* z, double* zdot) const override;
  bool isPassive() const override { return true; }
  /// Phi = p_a V (pi ln pi - pi + 1), J: what the compressed (or rarefied) air can give back.
  double calcStoredEnergy(const KneeKinematics& knee, const double* z) const override;
  std::unique_ptr<KneeLaw> clone() const override;

  /// pi = p / p_a at this knee angle and gas content.
  double calcPressureRatio(double flexion, double gasContent) const;

 private:
  double area() const;
  /// (L0 - r theta) / L0, floored far from zero so that a knee driven past the chamber's
  /// end gives a large but finite pressure.
  double volumeFraction(double flexion) const;
  PneumaticCylinderParams p_;
};

}  // namespace swingsim
