#include "swing/swing_simulation.h"

#include <Simbody.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "io/input_error.h"
#include "leg/leg_model.h"

namespace swingsim {

using namespace SimTK;

double calcHipHeight(const Participant& p) { return 0.530 * p.height; }

namespace {

// What the event handlers have seen so far. Handlers are const (Simbody's interface), so
// they write here through a pointer.
struct SwingLog {
  std::vector<SwingEvent> events;
  bool thighReached = false;
  bool peakSeen = false;
  bool kneeInZone = false;   // inside the zone after the peak
  bool enteredOnce = false;
  bool ended = false;
  bool bounce = false;
  double endTime = 0;
  double peak = -1e9, peakTime = 0;

  void add(const std::string& name, double t) { events.push_back({name, t}); }
  void checkEnd(double t) {
    if (!ended && thighReached && kneeInZone) {
      ended = true;
      endTime = t;
      add("swing_end", t);
    }
  }
};

class LegEventHandler : public TriggeredEventHandler {
 public:
  LegEventHandler(const LegModel& leg, SwingLog& log, Stage stage, double window)
      : TriggeredEventHandler(stage), leg_(leg), log_(log) {
    getTriggerInfo().setRequiredLocalizationTimeWindow(window);
  }

 protected:
  const LegModel& leg_;
  SwingLog& log_;
};

// Thigh reaches its defined flexion position (rising through the target).
class ThighTargetHandler : public LegEventHandler {
 public:
  ThighTargetHandler(const LegModel& leg, SwingLog& log, double window, double target)
      : LegEventHandler(leg, log, Stage::Position, window), target_(target) {
    getTriggerInfo().setTriggerOnFallingSignTransition(false);
  }
  Real getValue(const State& s) const override { return leg_.getHipFlexion(s) - target_; }
  void handleEvent(State& s, Real, bool&) const override {
    if (log_.thighReached) return;
    log_.thighReached = true;
    log_.add("thigh_at_target", s.getTime());
    log_.checkEnd(s.getTime());
  }

 private:
  double target_;
};

// Knee flexion rate falls through zero: a local maximum of knee flexion.
class KneePeakHandler : public LegEventHandler {
 public:
  KneePeakHandler(const LegModel& leg, SwingLog& log, double window, double zone)
      : LegEventHandler(leg, log, Stage::Velocity, window), zone_(zone) {
    getTriggerInfo().setTriggerOnRisingSignTransition(false);
  }
  // Knee rate while the knee is above the zone; a positive constant inside it, so a knee
  // resting near extension after the swing (rate dithering about zero) does not make the
  // integrator localize a stream of meaningless sign changes.
  Real getValue(const State& s) const override {
    return leg_.getKneeFlexion(s) > zone_ ? leg_.getKneeFlexionRate(s) : 1.0;
  }
  void handleEvent(State& s, Real, bool&) const override {
    const double knee = leg_.getKneeFlexion(s);
    if (knee <= zone_ || log_.ended) return;  // wiggles inside the zone are not the swing's peak
    log_.add("knee_peak_flexion", s.getTime());
    log_.peakSeen = true;
    if (knee > log_.peak) {
      log_.peak = knee;
      log_.peakTime = s.getTime();
    }
  }

 private:
  double zone_;
};

// Knee flexion crosses the zone-of-stability boundary. One handler per direction: at the
// localized event the knee can sit on the boundary to round-off, so the direction must
// come from the trigger, not from re-reading the angle.
class KneeZoneHandler : public LegEventHandler {
 public:
  KneeZoneHandler(const LegModel& leg, SwingLog& log, double window, double zone, bool entering)
      : LegEventHandler(leg, log, Stage::Position, window), zone_(zone), entering_(entering) {
    // witness = zone - knee rises through zero when the knee enters the zone.
    getTriggerInfo().setTriggerOnRisingSignTransition(entering);
    getTriggerInfo().setTriggerOnFallingSignTransition(!entering);
  }
  Real getValue(const State& s) const override { return zone_ - leg_.getKneeFlexion(s); }
  void handleEvent(State& s, Real, bool&) const override {
    const double t = s.getTime();
    if (entering_) {
      if (!log_.peakSeen) return;  // still on the way up from toe-off
      log_.add("knee_enters_zone", t);
      log_.kneeInZone = true;
      log_.enteredOnce = true;
      log_.checkEnd(t);
    } else if (log_.enteredOnce) {
      log_.add("knee_leaves_zone", t);
      log_.kneeInZone = false;
      log_.bounce = true;
    }
  }

 private:
  double zone_;
  bool entering_;
};

std::string describeState(const LegModel& leg, const State& s) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "at t = %.4f s: hip flexion %.1f deg (%.0f deg/s), knee flexion %.1f deg (%.0f deg/s)",
                s.getTime(), leg.getHipFlexion(s) * kRadToDeg, leg.getHipFlexionRate(s) * kRadToDeg,
                leg.getKneeFlexion(s) * kRadToDeg, leg.getKneeFlexionRate(s) * kRadToDeg);
  return buf;
}

// Joint state at the end of an integrator step: angles, rates, accelerations, moments.
struct StepEnd {
  double t, hip, knee, hipRate, kneeRate, hipAcc, kneeAcc, hipMoment, kneeMoment;
};

StepEnd readStepEnd(const LegModel& leg, const State& s) {
  const MultibodySystem& system = leg.getSystem();
  system.realize(s, Stage::Acceleration);
  const Vector& udot = s.getUDot();
  // Mobility order: thigh (hip) then shank (knee); the welds have none.
  return {s.getTime(), leg.getHipFlexion(s), leg.getKneeFlexion(s), leg.getHipFlexionRate(s),
          leg.getKneeFlexionRate(s), udot[0], udot[1], leg.calcHipMoment(s), leg.calcKneeMoment(s)};
}

// Cubic Hermite on the angle (from angle and rate at both step ends) and on the rate
// (from rate and acceleration): the samples cost no extra realization, so the integrator
// chooses its steps by accuracy alone, not by the output interval.
void appendSamples(const StepEnd& a, const StepEnd& b, double& nextSample, double interval, const LegGeometry& g,
                   double hipHeight, SwingTrajectory& tr) {
  const double h = b.t - a.t;
  auto hermite = [&](double y0, double d0, double y1, double d1, double s) {
    const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
    const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
    return h00 * y0 + h10 * h * d0 + h01 * y1 + h11 * h * d1;
  };
  while (nextSample <= b.t + 1e-12 && h > 0) {
    const double s = std::clamp((nextSample - a.t) / h, 0.0, 1.0);
    const double hip = hermite(a.hip, a.hipRate, b.hip, b.hipRate, s);
    const double knee = hermite(a.knee, a.kneeRate, b.knee, b.kneeRate, s);
    tr.time.push_back(nextSample);
    tr.hipFlexion.push_back(hip);
    tr.kneeFlexion.push_back(knee);
    tr.hipFlexionRate.push_back(hermite(a.hipRate, a.hipAcc, b.hipRate, b.hipAcc, s));
    tr.kneeFlexionRate.push_back(hermite(a.kneeRate, a.kneeAcc, b.kneeRate, b.kneeAcc, s));
    tr.hipMoment.push_back(a.hipMoment + s * (b.hipMoment - a.hipMoment));
    tr.kneeMoment.push_back(a.kneeMoment + s * (b.kneeMoment - a.kneeMoment));
    const PlanarPose pose = calcPlanarPoseXY(g, hipHeight, hip, knee);
    tr.kneeX.push_back(pose.knee[0]);
    tr.kneeY.push_back(pose.knee[1]);
    tr.ankleX.push_back(pose.ankle[0]);
    tr.ankleY.push_back(pose.ankle[1]);
    tr.toeX.push_back(pose.toe[0]);
    tr.toeY.push_back(pose.toe[1]);
    nextSample += interval;
  }
}

}  // namespace

SwingResult simulateSwing(const SwingSetup& setup, const SwingOptions& options) {
  const Participant& p = setup.participant;
  if (setup.knee == nullptr) throw InputError(p.path + ": no knee model");
  const LegGeometry geometry = calcLegGeometry(p, setup.lowering, setup.added);
  LegModel leg(geometry, *setup.knee, p.hipMoment, p.hipRange, calcHipHeight(p));

  SwingLog log;
  const SwingEndRule& rule = p.swingEnd;
  MultibodySystem& system = leg.updSystem();
  system.addEventHandler(new ThighTargetHandler(leg, log, options.eventWindow, rule.thighTargetFlexion));
  system.addEventHandler(new KneePeakHandler(leg, log, options.eventWindow, rule.zoneOfStability));
  system.addEventHandler(new KneeZoneHandler(leg, log, options.eventWindow, rule.zoneOfStability, true));
  system.addEventHandler(new KneeZoneHandler(leg, log, options.eventWindow, rule.zoneOfStability, false));
  system.realizeTopology();

  State state = leg.makeInitialState(p.initial);
  RungeKuttaMersonIntegrator integrator(system);
  integrator.setAccuracy(options.accuracy);
  // Return after every internal step: the loop stops as soon as the swing end plus the
  // bounce window has passed, and samples the output by interpolation between steps.
  integrator.setReturnEveryInternalStep(true);
  integrator.setFinalTime(rule.timeLimit);
  TimeStepper stepper(system, integrator);
  stepper.setReportAllSignificantStates(true);
  stepper.initialize(state);

  SwingResult result;
  log.add("toe_off", 0.0);
  const double hipHeight = calcHipHeight(p);
  SwingTrajectory& tr = result.trajectory;
  StepEnd previous = readStepEnd(leg, integrator.getState());
  double nextSample = 0;
  {
    // The first sample, at toe-off.
    const PlanarPose pose = calcPlanarPoseXY(geometry, hipHeight, previous.hip, previous.knee);
    tr.time.push_back(0);
    tr.hipFlexion.push_back(previous.hip);
    tr.kneeFlexion.push_back(previous.knee);
    tr.hipFlexionRate.push_back(previous.hipRate);
    tr.kneeFlexionRate.push_back(previous.kneeRate);
    tr.hipMoment.push_back(previous.hipMoment);
    tr.kneeMoment.push_back(previous.kneeMoment);
    tr.kneeX.push_back(pose.knee[0]);
    tr.kneeY.push_back(pose.knee[1]);
    tr.ankleX.push_back(pose.ankle[0]);
    tr.ankleY.push_back(pose.ankle[1]);
    tr.toeX.push_back(pose.toe[0]);
    tr.toeY.push_back(pose.toe[1]);
    nextSample = options.sampleInterval;
  }

  const double stopAfterEnd = rule.bounceWindow;
  while (true) {
    Integrator::SuccessfulStepStatus status;
    try {
      status = stepper.stepTo(rule.timeLimit);
    } catch (const std::exception& e) {
      throw RunError(p.name + ": the integrator failed " + describeState(leg, integrator.getState()) +
                     " (likely cause: a knee or hip law too stiff for the accuracy, or an unphysical input; " +
                     e.what() + ")");
    }
    const State& s = integrator.getState();
    const StepEnd now = readStepEnd(leg, s);
    if (now.t > previous.t) appendSamples(previous, now, nextSample, options.sampleInterval, geometry, hipHeight, tr);
    previous = now;
    if (!std::isfinite(now.hip) || !std::isfinite(now.knee)) {
      throw RunError(p.name + ": the simulation diverged " + describeState(leg, s) +
                     " (likely cause: an unphysical input such as a near-zero inertia)");
    }
    // The hip stop is soft (Hunt-Crossley): a thigh far past it means the inputs are wrong,
    // and a swing "ending" out there would look like a result.
    constexpr double kHipRangeSlack = 2 * kDegToRad;  // rad; plausible hip moments press the stop far less
    if (now.hip < p.hipRange.minFlexion - kHipRangeSlack || now.hip > p.hipRange.maxFlexion + kHipRangeSlack) {
      const auto deg = [](double rad) { return formatNumber(std::round(rad * kRadToDeg * 10) / 10); };
      throw RunError(p.name + " at lowering " + formatNumber(setup.lowering) + " m: the hip left its range of " +
                     deg(p.hipRange.minFlexion) + " to " + deg(p.hipRange.maxFlexion) + " deg " + describeState(leg, s) +
                     " (likely cause: a hip moment far too large for this leg, or a hip_range that excludes the swing)");
    }
    if (log.ended && s.getTime() >= log.endTime + stopAfterEnd - 1e-12) break;
    if (!log.ended && (s.getTime() >= rule.timeLimit - 1e-12 || status == Integrator::EndOfSimulation)) {
      std::string cause;
      if (!log.thighReached)
        cause = "the thigh never reached its target flexion of " +
                formatNumber(rule.thighTargetFlexion * kRadToDeg) + " deg (hip moment too small for this leg?)";
      else if (!log.peakSeen)
        cause = "the knee never reached a flexion peak above the zone of stability";
      else
        cause = "the knee never came back inside the zone of stability (< " +
                formatNumber(rule.zoneOfStability * kRadToDeg) + " deg) after its peak (knee resistance too high, or the hip extension moment too weak?)";
      throw RunError(p.name + " at lowering " + formatNumber(setup.lowering) + " m: the swing did not end within the time limit of " +
                     formatNumber(rule.timeLimit) + " s; " + describeState(leg, s) + "; " + cause);
    }
    if (status == Integrator::EndOfSimulation) break;
  }
  // Lowest ankle or toe from peak knee flexion (mid-swing) to the swing end; before the
  // peak the foot is still leaving the ground it pushed off from.
  double minClearance = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < tr.size(); ++k) {
    if (tr.time[k] >= log.peakTime && tr.time[k] <= log.endTime) minClearance = std::min({minClearance, tr.ankleY[k], tr.toeY[k]});
  }
  if (!options.recordTrajectory) result.trajectory = SwingTrajectory{};
  result.swingTime = log.endTime;
  result.peakKneeFlexion = log.peak;
  result.peakKneeFlexionTime = log.peakTime;
  result.bounce = log.bounce;
  result.minToeClearance = minClearance;
  result.events = log.events;
  result.steps = integrator.getNumStepsTaken();
  result.realizations = integrator.getNumRealizations();
  return result;
}

}  // namespace swingsim
