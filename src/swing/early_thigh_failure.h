#pragma once
// The early thigh failure (SwingOptions::earlyThighFailure; docs/swing-options.md): a swing
// whose thigh provably cannot reach its target flexion any more is stopped there instead of
// at the time limit. Only with a passive knee law, under a hip moment, on the fast path.
#include <Simbody.h>

#include "leg/leg_model.h"
#include "swing/step_end.h"
#include "swing/swing_simulation.h"

namespace swingsim {

// The leg's energy must be this far below what the thigh at its target needs, J: far above
// the integration's error in the energy (about the accuracy times the leg's few joules, and
// its drift over a swing's steps).
constexpr double kUnreachableEnergyMargin = 0.01;

class EarlyThighFailure {
 public:
  /// `fastPath`: the run steps with Dormand-Prince. Off with a compliant socket: the least
  /// potential energy is taken at zero deflection, and a sagging socket can go below it.
  EarlyThighFailure(const SwingSetup& setup, const SwingOptions& options, bool fastPath);
  bool isAllowed() const { return allowed_; }
  /// Checks step end `now` (of state `s`) of a swing whose thigh has not reached its target
  /// (`thighReached` false): past the hip moment's last breakpoint (the moment constant, M),
  /// with the thigh below its target and inside its range, the leg's energy E = kinetic +
  /// gravity potential + what the knee law stores - M hip is compared with the least the
  /// thigh at its target needs (LegModel::calcLeastPotentialEnergy - M target).
  void check(const StepEnd& now, const SimTK::State& s, const LegModel& leg, bool thighReached);
  /// Once true, the thigh cannot reach its target: a passive knee law and hip stop only take
  /// energy away.
  bool cannotEnd() const { return shortfall_ > 0; }
  double getShortfall() const { return shortfall_; }                 ///< J below the least needed
  double getFinalHipMoment() const { return hipMomentFinal_; }       ///< N m, M
  double getConstantFrom() const { return hipMomentConstantFrom_; }  ///< s, the last breakpoint

 private:
  const SwingSetup& setup_;
  bool allowed_;
  double hipMomentConstantFrom_;  // s
  double hipMomentFinal_;         // N m
  double thighTargetEnergy_;      // J, found when first needed (NaN before)
  double shortfall_ = 0;          // J: > 0 once the thigh cannot reach its target
};

}  // namespace swingsim
