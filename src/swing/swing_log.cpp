#include "swing/swing_log.h"

namespace swingsim {

using namespace SimTK;

namespace {

// The event witnesses, shared by both paths. Knee peak: the knee rate while the knee is
// above the zone; a positive constant inside it, so a knee resting near extension after the
// swing (rate dithering about zero) does not raise a stream of meaningless sign changes.
double calcPeakWitness(double knee, double kneeRate, double zone) { return knee > zone ? kneeRate : 1.0; }
// Simbody's sign transitions (Event::classifyTransition): a value leaving exactly zero is not one.
bool isRising(double before, double after) { return before < 0 && after >= 0; }
bool isFalling(double before, double after) { return before > 0 && after <= 0; }

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
  void handleEvent(State& s, Real, bool&) const override { log_.onThighAtTarget(s.getTime()); }

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
  Real getValue(const State& s) const override {
    return calcPeakWitness(leg_.getKneeFlexion(s), leg_.getKneeFlexionRate(s), zone_);
  }
  void handleEvent(State& s, Real, bool&) const override {
    log_.onKneePeak(s.getTime(), leg_.getKneeFlexion(s), zone_);
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
  void handleEvent(State& s, Real, bool&) const override { log_.onKneeZone(s.getTime(), entering_); }

 private:
  double zone_;
  bool entering_;
};

}  // namespace

void addSwingEventHandlers(MultibodySystem& system, const LegModel& leg, SwingLog& log, const SwingEndRule& rule,
                           double window) {
  system.addEventHandler(new ThighTargetHandler(leg, log, window, rule.thighTargetFlexion));
  system.addEventHandler(new KneePeakHandler(leg, log, window, rule.zoneOfStability));
  system.addEventHandler(new KneeZoneHandler(leg, log, window, rule.zoneOfStability, true));
  system.addEventHandler(new KneeZoneHandler(leg, log, window, rule.zoneOfStability, false));
  system.realizeTopology();
}

void handleStepEvents(const StepEnd& a, const StepEnd& b, const SwingEndRule& rule, SwingLog& log) {
  const double h = b.t - a.t;
  if (!(h > 0)) return;
  const double target = rule.thighTargetFlexion, zone = rule.zoneOfStability;
  auto hipAt = [&](double s) { return calcHermite(a.hip, a.hipRate, b.hip, b.hipRate, h, s); };
  auto kneeAt = [&](double s) { return calcHermite(a.knee, a.kneeRate, b.knee, b.kneeRate, h, s); };
  auto hipRateAt = [&](double s) { return calcHermite(a.hipRate, a.hipAcc, b.hipRate, b.hipAcc, h, s); };
  auto kneeRateAt = [&](double s) { return calcHermite(a.kneeRate, a.kneeAcc, b.kneeRate, b.kneeAcc, h, s); };
  auto thighWitness = [&](double s) { return hipAt(s) - target; };
  auto zoneWitness = [&](double s) { return zone - kneeAt(s); };
  enum Kind { kThigh, kPeak, kEnters, kLeaves };
  struct Crossing {
    double s;
    Kind kind;
  };
  Crossing crossings[5];  // at most 4: the thigh, and a knee peak with two zone crossings
  int count = 0;
  const double thigh0 = a.hip - target, thigh1 = b.hip - target;
  if (isRising(thigh0, thigh1)) {
    crossings[count++] = {findRoot(thighWitness, h), kThigh};
  } else if (thigh0 < 0 && thigh1 < 0 && a.hipRate > 0 && b.hipRate < 0) {
    const double top = findRoot(hipRateAt, h);  // the thigh's peak flexion inside the step
    if (thighWitness(top) >= 0) crossings[count++] = {findRoot(thighWitness, h, 0, top), kThigh};
  }
  if (isFalling(calcPeakWitness(a.knee, a.kneeRate, zone), calcPeakWitness(b.knee, b.kneeRate, zone)))
    crossings[count++] = {findRoot(kneeRateAt, h), kPeak};
  const double zone0 = zone - a.knee, zone1 = zone - b.knee;
  if (isRising(zone0, zone1)) {
    crossings[count++] = {findRoot(zoneWitness, h), kEnters};
  } else if (isFalling(zone0, zone1)) {
    crossings[count++] = {findRoot(zoneWitness, h), kLeaves};
  } else if (zone0 < 0 && zone1 < 0 && a.kneeRate < 0 && b.kneeRate > 0) {
    const double bottom = findRoot(kneeRateAt, h);  // a knee minimum dipping into the zone
    if (zoneWitness(bottom) > 0) {
      crossings[count++] = {findRoot(zoneWitness, h, 0, bottom), kEnters};
      crossings[count++] = {findRoot(zoneWitness, h, bottom, 1), kLeaves};
    }
  } else if (zone0 > 0 && zone1 > 0 && a.kneeRate > 0 && b.kneeRate < 0) {
    const double top = findRoot(kneeRateAt, h);  // a knee maximum rising out of the zone
    if (zoneWitness(top) < 0) {
      // Out, its peak and back in within the step: the peak's witness (the rate above the
      // zone) has no sign change at the step ends, so it is added here, or the rebound's
      // height would be lost.
      crossings[count++] = {findRoot(zoneWitness, h, 0, top), kLeaves};
      crossings[count++] = {top, kPeak};
      crossings[count++] = {findRoot(zoneWitness, h, top, 1), kEnters};
    }
  }
  for (int i = 1; i < count; ++i)
    for (int j = i; j > 0 && crossings[j].s < crossings[j - 1].s; --j) std::swap(crossings[j], crossings[j - 1]);
  for (int i = 0; i < count; ++i) {
    const double t = a.t + crossings[i].s * h;
    log.confirmUntil(t);
    if (log.ended) return;
    switch (crossings[i].kind) {
      case kThigh:
        log.onThighAtTarget(t);
        break;
      case kPeak:
        log.onKneePeak(t, kneeAt(crossings[i].s), zone);
        break;
      case kEnters:
        log.onKneeZone(t, true);
        break;
      case kLeaves:
        log.onKneeZone(t, false);
        break;
    }
  }
}

}  // namespace swingsim
