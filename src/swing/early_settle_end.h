#pragma once
// The early end of the settle dwell (SwingOptions::earlySettleEnd; docs/swing-options.md):
// the dwell ends as soon as the knee provably cannot leave the zone before it would end.
// Swing time, events and bounces are those of the full dwell (tests/swing/settle_dwell_test.cpp).
#include <Simbody.h>

#include "leg/leg_model.h"
#include "swing/knee_climb.h"
#include "swing/step_end.h"
#include "swing/swing_log.h"
#include "swing/swing_simulation.h"

namespace swingsim {

// Fraction of what holds the knee down that is trusted to hold it for the rest of the
// dwell (KneeClimb): the free acceleration under the least holding hip moment still to come,
// and the knee law's resisting parts. The holding moment also changes with the thigh's angle
// and rate (sin of the angle, about) over the dwell's tenths of a second, which the linear
// response to the hip moment at the present pose does not see: P1's falls by a few percent
// there. The same fraction of the knee law's resisting parts (friction, damping) is trusted:
// the knee's inertia mu^-1 below is taken at the present pose too.
constexpr double kHoldFraction = 0.5;

/// Whether the knee, at step end `e` in the zone, can no longer climb out of it. Treated as
/// one degree of freedom with the thigh free (KneeClimb): its acceleration without the knee
/// laws, `freeAcceleration` (rad/s^2; the caller takes the least holding one the hip moment
/// can still give), presses it down (< 0); the stop gives back at most its stored energy
/// (the midway spring) times mu = (M^-1)_knee,knee in 1/(kg m^2); the other parts of the
/// knee law act as they would on the way up. Decided where the knee rises or rests (rate >= 0)
/// below `edge` (rad): on the stop coming out of it, or above it.
bool isSettled(const StepEnd& e, const KneeClimb& climb, double edge, double mu, double freeAcceleration);

class EarlySettleEnd {
 public:
  /// `fastPath`: the run steps with Dormand-Prince. Off with trackImpactEnergy (the impact
  /// bookkeeping wants the whole dwell), without a stop below the zone, and with the
  /// measured thigh drive (the prescribed thigh's future is not bounded like a hip moment's),
  /// and on any leg but the two-mobility one, hip and knee at mobilities 0 and 1, that the
  /// bound is worked out for (`nu` mobilities: a compliant socket's springs add two and can
  /// give back what they hold).
  EarlySettleEnd(const SwingSetup& setup, const SwingOptions& options, const KneeClimb& climb, bool fastPath, int nu);
  bool isAllowed() const { return allowed_; }
  /// Whether the swing end candidate of `log` is decided at step end `now` (of state `s`;
  /// decided only at a true step end, not at a restored checkpoint).
  bool isDecided(const StepEnd& now, const SimTK::State& s, const LegModel& leg, const SwingLog& log);

 private:
  const HipMomentProfile& hipMoment_;
  const KneeClimb& climb_;
  bool allowed_;
  double edge_;  // rad: the zone minus the loose dwell's margin, where the dwell would be redone
  // The knee's column of M^-1 is asked for with a unit knee force (mobility 1), allocated once.
  SimTK::Vector unitKneeForce_, kneeResponse_;
};

}  // namespace swingsim
