#pragma once
// Knee unit friction near extension (Burkett 2004: friction Tc of Table 2 applied when
// the knee angle is below 4 deg).
#include "core/units.h"
#include "knee/knee_law.h"

namespace swingsim {

struct KneeFrictionParams {
  double frictionMoment = 0;             ///< Tc, N m, >= 0 (Burkett Table 2)
  double activeBelow = 4.0 * kDegToRad;  ///< flexion, rad
  /// Width of the smooth switch-off around activeBelow, rad.
  double angleWidth = 0.5 * kDegToRad;
  /// Velocity smoothing: moment = -Tc tanh(rate / smoothingRate). Chosen by the
  /// convergence study (docs/speed.md, "Convergence study"); smaller makes the equations stiff.
  double smoothingRate = 1.0;  ///< rad/s
};

/// Coulomb friction, smooth in velocity (tanh) and in angle (tanh step at activeBelow),
/// so the integrator never meets a discontinuity and the knee never chatters.
class KneeFriction final : public KneeLaw {
 public:
  explicit KneeFriction(KneeFrictionParams params);
  const KneeFrictionParams& params() const { return p_; }
  /// The angle gate in [0, 1]: 1 well below activeBelow, 0 well above.
  double calcGate(double flexion) const;

  std::string name() const override { return "knee friction"; }
  double calcMoment(const KneeKinematics& knee, const double* z) const override;
  /// Passive: Tc >= 0 (checked by the constructor) and the gate is positive.
  bool isPassive() const override { return true; }
  std::unique_ptr<KneeLaw> clone() const override { return std::make_unique<KneeFriction>(*this); }

 private:
  KneeFrictionParams p_;
};

}  // namespace swingsim
