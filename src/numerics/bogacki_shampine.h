#pragma once
// An adaptive explicit Runge-Kutta integrator of order 3(2): Bogacki & Shampine (1989),
// "A 3(2) pair of Runge-Kutta formulas", Appl. Math. Lett. 2(4):321-325 (MATLAB's ode23).
// Three derivative evaluations per step (four stages, the last one is the next step's
// first: FSAL), against Dormand-Prince's six: the cheaper method where a loose tolerance
// or a stability limit, not the order, decides the step (the swing's loose settle dwell,
// SwingOptions::dwellAccuracyFactor). Step-size control as DormandPrince's, with the
// error's order 3.
#include <vector>

#include "numerics/dormand_prince.h"

namespace swingsim {

/// Bogacki-Shampine RK3(2) with an embedded error estimate, FSAL and step-size control. All
/// buffers are allocated in the constructor: stepping never allocates.
///
/// A step is accepted when err = sqrt(mean_i ((y3_i - y2_i) / (absTol + relTol *
/// max(|y_i(t)|, |y_i(t+h)|)))^2) <= 1; the next step is h * clamp(0.9 err^(-1/3), 0.2, 5),
/// not larger than the last try after a rejection.
class BogackiShampine {
 public:
  /// relTol, absTol > 0; throws std::invalid_argument otherwise.
  BogackiShampine(const OdeSystem& system, double relTol, double absTol);

  /// Sets time, state (numStates() values), f(t0, y0) (numStates() values; the caller
  /// usually has it from the integrator it takes over from) and the first step to try
  /// (> 0, s).
  void initialize(double t0, const double* y0, const double* dydt0, double firstStep);

  /// Takes one accepted step, shortened if needed so that it ends exactly at tStop
  /// (> getTime()). Throws std::runtime_error if the step size underflows or the state
  /// becomes non-finite.
  void step(double tStop);

  double getTime() const { return t_; }
  const double* getState() const { return y_.data(); }
  /// f at the current step end.
  const double* getDerivatives() const { return k1_.data(); }
  /// The step size the controller plans next, s.
  double getPlannedStep() const { return h_; }
  int numStates() const { return n_; }
  long getNumSteps() const { return numSteps_; }
  long getNumRejectedSteps() const { return numRejected_; }
  long getNumEvaluations() const { return numEvaluations_; }

 private:
  const OdeSystem& system_;
  int n_;
  double relTol_, absTol_;
  double t_ = 0;
  double h_ = 0;  // proposed size of the next step
  std::vector<double> y_, yNew_, yStage_, yErr_;
  std::vector<double> k1_, k2_, k3_, k4_;
  long numSteps_ = 0, numRejected_ = 0, numEvaluations_ = 0;
};

}  // namespace swingsim
