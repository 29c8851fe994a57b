#pragma once
// An adaptive explicit Runge-Kutta integrator of order 5(4): Dormand & Prince (1980),
// "A family of embedded Runge-Kutta formulae", J. Comp. Appl. Math. 6:19-26, with the
// step-size control and the 4th-order continuous extension (dense output) of Hairer,
// Norsett & Wanner, "Solving Ordinary Differential Equations I", 2nd ed., Sec. II.4-II.6
// (their code DOPRI5). Written here, with no Simbody, so the reference swing
// (reference_swing.h) is independent of the multibody code it checks.
#include <vector>

namespace swingsim {

/// A first-order ODE system dy/dt = f(t, y) with a fixed number of states.
class OdeSystem {
 public:
  virtual ~OdeSystem() = default;
  virtual int numStates() const = 0;
  /// Writes f(t, y) to dydt[0..numStates()).
  virtual void calcDerivatives(double t, const double* y, double* dydt) const = 0;
};

/// Dormand-Prince RK5(4) with an embedded error estimate, FSAL, step-size control and dense
/// output. All buffers are allocated in the constructor: stepping never allocates.
///
/// Error control (Hairer I, Eq. II.4.11): a step is accepted when
///   err = sqrt(mean_i ((y5_i - y4_i) / (absTol + relTol * max(|y_i(t)|, |y_i(t+h)|)))^2) <= 1,
/// and the next step is h * clamp(0.9 err^(-0.17) errPrev^0.04, 0.2, 5) (PI control), not
/// larger than the last try after a rejection.
class DormandPrince {
 public:
  /// relTol, absTol > 0 (relative and absolute local error per step, in the states' units).
  /// Throws std::invalid_argument otherwise.
  DormandPrince(const OdeSystem& system, double relTol, double absTol);

  /// Largest step allowed, s (default: unlimited).
  void setMaxStep(double maxStep);
  /// Sets time and state (numStates() values) and chooses the first step size
  /// (Hairer I, Sec. II.4, "starting step size").
  void initialize(double t0, const double* y0);

  /// Takes one accepted step, shortened if needed so that it ends exactly at tStop
  /// (> getTime()). Throws std::runtime_error if the step size underflows or the state
  /// becomes non-finite.
  void step(double tStop);

  /// Steps until getTime() == tEnd exactly.
  void integrateTo(double tEnd);

  double getTime() const { return t_; }
  const double* getState() const { return y_.data(); }
  /// f at the current step end (the next step's first stage).
  const double* getDerivatives() const { return k1_.data(); }
  /// The step size the controller plans next, s.
  double getPlannedStep() const { return h_; }
  /// Start time and state of the last accepted step (the dense output's interval).
  double getStepStartTime() const { return tPrev_; }
  const double* getStepStartState() const { return yPrev_.data(); }

  /// State component i at time t inside the last accepted step [getStepStartTime(),
  /// getTime()], from the 4th-order continuous extension (Hairer I, Eq. II.6.7; DOPRI5's
  /// CONTD5). Exact at both ends.
  double interpolate(double t, int i) const;
  /// All components at t (numStates() values to y).
  void interpolate(double t, double* y) const;

  int numStates() const { return n_; }
  long getNumSteps() const { return numSteps_; }
  long getNumRejectedSteps() const { return numRejected_; }
  long getNumEvaluations() const { return numEvaluations_; }

 private:
  void prepareDenseOutput(double h);

  const OdeSystem& system_;
  int n_;
  double relTol_, absTol_;
  double maxStep_;
  double t_ = 0, tPrev_ = 0;
  double h_ = 0;           // proposed size of the next step
  double errPrev_ = 1e-4;  // error norm of the last accepted step (PI control)
  std::vector<double> y_, yPrev_, yStage_, yErr_;
  std::vector<double> k1_, k2_, k3_, k4_, k5_, k6_, k7_;
  std::vector<double> cont1_, cont2_, cont3_, cont4_, cont5_;  // dense output coefficients
  long numSteps_ = 0, numRejected_ = 0, numEvaluations_ = 0;
};

}  // namespace swingsim
