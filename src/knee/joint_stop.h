#pragma once
// A smooth joint limit with a stated coefficient of restitution. Used for the knee's
// hyperextension stop (Burkett 2004: a corrective flexion moment keeps the knee within
// 4 deg of full extension) and the hip's physiological range.
//
// Law: a Hertz spring k p^1.5 while the joint moves into the stop, e^2 k p^1.5 while it
// comes out (a loading-unloading hysteresis, the idea of Walton & Braun 1986, J. Rheol.
// 30:949, who unload a linear contact with a stiffer spring; here the unloading spring is
// weaker so that it returns e^2 of the stored energy). The exit speed is then e times the
// impact speed whatever the speed and the inertia behind the joint (a Hunt-Crossley damping
// c p^1.5 pdot, used before, returns e = 0.49 at c v = 1 but 0.13 at c v = 5: Simbody
// HuntCrossleyForce integrated alone: docs/assumptions.md). The switch between the two
// springs is a tanh in the penetration rate, so the moment is smooth for the integrator.
#include <optional>

#include "knee/knee_law.h"

namespace swingsim {

struct JointStopParams {
  double lower = 0;             ///< angle where the lower stop engages, rad
  std::optional<double> upper;  ///< angle where the upper stop engages, rad; absent: no upper stop
  /// k in M = k p^1.5, N m / rad^1.5. 2e4 keeps the overshoot of a 0.2 kg m^2 shank hitting
  /// at 8 rad/s at 3.3 deg, within Burkett 2004's "within 4 deg of full extension"
  /// (p = (1.25 I v^2 / k)^0.4); no published bumper stiffness exists (docs/assumptions.md), so
  /// the plausible range is 1.25e4 (4 deg at that impact) to 5e4.
  double stiffness = 2.0e4;
  /// e, the coefficient of restitution: exit speed / impact speed of a single impact, in
  /// [0, 1]. No bumper restitution is published (docs/assumptions.md); the prior is 0.3-0.5 at
  /// swing impact speeds, nominal 0.4 (the middle), chosen before any comparison with Burkett
  /// Table 4.
  double restitution = 0.4;
  /// w, rad/s: the penetration rate over which the law switches from the loading to the
  /// unloading spring (tanh). Far below impact speeds (0.5-10 rad/s), so the restitution
  /// holds within 5 % there (tests/knee/joint_stop_test.cpp); larger makes it speed-dependent,
  /// smaller makes the equations stiff at the turn.
  double switchRate = 0.05;
};

/// Moment M = k p^1.5 (1 - (1 - e^2) r), r = (1 - tanh(pdot / w)) / 2, p = penetration
/// beyond the limit, pdot its rate (r -> 0 going in, 1 coming out). Never negative (a stop
/// pushes, it never pulls) and continuous at contact (M = 0 at p = 0).
class JointStop final : public KneeLaw {
 public:
  explicit JointStop(JointStopParams params);
  const JointStopParams& params() const { return p_; }
  /// Moment on the joint coordinate (positive = increasing angle).
  double calcJointMoment(double angle, double rate) const;

  std::string name() const override { return "hyperextension stop"; }
  double calcMoment(const KneeKinematics& knee, const double*) const override {
    return calcJointMoment(knee.flexion, knee.flexionRate);
  }
  /// Passive with the stored energy below.
  bool isPassive() const override { return true; }
  /// (1 + e^2) / 2 k p^2.5 / 2.5, the energy of the spring midway between loading and
  /// unloading: the moment exceeds that spring's exactly when the penetration grows (r < 1/2
  /// for pdot > 0), so the stop's power into the leg plus this energy's rate,
  /// -(1 - e^2) k p^1.5 (1/2 - r) pdot, is never positive.
  double calcStoredEnergy(const KneeKinematics& knee, const double*) const override {
    return calcJointStoredEnergy(knee.flexion);
  }
  /// The stored energy at a joint angle, J.
  double calcJointStoredEnergy(double angle) const;
  std::unique_ptr<KneeLaw> clone() const override { return std::make_unique<JointStop>(*this); }

 private:
  // The moment pushing out of the stop at penetration p > 0 and penetration rate pdot.
  double calcPushingMoment(double p, double pdot) const;
  JointStopParams p_;
};

}  // namespace swingsim
