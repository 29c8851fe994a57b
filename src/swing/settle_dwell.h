#pragma once
// The loose settle dwell (SwingOptions::dwellAccuracyFactor; docs/swing-options.md): once
// the knee has entered the zone, the dwell that confirms the swing end is integrated loosely;
// if the knee comes back near the zone's edge, the run goes back to the entry and integrates
// the dwell at full accuracy.
#include <cstddef>
#include <optional>

#include "core/units.h"
#include "swing/step_end.h"
#include "swing/stop_impact_tracker.h"
#include "swing/swing_log.h"
#include "swing/swing_simulation.h"
#include "swing/swing_stepper.h"

namespace swingsim {

// The loose settle dwell: never looser than this, and redone tightly if the knee rises to
// within this margin of the zone's edge (rad; the loose integration's angle error is about
// the accuracy, 1e-3 rad, eight times smaller).
constexpr double kLoosestDwellAccuracy = 1e-3;
constexpr double kLooseDwellMargin = 0.5 * kDegToRad;

/// What a run goes back to when a loose dwell is redone: its state at the entry into the zone.
struct DwellCheckpoint {
  double candidateTime = -1;  ///< s, the swing end candidate it was taken for (-1: none)
  SwingLog log{0};
  std::optional<StopImpactTracker> impacts;
  StepEnd previous{};
  std::size_t samples = 0;  ///< trajectory samples kept
  double nextSample = 0;    ///< s
};

class SettleDwell {
 public:
  /// `canLoosen`: the run steps with Dormand-Prince (the loose dwell needs its checkpoint).
  SettleDwell(const SwingOptions& options, bool canLoosen, double zoneOfStability);
  bool isLoose() const { return loose_; }
  /// During a loose dwell: whether the step previous-now must be redone tightly (the knee
  /// rose to within kLooseDwellMargin of the zone's edge, or the candidate was lost).
  bool mustRedo(const StepEnd& previous, const StepEnd& now, const SwingLog& log) const;
  /// Goes back to the checkpoint: `stepper` restarts there at full accuracy; the caller
  /// restores the rest of the run from the returned checkpoint.
  const DwellCheckpoint& redo(DormandPrinceStepper& stepper);
  /// Whether to loosen now: the knee has entered the zone for a candidate not tried yet.
  bool shouldLoosen(const SwingLog& log) const;
  /// Keeps `checkpoint` (taken at the entry) and loosens `stepper`.
  void loosen(DwellCheckpoint checkpoint, DormandPrinceStepper& stepper);
  int getRetries() const { return retries_; }

 private:
  double accuracy_, looseAccuracy_, zone_;
  bool allowed_;
  bool loose_ = false;
  double tightenedFor_ = -1;  // s: a candidate already redone tightly gets no second loose try
  int retries_ = 0;
  DwellCheckpoint checkpoint_;
};

}  // namespace swingsim
