#include "swing/run_error_text.h"

#include <cmath>
#include <cstdio>

namespace swingsim {

using namespace SimTK;

namespace {

// An angle for a message: rad in, degrees rounded to 0.1 out.
std::string formatDegrees(double rad) { return formatNumber(std::round(rad * kRadToDeg * 10) / 10); }

// A time (s) or an energy (J) for a message, rounded to 4 decimal places.
std::string formatTo4Places(double t) { return formatNumber(std::round(t * 1e4) / 1e4); }

}  // namespace

std::string describeState(const LegModel& leg, const State& s) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "at t = %.4f s: hip flexion %.1f deg (%.0f deg/s), knee flexion %.1f deg (%.0f deg/s)",
                s.getTime(), leg.getHipFlexion(s) * kRadToDeg, leg.getHipFlexionRate(s) * kRadToDeg,
                leg.getKneeFlexion(s) * kRadToDeg, leg.getKneeFlexionRate(s) * kRadToDeg);
  return buf;
}

RunErrorText::RunErrorText(const SwingSetup& setup, const SwingOptions& options, const LegModel& leg, double timeLimit)
    : setup_(setup), options_(options), leg_(leg), timeLimit_(timeLimit) {}

std::string RunErrorText::who() const {
  return setup_.participant.name + " at lowering " + formatNumber(setup_.lowering) + " m";
}

RunError RunErrorText::integratorFailed(const State& s, const std::exception& e) const {
  return RunError(setup_.participant.name + ": the integrator failed " + describeState(leg_, s) +
                  " (likely cause: a knee or hip law too stiff for the accuracy, or an unphysical input; " + e.what() +
                  ")");
}

RunError RunErrorText::overBudget(RunBudget::Spent spent, int realizations, const State& s) const {
  const std::string what = spent == RunBudget::Spent::kRealizations
                               ? std::to_string(realizations) + " realizations (the budget of one swing is " +
                                     std::to_string(options_.maxRealizations) + "; a normal swing takes a few hundred)"
                               : formatNumber(options_.maxWallSeconds) +
                                     " s of computing (the limit for one swing; a normal swing takes milliseconds)";
  // What to change: the same advice for both budgets.
  return RunError(who() + ": the swing was stopped after " + what + " " + describeState(leg_, s) + ", with " +
                  integratorName(options_.integrator) + " at accuracy " + formatNumber(options_.accuracy) +
                  "; the knee or hip law is too stiff for this integrator at this accuracy: loosen the accuracy "
                  "(--accuracy, or accuracy: in the study; converged: " +
                  formatNumber(calcConvergedAccuracy(options_.integrator)) + "), or check the knee model " +
                  setup_.participant.kneeModelPath + " for a value far too large (a unit mistake?)");
}

RunError RunErrorText::diverged(const State& s) const {
  return RunError(setup_.participant.name + ": the simulation diverged " + describeState(leg_, s) +
                  " (likely cause: an unphysical input such as a near-zero inertia)");
}

RunError RunErrorText::hipLeftRange(const State& s) const {
  const Participant& p = setup_.participant;
  return RunError(who() + ": the hip left its range of " + formatDegrees(p.hipRange.minFlexion) + " to " +
                  formatDegrees(p.hipRange.maxFlexion) + " deg " + describeState(leg_, s) +
                  " (likely cause: a hip moment far too large for this leg, or a hip_range that excludes the swing)");
}

RunError RunErrorText::kneeLeftRange(const State& s, double crossingTime) const {
  const bool thighMotion = setup_.participant.drive == SwingDrive::kThighKinematics;
  return RunError(who() + ": the knee flexion passed " + formatDegrees(kKneeFlexionLimit) + " deg at " +
                  formatTo4Places(crossingTime) +
                  " s, beyond the knee's physical range (the shank folded onto the "
                  "thigh); the run is stopped " +
                  describeState(leg_, s) +
                  (thighMotion ? " (likely cause: a measured thigh motion far more violent than a swing's, e.g. a "
                                 "trial cut at the wrong events, or too little knee resistance for it)"
                               : " (likely cause: a hip moment far too large for this leg, or too little knee "
                                 "resistance: a knee model value far too small, a unit mistake?)"));
}

RunError RunErrorText::cannotEnd(const State& s, double hipMomentFinal, double constantFrom, double shortfall) const {
  const SwingEndRule& rule = setup_.participant.swingEnd;
  return RunError(who() + ": the swing cannot end (decided " + describeState(leg_, s) + ", before the time limit of " +
                  formatTo4Places(timeLimit_) + " s): the thigh never reached its target flexion of " +
                  formatDegrees(rule.thighTargetFlexion) +
                  " deg and cannot any more: with the hip moment constant at " + formatNumber(hipMomentFinal) +
                  " N m from t = " + formatTo4Places(constantFrom) + " s, the leg's energy is " +
                  formatTo4Places(shortfall) +
                  " J short of the least the thigh at its target needs, and the knee and the hip stop only take energy "
                  "away (hip moment too small for this leg?)");
}

RunError RunErrorText::didNotEnd(const State& s, const SwingLog& log) const {
  const SwingEndRule& rule = setup_.participant.swingEnd;
  const bool thighMotion = setup_.participant.drive == SwingDrive::kThighKinematics;
  std::string cause;
  if (!log.thighReached)
    cause = "the thigh never reached its target flexion of " + formatDegrees(rule.thighTargetFlexion) +
            (thighMotion ? " deg (set swing_end: thigh_target_flexion_deg below the measured thigh's peak)"
                         : " deg (hip moment too small for this leg?)");
  else if (!log.peakSeen)
    cause = "the knee never reached a flexion peak above the zone of stability";
  else if (log.enteredOnce)
    cause = "the knee did not settle: it left the zone of stability (< " + formatDegrees(rule.zoneOfStability) +
            " deg) " + std::to_string(log.bounces) + " times and never stayed inside it for the settle dwell of " +
            formatNumber(rule.settleDwell) + " s (a stop that returns too much of the impact, restitution near 1?)";
  else
    cause = "the knee never came back inside the zone of stability (< " + formatDegrees(rule.zoneOfStability) +
            " deg) after its peak (knee resistance too high, or the hip extension moment too weak?)";
  return RunError(who() + ": the swing did not end within the time limit of " + formatTo4Places(timeLimit_) + " s; " +
                  describeState(leg_, s) + "; " + cause);
}

}  // namespace swingsim
