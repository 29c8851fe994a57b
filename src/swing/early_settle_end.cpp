#include "swing/early_settle_end.h"

#include "swing/settle_dwell.h"

namespace swingsim {

bool isSettled(const StepEnd& e, const KneeClimb& climb, double edge, double mu, double freeAcceleration) {
  if (!(e.knee < edge && e.kneeRate >= 0)) return false;
  if (!(freeAcceleration < 0)) return false;
  return !climb.canReach(e.knee, e.kneeRate, edge, mu, -freeAcceleration, kHoldFraction);
}

EarlySettleEnd::EarlySettleEnd(const SwingSetup& setup, const SwingOptions& options, const KneeClimb& climb,
                               bool fastPath, int nu)
    : hipMoment_(setup.participant.hipMoment),
      climb_(climb),
      allowed_(options.earlySettleEnd && fastPath && !options.trackImpactEnergy && climb.getStop() != nullptr &&
               climb.getStop()->params().lower < setup.participant.swingEnd.zoneOfStability &&
               setup.participant.drive != SwingDrive::kThighKinematics && nu == 2),
      edge_(setup.participant.swingEnd.zoneOfStability - kLooseDwellMargin),
      unitKneeForce_(nu, 0.0) {
  unitKneeForce_[1] = 1.0;
}

bool EarlySettleEnd::isDecided(const StepEnd& now, const SimTK::State& s, const LegModel& leg, const SwingLog& log) {
  if (!(!log.ended && allowed_ && log.candidate && now.t == s.getTime() && now.knee < edge_ && now.kneeRate >= 0))
    return false;
  // The knee's acceleration per unit knee moment (mu) and per unit hip moment (nu), thigh
  // free: the knee column of M^-1 (symmetric).
  leg.getMatter().multiplyByMInv(s, unitKneeForce_, kneeResponse_);
  const double mu = kneeResponse_[1], nu = kneeResponse_[0];
  // Without the knee laws, under the hip moment still to come that holds it least.
  const auto [hipLow, hipHigh] = hipMoment_.calcRangeFrom(now.t);
  const double hipNow = hipMoment_.calcMoment(now.t);
  const double freeAcceleration = now.kneeAcc - mu * now.kneeMoment + nu * ((nu > 0 ? hipHigh : hipLow) - hipNow);
  return isSettled(now, climb_, edge_, mu, freeAcceleration);
}

}  // namespace swingsim
