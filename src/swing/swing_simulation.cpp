#include "swing/swing_simulation.h"

#include <Simbody.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <memory>
#include <stdexcept>

#include "core/input_error.h"
#include "leg/leg_model.h"
#include "numerics/bogacki_shampine.h"
#include "swing/knee_climb.h"
#include "swing/simbody_ode.h"

namespace swingsim {

using namespace SimTK;

const char* driveKey(SwingDrive drive) { return drive == SwingDrive::kHipMoment ? "hip_moment" : "thigh_kinematics"; }

std::string describeDrive(const Participant& p) {
  if (p.drive == SwingDrive::kHipMoment) return "hip moment: " + p.hipMoment.describe();
  const ThighKinematics& k = p.thighKinematics;
  std::string text = "measured thigh angle prescribed on the hip (" + (k.path.empty() ? std::string("given in code") : k.path) +
                     ", " + std::to_string(k.time.size()) + " samples over " +
                     formatNumber(k.time.empty() ? 0.0 : k.time.back()) + " s";
  try {
    const ThighMotion motion(k);
    char buf[96];
    std::snprintf(buf, sizeof buf, "; GCV quintic spline, %.3f deg RMS from the samples", motion.getFitRms() * kRadToDeg);
    text += buf;
  } catch (const InputError& e) {
    text += std::string("; unusable: ") + e.what();
  }
  return text + "); the hip moment is what the prescription needs";
}

double calcHipHeight(const Participant& p) {
  return 0.530 * p.height + (p.toeClearance.hipRiseGiven ? p.toeClearance.hipRise : 0.0);
}

namespace {

// What the swing events have shown so far, and what each event means for the swing end.
// Both ways of finding the events (Simbody's event handlers on the plain path, our own
// crossing search between step ends on the fast path) report them here, so the rule is
// written once. The settle rule: the swing ends at the last entry into the zone (with the
// thigh at its target) that is followed by `dwell` s inside it; the knee leaving the zone
// before then is a bounce, and the end waits for the next entry.
struct SwingLog {
  explicit SwingLog(double settleDwell) : dwell(settleDwell) {}
  double dwell;
  std::vector<SwingEvent> events;
  bool thighReached = false;
  bool peakSeen = false;
  bool kneeInZone = false;   // inside the zone after the peak
  bool enteredOnce = false;
  bool candidate = false;    // in the zone with the thigh at target: the end, if the knee stays
  double candidateTime = 0;
  bool ended = false;
  int bounces = 0;
  double bounceHeight = 0;   // rad: highest knee flexion after leaving the zone
  double endTime = 0;
  double peak = -1e9, peakTime = 0;

  void add(const std::string& name, double t) { events.push_back({name, t}); }
  // The end is decided once the knee has stayed in the zone for the dwell; every handler
  // first settles what time t has already decided.
  void confirmUntil(double t) {
    if (!ended && candidate && t >= candidateTime + dwell) {
      ended = true;
      endTime = candidateTime;
      add("swing_end", candidateTime);
    }
  }
  // The knee can no longer leave the zone (SwingOptions::earlySettleEnd): the candidate is
  // the end, as the full dwell would have confirmed.
  void endAtCandidate() {
    if (ended || !candidate) return;
    ended = true;
    endTime = candidateTime;
    add("swing_end", candidateTime);
  }
  void checkCandidate(double t) {
    if (!ended && !candidate && thighReached && kneeInZone) {
      candidate = true;
      candidateTime = t;
    }
  }
  // The thigh rose through its target flexion.
  void onThighAtTarget(double t) {
    confirmUntil(t);
    if (thighReached) return;
    thighReached = true;
    add("thigh_at_target", t);
    checkCandidate(t);
  }
  // The knee flexion rate fell through zero with the knee at `knee` (rad).
  void onKneePeak(double t, double knee, double zone) {
    confirmUntil(t);
    if (knee <= zone || ended) return;  // wiggles inside the zone are not the swing's peak
    add(enteredOnce ? "knee_bounce_peak" : "knee_peak_flexion", t);
    if (enteredOnce) bounceHeight = std::max(bounceHeight, knee);
    peakSeen = true;
    if (knee > peak) {
      peak = knee;
      peakTime = t;
    }
  }
  // The knee flexion crossed the zone boundary (entering: falling below it).
  void onKneeZone(double t, bool entering) {
    confirmUntil(t);
    if (ended) return;
    if (entering) {
      if (!peakSeen) return;  // still on the way up from toe-off
      add("knee_enters_zone", t);
      kneeInZone = true;
      enteredOnce = true;
      checkCandidate(t);
    } else if (enteredOnce) {
      add("knee_leaves_zone", t);
      kneeInZone = false;
      candidate = false;
      ++bounces;
    }
  }
};

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

// An angle for a message: rad in, degrees rounded to 0.1 out.
std::string formatDegrees(double rad) { return formatNumber(std::round(rad * kRadToDeg * 10) / 10); }

std::string describeState(const LegModel& leg, const State& s) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "at t = %.4f s: hip flexion %.1f deg (%.0f deg/s), knee flexion %.1f deg (%.0f deg/s)",
                s.getTime(), leg.getHipFlexion(s) * kRadToDeg, leg.getHipFlexionRate(s) * kRadToDeg,
                leg.getKneeFlexion(s) * kRadToDeg, leg.getKneeFlexionRate(s) * kRadToDeg);
  return buf;
}

// Cubic Hermite on [0, 1] from values y0, y1 and derivatives d0, d1 (per unit time) over
// a step of length h.
double calcHermite(double y0, double d0, double y1, double d1, double h, double s) {
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
  const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
  return h00 * y0 + h10 * h * d0 + h01 * y1 + h11 * h * d1;
}

// Work bookkeeping at a step end: each knee law part's work, then the hip's, J.
constexpr int kMaxWorkCauses = 12;

// Joint state at the end of an integrator step: angles, rates, accelerations, moments, and
// with energy tracking the kinetic energy and the work done so far.
struct StepEnd {
  double t, hip, knee, hipRate, kneeRate, hipAcc, kneeAcc, hipMoment, kneeMoment;
  double kinetic = 0;
  int numWork = 0;
  std::array<double, kMaxWorkCauses> work{};
};

StepEnd readStepEnd(const LegModel& leg, const State& s, bool trackEnergy) {
  const MultibodySystem& system = leg.getSystem();
  system.realize(s, Stage::Acceleration);
  StepEnd e{s.getTime(), leg.getHipFlexion(s), leg.getKneeFlexion(s), leg.getHipFlexionRate(s),
            leg.getKneeFlexionRate(s), leg.getHipFlexionAcceleration(s), leg.getKneeFlexionAcceleration(s),
            leg.calcHipMoment(s), leg.calcKneeMoment(s)};
  if (trackEnergy) {
    e.kinetic = system.calcKineticEnergy(s);
    const int parts = std::min(leg.numKneeWorkParts(), kMaxWorkCauses - 1);
    for (int i = 0; i < parts; ++i) e.work[static_cast<std::size_t>(i)] = leg.getKneePartWork(s, i);
    e.numWork = parts;
    if (!leg.hasPrescribedThigh()) e.work[static_cast<std::size_t>(e.numWork++)] = leg.getHipWork(s);
  }
  return e;
}

// One output sample: joint state, moments, and the landmarks by planar kinematics.
void appendSample(SwingTrajectory& tr, const LegGeometry& g, double hipHeight, double t, double hip, double knee,
                  double hipRate, double kneeRate, double hipMoment, double kneeMoment) {
  tr.time.push_back(t);
  tr.hipFlexion.push_back(hip);
  tr.kneeFlexion.push_back(knee);
  tr.hipFlexionRate.push_back(hipRate);
  tr.kneeFlexionRate.push_back(kneeRate);
  tr.hipMoment.push_back(hipMoment);
  tr.kneeMoment.push_back(kneeMoment);
  const PlanarPose pose = calcPlanarPoseXY(g, hipHeight, hip, knee);
  tr.kneeX.push_back(pose.knee[0]);
  tr.kneeY.push_back(pose.knee[1]);
  tr.ankleX.push_back(pose.ankle[0]);
  tr.ankleY.push_back(pose.ankle[1]);
  tr.toeX.push_back(pose.toe[0]);
  tr.toeY.push_back(pose.toe[1]);
}

// Cubic Hermite on the angle (from angle and rate at both step ends) and on the rate
// (from rate and acceleration): the samples cost no extra realization, so the integrator
// chooses its steps by accuracy alone, not by the output interval.
void appendSamples(const StepEnd& a, const StepEnd& b, double& nextSample, double interval, const LegGeometry& g,
                   double hipHeight, SwingTrajectory& tr) {
  const double h = b.t - a.t;
  auto hermite = [&](double y0, double d0, double y1, double d1, double s) { return calcHermite(y0, d0, y1, d1, h, s); };
  while (nextSample <= b.t + 1e-12 && h > 0) {
    const double s = std::clamp((nextSample - a.t) / h, 0.0, 1.0);
    const double hip = hermite(a.hip, a.hipRate, b.hip, b.hipRate, s);
    const double knee = hermite(a.knee, a.kneeRate, b.knee, b.kneeRate, s);
    appendSample(tr, g, hipHeight, nextSample, hip, knee, hermite(a.hipRate, a.hipAcc, b.hipRate, b.hipAcc, s),
                 hermite(a.kneeRate, a.kneeAcc, b.kneeRate, b.kneeAcc, s), a.hipMoment + s * (b.hipMoment - a.hipMoment),
                 a.kneeMoment + s * (b.kneeMoment - a.kneeMoment));
    nextSample += interval;
  }
}

// The loose settle dwell (SwingOptions::dwellAccuracyFactor): never looser than this, and
// redone tightly if the knee rises to within this margin of the zone's edge (rad; the loose
// integration's angle error is about the accuracy, 1e-3 rad, eight times smaller).
constexpr double kLoosestDwellAccuracy = 1e-3;
constexpr double kLooseDwellMargin = 0.5 * kDegToRad;

// Time crossing resolution of the fast path, s: far below the 0.1 ms the swing time is
// converged to, and far above round-off in t.
constexpr double kCrossingTimeTol = 1e-12;

// Root of f on [lo, hi] within [0, 1] (f(lo) and f(hi) bracket it, not both zero), by the
// Illinois variant of regula falsi, to kCrossingTimeTol / h in s.
template <class F>
double findRoot(const F& f, double h, double lo = 0, double hi = 1) {
  double s0 = lo, s1 = hi, f0 = f(lo), f1 = f(hi);
  if (f1 == 0) return hi;
  int side = 0;
  for (int it = 0; it < 100 && (s1 - s0) * h > kCrossingTimeTol; ++it) {
    double s = (s0 * f1 - s1 * f0) / (f1 - f0);
    if (!(s > s0 && s < s1)) s = 0.5 * (s0 + s1);
    const double fs = f(s);
    if (fs == 0) return s;
    if ((fs < 0) == (f1 < 0)) {
      s1 = s;
      f1 = fs;
      if (side == -1) f0 *= 0.5;
      side = -1;
    } else {
      s0 = s;
      f0 = fs;
      if (side == 1) f1 *= 0.5;
      side = 1;
    }
  }
  return 0.5 * (s0 + s1);
}

// The fast path's events: sign changes of the witnesses between two step ends, each
// crossing found on the Hermite interpolant of the step (no realization, no State copy),
// handled in time order. Events after the swing end is decided (the settle dwell passed) are
// left out. A thigh or knee angle that crosses its threshold and comes back
// within one step (a thigh grazing its target at peak flexion) has the same witness sign
// at both step ends; where the interpolated rate changes sign inside the step, the angle
// at that extremum is checked too, so both crossings are found (Simbody's event handlers
// see only step ends and miss them: 41 ms on one added-mass swing of P4).
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
  Crossing crossings[5];
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
      crossings[count++] = {findRoot(zoneWitness, h, 0, top), kLeaves};
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
      case kThigh: log.onThighAtTarget(t); break;
      case kPeak: log.onKneePeak(t, kneeAt(crossings[i].s), zone); break;
      case kEnters: log.onKneeZone(t, true); break;
      case kLeaves: log.onKneeZone(t, false); break;
    }
  }
}

// The early failure (SwingOptions::earlyThighFailure) needs the leg's energy this far below
// what the thigh at its target needs, J: far above the integration's error in the energy
// (about the accuracy times the leg's few joules, and its drift over a swing's steps).
constexpr double kUnreachableEnergyMargin = 0.01;

// The early end of the settle dwell (SwingOptions::earlySettleEnd): fraction of what holds
// the knee down that is trusted to hold it for the rest of the dwell (KneeClimb): the free
// acceleration under the least holding hip moment still to come, and the knee law's
// resisting parts. The holding moment also changes with the thigh's angle and rate (sin of
// the angle, about) over the dwell's tenths of a second, which the linear response to the
// hip moment at the present pose does not see: P1's falls by a few percent there. The same
// fraction of the knee law's resisting parts (friction, damping) is trusted: the knee's
// inertia mu^-1 below is taken at the present pose too.
constexpr double kHoldFraction = 0.5;

// Whether the knee, at step end `e` in the zone, can no longer climb out of it. Treated as
// one degree of freedom with the thigh free (KneeClimb): its acceleration without the knee
// laws, `freeAcceleration` (rad/s^2; the caller takes the least holding one the hip moment
// can still give), presses it down (< 0); the stop gives back at most its stored energy
// (the midway spring) times mu = (M^-1)_knee,knee in 1/(kg m^2); the other parts of the
// knee law act as they would on the way up. Decided where the knee rises or rests (rate >= 0)
// below `edge` (rad): on the stop coming out of it, or above it.
bool isSettled(const StepEnd& e, const KneeClimb& climb, double edge, double mu, double freeAcceleration) {
  if (!(e.knee < edge && e.kneeRate >= 0)) return false;
  if (!(freeAcceleration < 0)) return false;
  return !climb.canReach(e.knee, e.kneeRate, edge, mu, -freeAcceleration, kHoldFraction);
}

// Contacts of the knee with its hyperextension stop, from the step ends and their Hermite
// interpolants (as the fast path's events). It only reports; the swing end does not use it.
class StopImpactTracker {
 public:
  static constexpr std::size_t kMaxImpacts = 20;  // a knee resting on its stop could chatter

  StopImpactTracker(double engage, std::vector<std::string> causes) : engage_(engage), causes_(std::move(causes)) {}

  void onStep(const StepEnd& a, const StepEnd& b) {
    const double h = b.t - a.t;
    if (!(h > 0)) return;
    auto kneeAt = [&](double s) { return calcHermite(a.knee, a.kneeRate, b.knee, b.kneeRate, h, s); };
    auto rateAt = [&](double s) { return calcHermite(a.kneeRate, a.kneeAcc, b.kneeRate, b.kneeAcc, h, s); };
    auto witness = [&](double s) { return kneeAt(s) - engage_; };
    if (phase_ == kRebound && a.kneeRate > 0 && b.kneeRate <= 0) {
      const double top = findRoot(rateAt, h);
      closeRebound(a, b, top, kneeAt(top));
    }
    if (phase_ != kContact && a.knee >= engage_ && b.knee < engage_) {
      if (phase_ == kRebound) closeRebound(a, a, 0, a.knee);  // back on the stop before a top
      if (impacts_.size() >= kMaxImpacts) return;
      const double s0 = findRoot(witness, h);
      StopImpact impact;
      impact.time = a.t + s0 * h;
      impact.impactRate = -rateAt(s0);
      impact.kineticEnergy = lerp(a.kinetic, b.kinetic, s0);
      impacts_.push_back(impact);
      start_ = snapshot(a, b, s0);
      phase_ = kContact;
    }
    if (phase_ == kContact) {
      StopImpact& impact = impacts_.back();
      impact.maxPenetration = std::max(impact.maxPenetration, engage_ - b.knee);
      if (a.kneeRate < 0 && b.kneeRate > 0) impact.maxPenetration = std::max(impact.maxPenetration, engage_ - kneeAt(findRoot(rateAt, h)));
      if (a.knee < engage_ && b.knee >= engage_) {
        const double s1 = findRoot(witness, h);
        impact.reboundRate = std::max(0.0, rateAt(s1));
        impact.restitution = impact.impactRate > 0 ? impact.reboundRate / impact.impactRate : 0;
        phase_ = kRebound;
      }
    }
  }

  // The impacts, the last one closed at the final step end `last`.
  std::vector<StopImpact> finish(const StepEnd& last) {
    if (phase_ == kContact || phase_ == kRebound) closeRebound(last, last, 0, phase_ == kRebound ? last.knee : engage_);
    return impacts_;
  }

 private:
  enum Phase { kFree, kContact, kRebound };
  using Snapshot = std::array<double, kMaxWorkCauses>;
  static double lerp(double x0, double x1, double s) { return x0 + s * (x1 - x0); }
  static Snapshot snapshot(const StepEnd& a, const StepEnd& b, double s) {
    Snapshot w{};
    for (int i = 0; i < b.numWork; ++i) w[static_cast<std::size_t>(i)] = lerp(a.work[static_cast<std::size_t>(i)], b.work[static_cast<std::size_t>(i)], s);
    return w;
  }
  void closeRebound(const StepEnd& a, const StepEnd& b, double s, double height) {
    StopImpact& impact = impacts_.back();
    impact.reboundHeight = std::max(height, engage_);
    if (b.numWork > 0) {
      const Snapshot end = snapshot(a, b, s);
      for (int i = 0; i < b.numWork && static_cast<std::size_t>(i) < causes_.size(); ++i)
        impact.work.push_back({causes_[static_cast<std::size_t>(i)], end[static_cast<std::size_t>(i)] - start_[static_cast<std::size_t>(i)]});
    }
    phase_ = kFree;
  }

  double engage_;
  std::vector<std::string> causes_;
  Phase phase_ = kFree;
  Snapshot start_{};
  std::vector<StopImpact> impacts_;
};

std::unique_ptr<Integrator> makeIntegrator(SwingIntegrator kind, const MultibodySystem& system) {
  switch (kind) {
    case SwingIntegrator::kRungeKuttaFeldberg: return std::make_unique<RungeKuttaFeldbergIntegrator>(system);
    case SwingIntegrator::kRungeKutta3: return std::make_unique<RungeKutta3Integrator>(system);
    case SwingIntegrator::kVerlet: return std::make_unique<VerletIntegrator>(system);
    case SwingIntegrator::kRungeKuttaMerson: return std::make_unique<RungeKuttaMersonIntegrator>(system);
    case SwingIntegrator::kDormandPrince: break;
  }
  throw std::invalid_argument("makeIntegrator: Dormand-Prince is not one of Simbody's integrators");
}

// One integrator step at a time, from toe-off to the time limit: Simbody's integrators
// (with or without its event handlers) or our Dormand-Prince over Simbody realizations.
class SwingStepper {
 public:
  virtual ~SwingStepper() = default;
  /// Takes one step, not past tLimit; returns false once tLimit has been reached.
  virtual bool step(double tLimit) = 0;
  /// The state at the last step end, realized to Acceleration.
  virtual const State& getState() = 0;
  virtual int getNumSteps() const = 0;
  virtual int getNumRealizations() const = 0;
};

class SimbodyStepper final : public SwingStepper {
 public:
  SimbodyStepper(const MultibodySystem& system, const State& initial, const SwingOptions& options, double tLimit)
      : system_(system), integrator_(makeIntegrator(options.integrator, system)) {
    integrator_->setAccuracy(options.accuracy);
    // Return after every internal step: the loop stops as soon as the swing end plus the
    // settle dwell has passed, finds the fast path's events and samples the output by
    // interpolation between steps.
    integrator_->setReturnEveryInternalStep(true);
    integrator_->setFinalTime(tLimit);
    if (options.simbodyEvents) {
      timeStepper_ = std::make_unique<TimeStepper>(system, *integrator_);
      timeStepper_->setReportAllSignificantStates(true);
      timeStepper_->initialize(initial);
    } else {
      integrator_->initialize(initial);
    }
  }
  bool step(double tLimit) override {
    const auto status = timeStepper_ ? timeStepper_->stepTo(tLimit) : integrator_->stepTo(tLimit);
    return status != Integrator::EndOfSimulation;
  }
  const State& getState() override {
    const State& s = integrator_->getState();
    system_.realize(s, Stage::Acceleration);
    return s;
  }
  int getNumSteps() const override { return integrator_->getNumStepsTaken(); }
  int getNumRealizations() const override { return integrator_->getNumRealizations(); }

 private:
  const MultibodySystem& system_;
  std::unique_ptr<Integrator> integrator_;
  std::unique_ptr<TimeStepper> timeStepper_;
};

// Dormand-Prince 5(4) (dormand_prince.h) on the Simbody leg's (q, u, z): six realizations
// per step, first same as last, and nothing else per step.
class DormandPrinceStepper final : public SwingStepper {
 public:
  DormandPrinceStepper(const MultibodySystem& system, const State& initial, double accuracy,
                       std::vector<double> breakpoints)
      : work_(initial), ode_(system, work_), y_(ode_.numStates()), breakpoints_(std::move(breakpoints)) {
    ode_.readState(initial, y_.data());
    start(initial.getTime(), accuracy);
  }
  bool step(double tLimit) override {
    const double t = getTime();
    if (t >= tLimit) return false;
    // End steps on the hip moment's kinks: a step across one loses the method's order.
    double tStop = tLimit;
    for (double b : breakpoints_)
      if (b > t && b < tStop) tStop = b;
    // End steps where the falling knee reaches its next level (the zone, the stop).
    if (kneeIndex_ >= 0) tStop = std::min(tStop, t + calcTimeToKneeLevel());
    if (loose_) loose_->step(tStop);
    else dp_->step(tStop);
    return getTime() < tLimit;
  }
  const State& getState() override { return ode_.realizeAt(getTime(), loose_ ? loose_->getState() : dp_->getState()); }
  int getNumSteps() const override {
    return stepsBefore_ + static_cast<int>(dp_->getNumSteps() + (loose_ ? loose_->getNumSteps() : 0));
  }
  int getNumRealizations() const override { return static_cast<int>(ode_.getNumRealizations()); }

  /// Ends a step where the knee (coordinate `kneeIndex` of q), falling, is predicted to
  /// reach the next of `levels` (rad, descending) below it, when that is sooner than the
  /// step planned: the swing's levels are just inside the zone of stability (the swing end
  /// is then found by a tight step, and the friction switching on near extension falls in
  /// the loose dwell) and the stop's engage angle (a step that runs into the stop's
  /// stiffness is rejected, often several times over). Predicted from the knee's angle,
  /// rate and acceleration at the step start (a parabola); a level within kLevelSlack
  /// above the knee is passed by, so no sliver of a step is forced.
  void setKneeLevels(int kneeIndex, std::vector<double> levels) {
    kneeIndex_ = kneeIndex;
    kneeLevels_ = std::move(levels);
  }
  /// Remembers the current step end (time and state).
  void saveCheckpoint() {
    checkpointTime_ = getTime();
    checkpoint_.assign(dp_->getState(), dp_->getState() + ode_.numStates());
  }
  /// Goes on from the current step end with Bogacki-Shampine 3(2) at `accuracy` (the loose
  /// settle dwell): half the realizations of a Dormand-Prince step, and where the knee
  /// meets its stop the step is bounded by the stop's stiffness rather than the order.
  /// Its first step is Dormand-Prince's planned one scaled by (accuracy ratio)^(1/5); f at
  /// the step end is Dormand-Prince's (FSAL), so the switch costs no realization.
  void loosen(double accuracy) {
    const double firstStep = dp_->getPlannedStep() * std::pow(accuracy / accuracy_, 0.2);
    loose_ = std::make_unique<BogackiShampine>(ode_, accuracy, accuracy);
    loose_->initialize(dp_->getTime(), dp_->getState(), dp_->getDerivatives(), firstStep);
  }
  /// Goes back to the checkpoint and on from there with Dormand-Prince at `accuracy`.
  void restoreCheckpoint(double accuracy) {
    stepsBefore_ += static_cast<int>(dp_->getNumSteps() + (loose_ ? loose_->getNumSteps() : 0));
    loose_.reset();
    y_ = checkpoint_;
    start(checkpointTime_, accuracy);
  }

 private:
  double getTime() const { return loose_ ? loose_->getTime() : dp_->getTime(); }
  void start(double t, double accuracy) {
    // One number for the relative and the absolute tolerance, as Simbody's accuracy is
    // used (angles in rad, rates in rad/s, work in J, law states dimensionless).
    accuracy_ = accuracy;
    dp_ = std::make_unique<DormandPrince>(ode_, accuracy, accuracy);
    dp_->initialize(t, y_.data());
  }
  State work_;
  SimbodyOde ode_;
  std::vector<double> y_;
  std::vector<double> breakpoints_;  // s
  static constexpr double kLevelSlack = 1e-3;  // rad
  // Time to the knee's next level from the current step end, s (+inf: none ahead).
  double calcTimeToKneeLevel() const {
    const double* y = loose_ ? loose_->getState() : dp_->getState();
    const double* f = loose_ ? loose_->getDerivatives() : dp_->getDerivatives();
    const int nq = work_.getNQ();
    const double knee = y[kneeIndex_], rate = y[nq + kneeIndex_], acc = f[nq + kneeIndex_];
    if (!(rate < 0)) return std::numeric_limits<double>::infinity();
    for (double level : kneeLevels_) {
      const double gap = knee - level;
      if (gap <= kLevelSlack) continue;
      // Smallest s > 0 with gap + rate s + acc s^2 / 2 = 0, in the form without
      // cancellation; none if the knee stops short of the level.
      const double disc = rate * rate - 2 * acc * gap;
      if (disc < 0) return std::numeric_limits<double>::infinity();
      return 2 * gap / (-rate + std::sqrt(disc));
    }
    return std::numeric_limits<double>::infinity();
  }
  int kneeIndex_ = -1;
  std::vector<double> kneeLevels_;  // rad, descending
  double accuracy_ = 0;
  std::unique_ptr<DormandPrince> dp_;
  std::unique_ptr<BogackiShampine> loose_;  // the loose dwell, once it has begun
  int stepsBefore_ = 0;
  double checkpointTime_ = 0;
  std::vector<double> checkpoint_;
};

}  // namespace

namespace {

// Every integrator once: its YAML/CLI key, its display name, and the loosest accuracy at
// which its swing times converge to 0.1 ms (README, Convergence study). In enum order.
struct IntegratorInfo {
  const char* key;
  const char* name;
  double convergedAccuracy;
};
constexpr IntegratorInfo kIntegrators[] = {
    {"dormand-prince", "Dormand-Prince 5(4) over Simbody realizations", 1e-5},
    {"runge-kutta-merson", "Simbody Runge-Kutta-Merson", 1e-4},
    {"runge-kutta-feldberg", "Simbody Runge-Kutta-Feldberg", 1e-5},
    {"runge-kutta-3", "Simbody Runge-Kutta 3", 1e-3},
    {"verlet", "Simbody Verlet", 1e-5},
};

const IntegratorInfo& infoOf(SwingIntegrator integrator) { return kIntegrators[static_cast<int>(integrator)]; }

}  // namespace

const char* integratorName(SwingIntegrator integrator) { return infoOf(integrator).name; }

double calcConvergedAccuracy(SwingIntegrator integrator) { return infoOf(integrator).convergedAccuracy; }

const std::vector<std::string>& integratorKeys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k;
    for (const auto& i : kIntegrators) k.push_back(i.key);
    return k;
  }();
  return keys;
}

std::optional<SwingIntegrator> findIntegrator(const std::string& key) {
  for (std::size_t i = 0; i < std::size(kIntegrators); ++i)
    if (key == kIntegrators[i].key) return static_cast<SwingIntegrator>(i);
  return std::nullopt;
}

std::string checkAccuracy(double accuracy) {
  // Below about 1e-14 a relative accuracy asks for less than double round-off: the step-size
  // control breaks down (1e-300 made a NaN inertia) instead of converging further.
  constexpr double kTightestAccuracy = 1e-14;
  return accuracy >= kTightestAccuracy && accuracy <= 1e-2 ? "" : "expected a relative accuracy in [1e-14, 0.01]";
}

SwingOptions makeSimbodyIntegratorOptions(double accuracy) {
  SwingOptions o;
  o.integrator = SwingIntegrator::kRungeKuttaMerson;
  o.accuracy = accuracy;
  return o;
}

SwingOptions makePlainPathOptions(double accuracy, double eventWindow) {
  SwingOptions o = makeSimbodyIntegratorOptions(accuracy);
  o.simbodyEvents = true;
  o.eventWindow = eventWindow;
  return o;
}

SwingResult simulateSwing(const SwingSetup& setup, const SwingOptions& options) {
  const Participant& p = setup.participant;
  if (setup.knee == nullptr) throw InputError(p.path + ": no knee model");
  const LegGeometry geometry = calcLegGeometry(p, setup.lowering, setup.added);
  const bool trackEnergy = options.trackImpactEnergy;
  // The measured thigh drive: the thigh follows its spline, and the swing must end before
  // the measurement does.
  std::optional<ThighMotion> thighMotion;
  if (p.drive == SwingDrive::kThighKinematics) thighMotion.emplace(p.thighKinematics);
  std::optional<HipPath> hipPath;  // a measured pelvis moves the hip
  if (thighMotion && HipPath::hasPelvis(p.thighKinematics)) hipPath.emplace(p.thighKinematics, p.hipOffsetInPelvis, p.path);
  LegModel leg(geometry, *setup.knee, p.hipMoment, p.hipRange, calcHipHeight(p), trackEnergy,
               thighMotion ? &*thighMotion : nullptr, hipPath ? &*hipPath : nullptr);
  const double timeLimit = thighMotion ? std::min(p.swingEnd.timeLimit, thighMotion->getEndTime()) : p.swingEnd.timeLimit;

  if (options.simbodyEvents && options.integrator == SwingIntegrator::kDormandPrince)
    throw std::invalid_argument("simulateSwing: Simbody's event handlers need one of Simbody's integrators");
  const SwingEndRule& rule = p.swingEnd;
  SwingLog log(rule.settleDwell);
  MultibodySystem& system = leg.updSystem();
  if (options.simbodyEvents) {
    system.addEventHandler(new ThighTargetHandler(leg, log, options.eventWindow, rule.thighTargetFlexion));
    system.addEventHandler(new KneePeakHandler(leg, log, options.eventWindow, rule.zoneOfStability));
    system.addEventHandler(new KneeZoneHandler(leg, log, options.eventWindow, rule.zoneOfStability, true));
    system.addEventHandler(new KneeZoneHandler(leg, log, options.eventWindow, rule.zoneOfStability, false));
    system.realizeTopology();
  }

  InitialConditions initialConditions = p.initial;
  if (thighMotion) {
    initialConditions.hipFlexion = thighMotion->calcAngle(0);
    initialConditions.hipFlexionRate = thighMotion->calcRate(0);
  }
  const State initial = leg.makeInitialState(initialConditions);
  std::unique_ptr<SwingStepper> stepper;
  // The knee law's hyperextension stop and the parts the settle dwell's early end weighs.
  const KneeClimb climb(*setup.knee);
  DormandPrinceStepper* dormandPrince = nullptr;
  if (options.integrator == SwingIntegrator::kDormandPrince) {
    // End steps on the hip moment's kinks; the thigh spline is smooth (C4).
    auto dp = std::make_unique<DormandPrinceStepper>(system, initial, options.accuracy,
                                                     thighMotion ? std::vector<double>{} : p.hipMoment.calcBreakpoints());
    dormandPrince = dp.get();
    {
      // The knee's levels: inside the zone, the stop.
      std::vector<double> levels{rule.zoneOfStability - kLooseDwellMargin};
      if (const JointStop* stop = climb.getStop())
        if (stop->params().lower < levels.back()) levels.push_back(stop->params().lower);
      dp->setKneeLevels(leg.getKneeCoordinateIndex(), std::move(levels));
    }
    stepper = std::move(dp);
  } else {
    stepper = std::make_unique<SimbodyStepper>(system, initial, options, timeLimit);
  }

  SwingResult result;
  log.add("toe_off", 0.0);
  const double hipHeight = calcHipHeight(p);
  SwingTrajectory& tr = result.trajectory;
  StepEnd previous = readStepEnd(leg, stepper->getState(), trackEnergy);
  std::optional<StopImpactTracker> impacts;
  if (const JointStop* stop = climb.getStop()) {
    std::vector<std::string> causes;
    if (trackEnergy) {
      for (int i = 0; i < std::min(leg.numKneeWorkParts(), kMaxWorkCauses - 1); ++i) causes.push_back(leg.getKneeWorkPartName(i));
      if (!thighMotion) causes.push_back("hip drive");
    }
    impacts.emplace(stop->params().lower, std::move(causes));
  }
  double nextSample = 0;
  {
    // Room for a typical swing plus its settle dwell, so samples rarely reallocate.
    constexpr double kTypicalDuration = 0.8;  // s
    const std::size_t capacity = static_cast<std::size_t>(std::min(timeLimit, kTypicalDuration) / options.sampleInterval) + 2;
    for (auto* v : tr.columns()) v->reserve(capacity);
    // The first sample, at toe-off.
    appendSample(tr, geometry, hipHeight, 0.0, previous.hip, previous.knee, previous.hipRate, previous.kneeRate,
                 previous.hipMoment, previous.kneeMoment);
    nextSample = options.sampleInterval;
  }

  double candidateTime = -1;  // the swing end candidate whose realizations were counted
  // The loose settle dwell (SwingOptions::looseDwellAccuracy): what to go back to if the
  // knee comes near the zone's edge while the dwell is integrated loosely.
  struct DwellCheckpoint {
    double candidateTime = -1;  // the candidate it was taken for (-1: none)
    SwingLog log{0};
    std::optional<StopImpactTracker> impacts;
    StepEnd previous{};
    std::size_t samples = 0;
    double nextSample = 0;
  } checkpoint;
  bool loose = false;
  double tightenedFor = -1;  // a candidate already redone tightly: no second loose try
  const double looseAccuracy = std::min(options.accuracy * options.dwellAccuracyFactor, kLoosestDwellAccuracy);
  const bool looseDwellAllowed = dormandPrince != nullptr && !trackEnergy && looseAccuracy > options.accuracy;
  const double zone = rule.zoneOfStability;
  // The hip moment is constant from the profile's last breakpoint on.
  const std::vector<double> hipBreakpoints = p.hipMoment.calcBreakpoints();
  const double hipMomentConstantFrom = hipBreakpoints.empty() ? 0.0 : hipBreakpoints.back();
  // The early settle end (SwingOptions::earlySettleEnd) needs the stop; not with the measured
  // thigh drive: the prescribed thigh keeps moving. It is decided below `settleEdge`: not
  // within the loose dwell's margin of the zone's edge either, where the dwell would be
  // redone tightly (a knee that rises that high may bounce out).
  const bool earlyEndAllowed = options.earlySettleEnd && dormandPrince != nullptr && !trackEnergy &&
                               climb.getStop() != nullptr && climb.getStop()->params().lower < zone && !thighMotion;
  const double settleEdge = zone - kLooseDwellMargin;
  // The knee's column of M^-1 is asked for with a unit knee force (mobility 1).
  Vector unitKneeForce(initial.getNU(), 0.0), kneeResponse;
  unitKneeForce[1] = 1.0;
  // The early failure (SwingOptions::earlyThighFailure): the hip moment after its last
  // breakpoint, and the least energy (J) the leg must have for the thigh to get to its target.
  const double hipMomentFinal = p.hipMoment.calcMoment(hipMomentConstantFrom + 1.0);
  const bool earlyFailureAllowed =
      options.earlyThighFailure && dormandPrince != nullptr && !thighMotion && setup.knee->isPassive();
  double thighTargetEnergy = std::numeric_limits<double>::quiet_NaN();  // found when first needed
  double thighShortfall = 0;  // J: > 0 once the thigh cannot reach its target
  const auto wallStart = std::chrono::steady_clock::now();
  // What to change when a budget runs out: the same advice for both budgets.
  const auto overBudget = [&](const std::string& what, const State& s) {
    return RunError(p.name + " at lowering " + formatNumber(setup.lowering) + " m: the swing was stopped after " + what +
                    " " + describeState(leg, s) + ", with " + integratorName(options.integrator) + " at accuracy " +
                    formatNumber(options.accuracy) +
                    "; the knee or hip law is too stiff for this integrator at this accuracy: loosen the accuracy "
                    "(--accuracy, or accuracy: in the study; converged: " +
                    formatNumber(calcConvergedAccuracy(options.integrator)) + "), or check the knee model " +
                    p.kneeModelPath + " for a value far too large (a unit mistake?)");
  };
  while (true) {
    bool more;
    try {
      more = stepper->step(timeLimit);
    } catch (const std::exception& e) {
      throw RunError(p.name + ": the integrator failed " + describeState(leg, stepper->getState()) +
                     " (likely cause: a knee or hip law too stiff for the accuracy, or an unphysical input; " +
                     e.what() + ")");
    }
    const State& s = stepper->getState();
    if (stepper->getNumRealizations() > options.maxRealizations)
      throw overBudget(std::to_string(stepper->getNumRealizations()) + " realizations (the budget of one swing is " +
                           std::to_string(options.maxRealizations) + "; a normal swing takes a few hundred)",
                       s);
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count() > options.maxWallSeconds)
      throw overBudget(formatNumber(options.maxWallSeconds) + " s of computing (the limit for one swing; a normal swing takes milliseconds)", s);
    StepEnd now = readStepEnd(leg, s, trackEnergy);
    if (!std::isfinite(now.hip) || !std::isfinite(now.knee)) {
      throw RunError(p.name + ": the simulation diverged " + describeState(leg, s) +
                     " (likely cause: an unphysical input such as a near-zero inertia)");
    }
    if (!options.simbodyEvents) handleStepEvents(previous, now, rule, log);
    log.confirmUntil(now.t);
    if (impacts) impacts->onStep(previous, now);
    if (now.t > previous.t) appendSamples(previous, now, nextSample, options.sampleInterval, geometry, hipHeight, tr);
    // The hip stop is soft (Hunt-Crossley): a thigh far past it means the inputs are wrong,
    // and a swing "ending" out there would look like a result.
    constexpr double kHipRangeSlack = 2 * kDegToRad;  // rad; plausible hip moments press the stop far less
    if (!thighMotion && (now.hip < p.hipRange.minFlexion - kHipRangeSlack || now.hip > p.hipRange.maxFlexion + kHipRangeSlack)) {
      throw RunError(p.name + " at lowering " + formatNumber(setup.lowering) + " m: the hip left its range of " +
                     formatDegrees(p.hipRange.minFlexion) + " to " + formatDegrees(p.hipRange.maxFlexion) + " deg " + describeState(leg, s) +
                     " (likely cause: a hip moment far too large for this leg, or a hip_range that excludes the swing)");
    }
    if (loose) {
      // The knee back near the zone's edge (or out of it) during the loose dwell: a bounce may
      // decide the swing end, so go back to the entry and integrate the dwell tightly.
      // (The knee enters the zone falling: only where it rises again does the edge matter.)
      double highest = now.kneeRate > 0 ? now.knee : -1e9;
      if (previous.kneeRate > 0 && now.kneeRate < 0) {
        const double h = now.t - previous.t;
        const double top = findRoot([&](double x) { return calcHermite(previous.kneeRate, previous.kneeAcc, now.kneeRate, now.kneeAcc, h, x); }, h);
        highest = std::max(highest, calcHermite(previous.knee, previous.kneeRate, now.knee, now.kneeRate, h, top));
      }
      if (highest > zone - kLooseDwellMargin || !log.candidate) {
        log = checkpoint.log;
        impacts = checkpoint.impacts;
        now = checkpoint.previous;
        for (auto* v : tr.columns()) v->resize(checkpoint.samples);
        nextSample = checkpoint.nextSample;
        dormandPrince->restoreCheckpoint(options.accuracy);
        tightenedFor = checkpoint.candidateTime;
        loose = false;
        ++result.looseDwellRetries;
      }
    }
    previous = now;
    if (log.candidate && log.candidateTime != candidateTime) {
      // The realizations up to the step of the (latest) entry into the zone.
      candidateTime = log.candidateTime;
      result.realizationsToEnd = stepper->getNumRealizations();
    }
    if (!log.ended && earlyEndAllowed && log.candidate && now.t == s.getTime() && now.knee < settleEdge &&
        now.kneeRate >= 0) {
      // The knee's acceleration per unit knee moment (mu) and per unit hip moment (nu),
      // thigh free: the knee column of M^-1 (symmetric).
      leg.getMatter().multiplyByMInv(s, unitKneeForce, kneeResponse);
      const double mu = kneeResponse[1], nu = kneeResponse[0];
      // Without the knee laws, under the hip moment still to come that holds it least.
      const auto [hipLow, hipHigh] = p.hipMoment.calcRangeFrom(now.t);
      const double hipNow = p.hipMoment.calcMoment(now.t);
      const double freeAcceleration = now.kneeAcc - mu * now.kneeMoment + nu * ((nu > 0 ? hipHigh : hipLow) - hipNow);
      if (isSettled(now, climb, settleEdge, mu, freeAcceleration)) log.endAtCandidate();
    }
    if (log.ended) {
      result.endDecidedTime = now.t;
      break;
    }
    if (looseDwellAllowed && !loose && log.candidate && log.candidateTime != tightenedFor &&
        log.candidateTime != checkpoint.candidateTime) {
      // The knee has entered the zone: integrate the dwell loosely from here, keeping what is
      // needed to come back.
      checkpoint.candidateTime = log.candidateTime;
      checkpoint.log = log;
      checkpoint.impacts = impacts;
      checkpoint.previous = now;
      checkpoint.samples = tr.size();
      checkpoint.nextSample = nextSample;
      dormandPrince->saveCheckpoint();
      dormandPrince->loosen(looseAccuracy);
      loose = true;
    }
    if (earlyFailureAllowed && !log.thighReached && now.t >= hipMomentConstantFrom && now.t == s.getTime() &&
        now.hip < rule.thighTargetFlexion && now.hip > p.hipRange.minFlexion && now.hip < p.hipRange.maxFlexion) {
      if (std::isnan(thighTargetEnergy))
        thighTargetEnergy = leg.calcLeastPotentialEnergy(rule.thighTargetFlexion) - hipMomentFinal * rule.thighTargetFlexion;
      const double energy = leg.calcMechanicalEnergy(s) +
                            setup.knee->calcStoredEnergy({now.knee, now.kneeRate}, leg.getKneeLawStates(s)) -
                            hipMomentFinal * now.hip;
      if (energy < thighTargetEnergy - kUnreachableEnergyMargin) thighShortfall = thighTargetEnergy - energy;
    }
    const bool cannotEnd = thighShortfall > 0;
    if (!log.ended && (now.t >= timeLimit - 1e-12 || !more || cannotEnd) && !options.requireSwingEnd) break;
    if (!log.ended && cannotEnd) {
      throw RunError(p.name + " at lowering " + formatNumber(setup.lowering) + " m: the swing cannot end (decided " +
                     describeState(leg, s) + ", before the time limit of " + formatNumber(std::round(timeLimit * 1e4) / 1e4) +
                     " s): the thigh never reached its target flexion of " + formatDegrees(rule.thighTargetFlexion) +
                     " deg and cannot any more: with the hip moment constant at " + formatNumber(hipMomentFinal) +
                     " N m from t = " + formatNumber(std::round(hipMomentConstantFrom * 1e4) / 1e4) + " s, the leg's energy is " +
                     formatNumber(std::round(thighShortfall * 1e4) / 1e4) +
                     " J short of the least the thigh at its target needs, and the knee and the hip stop only take energy "
                     "away (hip moment too small for this leg?)");
    }
    if (!log.ended && (now.t >= timeLimit - 1e-12 || !more)) {
      std::string cause;
      if (thighMotion && timeLimit < rule.timeLimit)
        cause = "the measured thigh motion (" + (p.thighKinematics.path.empty() ? std::string("given in code") : p.thighKinematics.path) +
                ") ends at " + formatNumber(std::round(timeLimit * 1e4) / 1e4) +
                " s, before the swing ended (it needs the thigh at its target, the knee back in the zone and the settle "
                "dwell of " + formatNumber(rule.settleDwell) + " s): give a longer trial, or a shorter settle_dwell_s; ";
      if (!log.thighReached)
        cause += "the thigh never reached its target flexion of " + formatDegrees(rule.thighTargetFlexion) +
                 (thighMotion ? " deg (set swing_end: thigh_target_flexion_deg below the measured thigh's peak)"
                              : " deg (hip moment too small for this leg?)");
      else if (!log.peakSeen)
        cause += "the knee never reached a flexion peak above the zone of stability";
      else if (log.enteredOnce)
        cause += "the knee did not settle: it left the zone of stability (< " + formatDegrees(rule.zoneOfStability) +
                " deg) " + std::to_string(log.bounces) + " times and never stayed inside it for the settle dwell of " +
                formatNumber(rule.settleDwell) + " s (a stop that returns too much of the impact, restitution near 1?)";
      else
        cause += "the knee never came back inside the zone of stability (< " +
                formatDegrees(rule.zoneOfStability) + " deg) after its peak (knee resistance too high, or the hip extension moment too weak?)";
      throw RunError(p.name + " at lowering " + formatNumber(setup.lowering) + " m: the swing did not end within the time limit of " +
                     formatNumber(std::round(timeLimit * 1e4) / 1e4) + " s; " + describeState(leg, s) + "; " + cause);
    }
    if (!more) break;
  }
  // Lowest ankle or toe from peak knee flexion (mid-swing) to the swing end; before the
  // peak the foot is still leaving the ground it pushed off from.
  double minClearance = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < tr.size(); ++k) {
    if (tr.time[k] >= log.peakTime && tr.time[k] <= (log.ended ? log.endTime : previous.t)) minClearance = std::min({minClearance, tr.ankleY[k], tr.toeY[k]});
  }
  if (!options.recordTrajectory) result.trajectory = SwingTrajectory{};
  result.swingTime = log.ended ? log.endTime : std::numeric_limits<double>::quiet_NaN();
  result.peakKneeFlexion = log.peak;
  result.peakKneeFlexionTime = log.peakTime;
  result.bounces = log.bounces;
  result.bounce = log.bounces > 0;
  result.bounceHeight = log.bounceHeight;
  if (impacts) result.impacts = impacts->finish(previous);
  std::stable_sort(log.events.begin(), log.events.end(), [](const SwingEvent& x, const SwingEvent& y) { return x.time < y.time; });
  result.minToeClearance = minClearance;
  result.events = log.events;
  result.steps = stepper->getNumSteps();
  result.realizations = stepper->getNumRealizations();
  return result;
}

}  // namespace swingsim
