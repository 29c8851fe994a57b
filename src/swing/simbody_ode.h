#pragma once
// A Simbody system's continuous state y = (q, u, z) as an OdeSystem (dormand_prince.h):
// each derivative evaluation writes t and y into one State, realizes it to Acceleration
// and reads (qdot, udot, zdot) back. This lets our Dormand-Prince 5(4) step the Simbody
// leg with no State copies and no per-step bookkeeping beyond its six realizations
// (Simbody's own integrators spend about as much again per step on State copies,
// projection and error norms as they spend realizing). Valid for systems without
// constraints (the leg has none): nothing is projected.
#include <Simbody.h>

#include "numerics/dormand_prince.h"

namespace swingsim {

class SimbodyOde final : public OdeSystem {
 public:
  /// `state` is the work State the evaluations realize (it must outlive this object and
  /// belong to `system`, realized at least to Model stage). Throws std::invalid_argument
  /// if the system has constraints.
  SimbodyOde(const SimTK::MultibodySystem& system, SimTK::State& state);

  int numStates() const override { return nq_ + nu_ + nz_; }
  void calcDerivatives(double t, const double* y, double* dydt) const override;

  /// Copies the State's (q, u, z) into y (numStates() values).
  void readState(const SimTK::State& s, double* y) const;
  /// The work State realized to Acceleration at (t, y). A no-op when the last evaluation
  /// was at exactly (t, y): after DormandPrince::step() that is the step end (first same
  /// as last), so reading the step end costs no realization.
  const SimTK::State& realizeAt(double t, const double* y) const;

  /// Realizations done so far.
  long getNumRealizations() const { return realizations_; }

 private:
  bool isAt(double t, const double* y) const;
  /// (q, u, z)-shaped vectors laid end to end into y (numStates() values).
  void concatenate(const SimTK::Vector& q, const SimTK::Vector& u, const SimTK::Vector& z, double* y) const;
  const SimTK::MultibodySystem& system_;
  SimTK::State& state_;
  int nq_, nu_, nz_;
  bool prescribed_;  // the system has a prescribed motion: prescribe q and u at each evaluation
  mutable long realizations_ = 0;
};

}  // namespace swingsim
