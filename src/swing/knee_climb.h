#pragma once
// How high the knee can still climb out of its hyperextension stop, treated as one degree
// of freedom: the settle dwell's early end (SwingOptions::earlySettleEnd) asks whether a
// knee that rises now can get back out of the zone of stability.
//
// The knee, rising at rate w >= 0 from flexion q, has per unit inertia the energy
// E = w^2 / 2 + mu U(q), U the stop's stored energy (JointStop::calcJointStoredEnergy, the
// most it can give back). Climbing, it loses per radian the hold h (rad/s^2, what presses it
// down: the hip moment and gravity with the knee laws left out) and the work of the knee
// law's other parts at the rate the energy left gives it (Coulomb friction near extension,
// the damping table, an added assist spring):
//
//   dE/dq = -f h + mu (f min(M, 0) + max(M, 0)),   M = M(q, sqrt(2 E)),
//
// f the fraction of what holds it back that is trusted (the swing's kHoldFraction,
// swing_simulation.cpp, says why it is below 1); a part that pushes the knee up (M > 0
// while it flexes) counts whole.
// The climb is integrated in q (midpoint rule, steps of at most kClimbStep) from q to the
// edge; the knee cannot get there if E reaches 0 first.
//
// Parts with states of their own (the Mauch cylinder's latch) cannot be evaluated along a
// climb without integrating them: they are left out (taken to resist, as before this unit).
#include <vector>

#include "core/units.h"
#include "knee/joint_stop.h"
#include "knee/knee_law.h"

namespace swingsim {

class KneeClimb {
 public:
  /// Collects `law`'s hyperextension stop (the first JointStop in it, through nested sums)
  /// and its stateless other parts. `law` must outlive this object.
  explicit KneeClimb(const KneeLaw& law);

  /// The stop, or null if the law has none (then there is nothing to settle on).
  const JointStop* getStop() const { return stop_; }

  /// Whether the knee at `flexion` (rad) rising at `rate` (rad/s, >= 0) can reach `edge`
  /// (rad, above `flexion`). `mu`: knee acceleration per unit knee moment, 1/(kg m^2);
  /// `hold`: deceleration pressing the knee down, rad/s^2 (> 0); `trusted`: f in (0, 1].
  bool canReach(double flexion, double rate, double edge, double mu, double hold, double trusted) const;

  /// The climb's largest step, rad (a quarter of the friction's switch-off width, so its
  /// gate is followed; the climb is a few degrees).
  static constexpr double kClimbStep = 0.25 * kDegToRad;

 private:
  void collect(const KneeLaw& law);
  /// Sum of the other parts' moments at (flexion, rate), N m.
  double calcOtherMoment(double flexion, double rate) const;

  const JointStop* stop_ = nullptr;
  std::vector<const KneeLaw*> others_;  // stateless parts other than the stop
  bool othersPassive_ = true;           // every one of them is (KneeLaw::isPassive)
};

}  // namespace swingsim
