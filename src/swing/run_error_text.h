#pragma once
// Every RunError one swing can end with, worded in one place: who (participant, lowering),
// when (the time and joint state), and the likely cause or what to change.
#include <Simbody.h>

#include <exception>
#include <string>

#include "core/input_error.h"
#include "leg/leg_model.h"
#include "swing/run_budget.h"
#include "swing/swing_log.h"
#include "swing/swing_simulation.h"

namespace swingsim {

/// "at t = 0.1234 s: hip flexion 1.2 deg (3 deg/s), knee flexion 4.5 deg (-6 deg/s)".
std::string describeState(const LegModel& leg, const SimTK::State& s);

class RunErrorText {
 public:
  /// All references must outlive this object.
  RunErrorText(const SwingSetup& setup, const SwingOptions& options, const LegModel& leg, double timeLimit);

  /// The integrator threw `e` at state `s`.
  RunError integratorFailed(const SimTK::State& s, const std::exception& e) const;
  /// A budget (RunBudget) ran out after `realizations`.
  RunError overBudget(RunBudget::Spent spent, int realizations, const SimTK::State& s) const;
  /// The joint angles are no longer finite.
  RunError diverged(const SimTK::State& s) const;
  /// The thigh left the hip's range (plus its slack).
  RunError hipLeftRange(const SimTK::State& s) const;
  /// The knee flexion passed kKneeFlexionLimit at `crossingTime` s; `s` is the state at the
  /// end of the step in which it did.
  RunError kneeLeftRange(const SimTK::State& s, double crossingTime) const;
  /// The thigh cannot reach its target any more (EarlyThighFailure): the hip moment
  /// `hipMomentFinal` N m constant from `constantFrom` s, the energy `shortfall` J short.
  RunError cannotEnd(const SimTK::State& s, double hipMomentFinal, double constantFrom, double shortfall) const;
  /// The time limit came before the swing end rule was met; `log` says which part was not.
  RunError didNotEnd(const SimTK::State& s, const SwingLog& log) const;

 private:
  std::string who() const;  // "P1 at lowering 0.05 m"
  const SwingSetup& setup_;
  const SwingOptions& options_;
  const LegModel& leg_;
  double timeLimit_;
};

}  // namespace swingsim
