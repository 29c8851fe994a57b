#pragma once
// One swing from toe-off to its end (simulateSwing's work): builds the leg, steps it, hands
// each step end to the swing events and to the end-of-swing rules, each a unit of its own:
// the settle rule (SwingLog), the loose settle dwell (SettleDwell), the early settle end
// (EarlySettleEnd), the early thigh failure (EarlyThighFailure) and the budgets (RunBudget);
// every failure is worded by RunErrorText. docs/swing-options.md says what each option does.
#include <Simbody.h>

#include <memory>
#include <optional>

#include "leg/hip_path.h"
#include "leg/leg_model.h"
#include "leg/thigh_motion.h"
#include "swing/early_settle_end.h"
#include "swing/early_thigh_failure.h"
#include "swing/knee_climb.h"
#include "swing/run_budget.h"
#include "swing/run_error_text.h"
#include "swing/settle_dwell.h"
#include "swing/step_end.h"
#include "swing/stop_impact_tracker.h"
#include "swing/swing_log.h"
#include "swing/swing_simulation.h"
#include "swing/swing_stepper.h"

namespace swingsim {

class SwingRun {
 public:
  /// Builds the leg and its integrator. Throws InputError without a knee law or with an
  /// unusable measured thigh, std::invalid_argument for Simbody's events with Dormand-Prince.
  /// `setup` and `options` must outlive the run.
  SwingRun(const SwingSetup& setup, const SwingOptions& options);
  SwingRun(const SwingRun&) = delete;
  SwingRun& operator=(const SwingRun&) = delete;

  /// Runs the swing to its end (once). Throws RunError as simulateSwing says.
  SwingResult run();

 private:
  void startTrajectory();
  bool takeStep();  // false once the time limit is reached
  // The step end `now` of state `s`: budgets, divergence, events, impacts, samples, hip range.
  void recordStep(const StepEnd& now, const SimTK::State& s);
  void redoLooseDwell(StepEnd& now);
  // Whether the run stops at `now` without a swing end (a result), or throws why it must.
  bool stopsUnended(const StepEnd& now, const SimTK::State& s, bool more);
  TrialEnd calcTrialEnd(const StepEnd& now) const;
  SwingResult finish();

  const SwingSetup& setup_;
  const SwingOptions& options_;
  const Participant& p_;
  const SwingEndRule& rule_;
  const LegGeometry geometry_;
  std::optional<ThighMotion> thighMotion_;  // the measured thigh drive: the thigh follows its spline
  std::optional<HipPath> hipPath_;          // a measured pelvis: the hip follows it
  LegModel leg_;
  const double timeLimit_;  // s: the rule's, or the measured trial's end if sooner
  const double hipHeight_;  // m
  SwingLog log_;
  const KneeClimb climb_;  // the knee law's stop and the parts the early settle end weighs
  std::unique_ptr<SwingStepper> stepper_;
  DormandPrinceStepper* dormandPrince_ = nullptr;  // stepper_ on the fast path
  RunErrorText errors_;
  RunBudget budget_;
  SettleDwell dwell_;
  std::optional<EarlySettleEnd> earlyEnd_;
  EarlyThighFailure thighFailure_;
  SwingResult result_;
  StepEnd previous_{};
  std::optional<StopImpactTracker> impacts_;
  double nextSample_ = 0;      // s
  double candidateTime_ = -1;  // s: the swing end candidate whose realizations were counted
  double thighPeak_ = 0;       // rad: highest thigh flexion at a step end (TrialEnd); from toe-off on
};

}  // namespace swingsim
