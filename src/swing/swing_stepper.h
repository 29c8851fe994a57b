#pragma once
// One integrator step at a time over the Simbody leg: Simbody's own integrators (with or
// without its event handlers), or Dormand-Prince over Simbody realizations with its loose
// settle dwell (Bogacki-Shampine) and checkpoint.
#include <Simbody.h>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "numerics/bogacki_shampine.h"
#include "numerics/dormand_prince.h"
#include "swing/simbody_ode.h"
#include "swing/swing_simulation.h"

namespace swingsim {

/// Simbody's integrator `kind`; throws std::invalid_argument for Dormand-Prince (ours).
std::unique_ptr<SimTK::Integrator> makeIntegrator(SwingIntegrator kind, const SimTK::MultibodySystem& system);

// One integrator step at a time, from toe-off to the time limit: Simbody's integrators
// (with or without its event handlers) or our Dormand-Prince over Simbody realizations.
class SwingStepper {
 public:
  virtual ~SwingStepper() = default;
  /// Takes one step, not past tLimit; returns false once tLimit has been reached.
  virtual bool step(double tLimit) = 0;
  /// The state at the last step end, realized to Acceleration.
  virtual const SimTK::State& getState() = 0;
  virtual int getNumSteps() const = 0;
  virtual int getNumRealizations() const = 0;
};

class SimbodyStepper final : public SwingStepper {
 public:
  SimbodyStepper(const SimTK::MultibodySystem& system, const SimTK::State& initial, const SwingOptions& options,
                 double tLimit)
      : system_(system), integrator_(makeIntegrator(options.integrator, system)) {
    integrator_->setAccuracy(options.accuracy);
    // Return after every internal step: the loop stops as soon as the swing end plus the
    // settle dwell has passed, finds the fast path's events and samples the output by
    // interpolation between steps.
    integrator_->setReturnEveryInternalStep(true);
    integrator_->setFinalTime(tLimit);
    if (options.simbodyEvents) {
      timeStepper_ = std::make_unique<SimTK::TimeStepper>(system, *integrator_);
      timeStepper_->setReportAllSignificantStates(true);
      timeStepper_->initialize(initial);
    } else {
      integrator_->initialize(initial);
    }
  }
  bool step(double tLimit) override {
    const auto status = timeStepper_ ? timeStepper_->stepTo(tLimit) : integrator_->stepTo(tLimit);
    return status != SimTK::Integrator::EndOfSimulation;
  }
  const SimTK::State& getState() override {
    const SimTK::State& s = integrator_->getState();
    system_.realize(s, SimTK::Stage::Acceleration);
    return s;
  }
  int getNumSteps() const override { return integrator_->getNumStepsTaken(); }
  int getNumRealizations() const override { return integrator_->getNumRealizations(); }

 private:
  const SimTK::MultibodySystem& system_;
  std::unique_ptr<SimTK::Integrator> integrator_;
  std::unique_ptr<SimTK::TimeStepper> timeStepper_;
};

// Dormand-Prince 5(4) (dormand_prince.h) on the Simbody leg's (q, u, z): six realizations
// per step, first same as last, and nothing else per step.
class DormandPrinceStepper final : public SwingStepper {
 public:
  /// Takes `initial` over as its working state (realized at the step ends and stages).
  DormandPrinceStepper(const SimTK::MultibodySystem& system, SimTK::State initial, double accuracy,
                       std::vector<double> breakpoints)
      : work_(std::move(initial)), ode_(system, work_), y_(ode_.numStates()), breakpoints_(std::move(breakpoints)) {
    ode_.readState(work_, y_.data());
    start(work_.getTime(), accuracy);
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
    if (loose_)
      loose_->step(tStop);
    else
      dp_->step(tStop);
    return getTime() < tLimit;
  }
  const SimTK::State& getState() override {
    return ode_.realizeAt(getTime(), loose_ ? loose_->getState() : dp_->getState());
  }
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
  SimTK::State work_;
  SimbodyOde ode_;
  std::vector<double> y_;
  std::vector<double> breakpoints_;            // s
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

}  // namespace swingsim
