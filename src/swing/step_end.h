#pragma once
// The joint state at an integrator step's end, and what is read off between two step ends
// without a realization: cubic Hermite interpolants, their roots, and trajectory samples.
#include <Simbody.h>

#include <array>
#include <optional>

#include "leg/leg_model.h"
#include "model/leg_parameters.h"
#include "model/swing_trajectory.h"

namespace swingsim {

// Cubic Hermite on [0, 1] from values y0, y1 and derivatives d0, d1 (per unit time) over
// a step of length h.
inline double calcHermite(double y0, double d0, double y1, double d1, double h, double s) {
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
  const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
  return h00 * y0 + h10 * h * d0 + h01 * y1 + h11 * h * d1;
}

// Work bookkeeping at a step end: each knee law part's work, then the hip's, J.
constexpr int kMaxWorkCauses = 12;

// Joint state at the end of an integrator step: angles, rates, accelerations, moments, and
// with energy tracking the kinetic energy and the work done so far.
struct StepEnd {
  double t, hip, knee, hipRate, kneeRate, hipAcc, kneeAcc, hipMoment, kneeMoment;
  SocketDeflection socket;  ///< a compliant socket's (LegModel::getSocketDeflection); zero without one
  double kinetic = 0;
  int numWork = 0;
  std::array<double, kMaxWorkCauses> work{};
};

/// The step end of `s` (realized here to Acceleration); with `trackEnergy` its kinetic
/// energy and the work of each knee law part and of the hip.
StepEnd readStepEnd(const LegModel& leg, const SimTK::State& s, bool trackEnergy);

/// One output sample: joint state, moments, and the landmarks by planar kinematics (with a
/// compliant socket's deflection `socket`).
void appendSample(SwingTrajectory& tr, const LegGeometry& g, double hipHeight, double t, double hip, double knee,
                  double hipRate, double kneeRate, double hipMoment, double kneeMoment,
                  const SocketDeflection& socket = {});

/// The samples from `nextSample` (s, advanced past them) to step end b, on the Hermite
/// interpolants of the step a-b: they cost no realization, so the integrator chooses its
/// steps by accuracy alone, not by the output interval.
void appendSamples(const StepEnd& a, const StepEnd& b, double& nextSample, double interval, const LegGeometry& g,
                   double hipHeight, SwingTrajectory& tr);

// Time crossing resolution of the fast path, s: far below the 0.1 ms the swing time is
// converged to, and far above round-off in t.
constexpr double kCrossingTimeTol = 1e-12;

// Root of f on [lo, hi] within [0, 1] (f(lo) and f(hi) bracket it, not both zero), by the
// Illinois variant of regula falsi, to kCrossingTimeTol / h in s.
template <class F>
inline double findRoot(const F& f, double h, double lo = 0, double hi = 1) {
  double s0 = lo, s1 = hi, f0 = f(lo), f1 = f(hi);
  if (f1 == 0) return hi;
  int side = 0;
  for (int it = 0; it < 100 && (s1 - s0) * h > kCrossingTimeTol; ++it) {
    double s = (s0 * f1 - s1 * f0) / (f1 - f0);
    if (!(s > s0 && s < s1)) s = 0.5 * (s0 + s1);
    const double fs = f(s);
    if (fs == 0) return s;
    if ((fs < 0) == (f1 < 0)) {
      s1 = s;
      f1 = fs;
      if (side == -1) f0 *= 0.5;
      side = -1;
    } else {
      s0 = s;
      f0 = fs;
      if (side == 1) f1 *= 0.5;
      side = 1;
    }
  }
  return 0.5 * (s0 + s1);
}

/// The time (s) in (a.t, b.t] at which the knee, on the Hermite interpolant of the step a-b,
/// first rises above `level` (rad), or nullopt if it stays at or below it. A knee that
/// rises above and comes back within the step (its interpolated peak above `level`) counts.
std::optional<double> findKneeRisingAbove(const StepEnd& a, const StepEnd& b, double level);

}  // namespace swingsim
