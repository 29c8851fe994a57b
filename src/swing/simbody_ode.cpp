#include "swing/simbody_ode.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace swingsim {

using namespace SimTK;

namespace {

bool hasPrescribedMotion(const SimbodyMatterSubsystem& matter) {
  for (MobilizedBodyIndex i(0); i < matter.getNumBodies(); ++i)
    if (matter.getMobilizedBody(i).hasMotion()) return true;
  return false;
}

}  // namespace

SimbodyOde::SimbodyOde(const MultibodySystem& system, State& state)
    : system_(system),
      state_(state),
      nq_(state.getNQ()),
      nu_(state.getNU()),
      nz_(state.getNZ()),
      prescribed_(hasPrescribedMotion(system.getMatterSubsystem())) {
  if (system.getMatterSubsystem().getNumConstraints() > 0)
    throw std::invalid_argument("SimbodyOde: systems with constraints need projection; use a Simbody integrator");
}

void SimbodyOde::concatenate(const Vector& q, const Vector& u, const Vector& z, double* y) const {
  for (int i = 0; i < nq_; ++i) y[i] = q[i];
  for (int i = 0; i < nu_; ++i) y[nq_ + i] = u[i];
  for (int i = 0; i < nz_; ++i) y[nq_ + nu_ + i] = z[i];
}

void SimbodyOde::readState(const State& s, double* y) const { concatenate(s.getQ(), s.getU(), s.getZ(), y); }

bool SimbodyOde::isAt(double t, const double* y) const {
  if (state_.getSystemStage() < Stage::Acceleration || state_.getTime() != t) return false;
  const Vector &q = state_.getQ(), &u = state_.getU(), &z = state_.getZ();
  for (int i = 0; i < nq_; ++i)
    if (q[i] != y[i]) return false;
  for (int i = 0; i < nu_; ++i)
    if (u[i] != y[nq_ + i]) return false;
  for (int i = 0; i < nz_; ++i)
    if (z[i] != y[nq_ + nu_ + i]) return false;
  return true;
}

const State& SimbodyOde::realizeAt(double t, const double* y) const {
  if (isAt(t, y)) return state_;
  state_.updTime() = t;
  Vector& q = state_.updQ();
  for (int i = 0; i < nq_; ++i) q[i] = y[i];
  Vector& u = state_.updU();
  for (int i = 0; i < nu_; ++i) u[i] = y[nq_ + i];
  if (nz_ > 0) {
    Vector& z = state_.updZ();
    for (int i = 0; i < nz_; ++i) z[i] = y[nq_ + nu_ + i];
  }
  if (prescribed_) {
    // A prescribed motion (the measured thigh drive) owns its q and u: write them from
    // their functions of time, as Simbody's own integrators do (System::prescribe).
    system_.realize(state_, Stage::Time);
    system_.prescribeQ(state_);
    system_.realize(state_, Stage::Position);
    system_.prescribeU(state_);
  }
  system_.realize(state_, Stage::Acceleration);
  ++realizations_;
  return state_;
}

void SimbodyOde::calcDerivatives(double t, const double* y, double* dydt) const {
  const State& s = realizeAt(t, y);
  concatenate(s.getQDot(), s.getUDot(), s.getZDot(), dydt);
  // Say it here, where the cause is: a NaN passed on would next surface in Simbody as
  // "Inertia matrix contains a NaN", pointing away from the force element that made it.
  for (int i = 0; i < numStates(); ++i) {
    if (!std::isfinite(dydt[i])) {
      const char* kind = i < nq_ ? "q" : i < nq_ + nu_ ? "u" : "z";
      const int index = i < nq_ ? i : i < nq_ + nu_ ? i - nq_ : i - nq_ - nu_;
      throw std::runtime_error("the derivative of " + std::string(kind) + "[" + std::to_string(index) +
                               "] is not finite at t = " + std::to_string(t) +
                               " s (a force element, e.g. the knee or hip law, returned NaN or infinity)");
    }
  }
}

}  // namespace swingsim
