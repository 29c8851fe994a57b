#include "swing/early_thigh_failure.h"

#include <cmath>
#include <limits>
#include <vector>

namespace swingsim {

namespace {

// The hip moment is constant from the profile's last breakpoint on.
double calcConstantFrom(const HipMomentProfile& hipMoment) {
  const std::vector<double> breakpoints = hipMoment.calcBreakpoints();
  return breakpoints.empty() ? 0.0 : breakpoints.back();
}

}  // namespace

EarlyThighFailure::EarlyThighFailure(const SwingSetup& setup, const SwingOptions& options, bool fastPath)
    : setup_(setup),
      allowed_(options.earlyThighFailure && fastPath && setup.participant.drive != SwingDrive::kThighKinematics &&
               setup.knee->isPassive() && !setup.participant.socket),
      hipMomentConstantFrom_(calcConstantFrom(setup.participant.hipMoment)),
      hipMomentFinal_(setup.participant.hipMoment.calcMoment(hipMomentConstantFrom_ + 1.0)),
      thighTargetEnergy_(std::numeric_limits<double>::quiet_NaN()) {}

void EarlyThighFailure::check(const StepEnd& now, const SimTK::State& s, const LegModel& leg, bool thighReached) {
  const Participant& p = setup_.participant;
  const double target = p.swingEnd.thighTargetFlexion;
  if (!(allowed_ && !thighReached && now.t >= hipMomentConstantFrom_ && now.t == s.getTime() && now.hip < target &&
        now.hip > p.hipRange.minFlexion && now.hip < p.hipRange.maxFlexion))
    return;
  if (std::isnan(thighTargetEnergy_))
    thighTargetEnergy_ = leg.calcLeastPotentialEnergy(target) - hipMomentFinal_ * target;
  const double energy = leg.calcMechanicalEnergy(s) +
                        setup_.knee->calcStoredEnergy({now.knee, now.kneeRate}, leg.getKneeLawStates(s)) -
                        hipMomentFinal_ * now.hip;
  if (energy < thighTargetEnergy_ - kUnreachableEnergyMargin) shortfall_ = thighTargetEnergy_ - energy;
}

}  // namespace swingsim
