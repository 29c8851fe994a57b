#pragma once
// A smooth, dissipative joint limit (Hunt & Crossley 1975 contact law applied to a joint
// angle). Used for the knee's hyperextension stop (Burkett 2004: a corrective flexion
// moment keeps the knee within 4 deg of full extension) and the hip's physiological range.
#include "knee/knee_law.h"

namespace swingsim {

struct JointStopParams {
  double lower = 0;  ///< angle where the lower stop engages, rad
  double upper = 1e9;  ///< angle where the upper stop engages, rad (huge = none)
  /// k in M = k p^1.5 (1 + 1.5 c pdot); N m / rad^1.5.
  double stiffness = 2.0e4;
  /// c, s/rad: the Hunt-Crossley dissipation (restitution ~ 1 - c v / 1.5 for small c v).
  double dissipation = 0.3;
};

/// Moment M = k p^1.5 (1 + 1.5 c pdot), p = penetration beyond the limit, pdot its rate,
/// and never negative (a stop pushes, it never pulls, so nothing sticks on release).
/// Continuous at contact: both terms vanish at p = 0.
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
  std::unique_ptr<KneeLaw> clone() const override { return std::make_unique<JointStop>(*this); }

 private:
  JointStopParams p_;
};

}  // namespace swingsim
