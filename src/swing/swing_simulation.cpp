#include "swing/swing_simulation.h"

#include <Simbody.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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
  Real getValue(const State& s) const override { return leg_.getKneeFlexionRate(s); }
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

void recordSample(const LegModel& leg, const State& s, SwingTrajectory& tr) {
  tr.time.push_back(s.getTime());
  tr.hipFlexion.push_back(leg.getHipFlexion(s));
  tr.kneeFlexion.push_back(leg.getKneeFlexion(s));
  tr.hipFlexionRate.push_back(leg.getHipFlexionRate(s));
  tr.kneeFlexionRate.push_back(leg.getKneeFlexionRate(s));
  tr.hipMoment.push_back(leg.calcHipMoment(s));
  tr.kneeMoment.push_back(leg.calcKneeMoment(s));
  LegPose pose = leg.calcPose(s);
  tr.kneeX.push_back(pose.knee[0]);
  tr.kneeY.push_back(pose.knee[1]);
  tr.ankleX.push_back(pose.ankle[0]);
  tr.ankleY.push_back(pose.ankle[1]);
  tr.toeX.push_back(pose.toe[0]);
  tr.toeY.push_back(pose.toe[1]);
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
  integrator.setAllowInterpolation(true);
  TimeStepper stepper(system, integrator);
  stepper.setReportAllSignificantStates(false);
  stepper.initialize(state);

  SwingResult result;
  log.add("toe_off", 0.0);
  double minClearance = 1e9;
  auto observe = [&](const State& s) {
    if (options.recordTrajectory) recordSample(leg, s, result.trajectory);
    // Clearance matters from peak knee flexion (mid-swing) to the swing end; before that
    // the foot is still leaving the ground it pushed off from.
    if (log.peakSeen && !log.ended) {
      LegPose pose = leg.calcPose(s);
      minClearance = std::min({minClearance, pose.ankle[1], pose.toe[1]});
    }
  };
  system.realize(integrator.getState(), Stage::Acceleration);
  observe(integrator.getState());

  const double stopAfterEnd = rule.bounceWindow;
  double t = 0;
  while (true) {
    t += options.sampleInterval;
    Integrator::SuccessfulStepStatus status;
    try {
      status = stepper.stepTo(t);
    } catch (const std::exception& e) {
      throw RunError(p.name + ": the integrator failed " + describeState(leg, integrator.getState()) +
                     " (likely cause: a knee or hip law too stiff for the accuracy, or an unphysical input; " +
                     e.what() + ")");
    }
    const State& s = integrator.getState();
    system.realize(s, Stage::Acceleration);
    observe(s);
    if (status == Integrator::EndOfSimulation) break;
    if (log.ended && s.getTime() >= log.endTime + stopAfterEnd - 1e-12) break;
    if (!log.ended && s.getTime() >= rule.timeLimit - 1e-12) {
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
  }
  result.swingTime = log.endTime;
  result.peakKneeFlexion = log.peak;
  result.peakKneeFlexionTime = log.peakTime;
  result.bounce = log.bounce;
  result.minToeClearance = minClearance;
  result.events = log.events;
  result.steps = integrator.getNumStepsTaken();
  return result;
}

}  // namespace swingsim
