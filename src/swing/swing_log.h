#pragma once
// The swing events (thigh at target, knee peak, knee enters and leaves the zone) and the
// settle rule they decide the swing end by (SwingEndRule::settleDwell).
#include <Simbody.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "leg/leg_model.h"
#include "model/leg_parameters.h"
#include "swing/step_end.h"
#include "swing/swing_simulation.h"

namespace swingsim {

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
  bool kneeInZone = false;  // inside the zone after the peak
  bool enteredOnce = false;
  bool candidate = false;  // in the zone with the thigh at target: the end, if the knee stays
  double candidateTime = 0;
  bool ended = false;
  int bounces = 0;
  std::optional<double> bounceHeight;  // rad: highest knee peak after leaving the zone, if any
  double endTime = 0;
  std::optional<KneePeak> peak;  // the highest knee peak above the zone, if any

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
    if (enteredOnce) bounceHeight = std::max(bounceHeight.value_or(knee), knee);
    peakSeen = true;
    if (!peak || knee > peak->flexion) peak = KneePeak{knee, t};
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

/// The plain path (SwingOptions::simbodyEvents): Simbody TriggeredEventHandlers for the four
/// events, reporting to `log`, each crossing localized to `window` s. Realizes the topology.
void addSwingEventHandlers(SimTK::MultibodySystem& system, const LegModel& leg, SwingLog& log, const SwingEndRule& rule,
                           double window);

// The fast path's events: sign changes of the witnesses between two step ends, each
// crossing found on the Hermite interpolant of the step (no realization, no State copy),
// handled in time order. Events after the swing end is decided (the settle dwell passed) are
// left out. A thigh or knee angle that crosses its threshold and comes back
// within one step (a thigh grazing its target at peak flexion) has the same witness sign
// at both step ends; where the interpolated rate changes sign inside the step, the angle
// at that extremum is checked too, so both crossings are found (Simbody's event handlers
// see only step ends and miss them: 41 ms on one added-mass swing of P4).
void handleStepEvents(const StepEnd& a, const StepEnd& b, const SwingEndRule& rule, SwingLog& log);

}  // namespace swingsim
