#pragma once
// The hip moment that drives the swing, as a function of time since toe-off. Burkett 2004
// measured it per participant on an isokinetic dynamometer but did not publish it; see the
// docs/assumptions.md ("Hip moment") for the profile we use and how it is calibrated.
#include <string>
#include <utility>
#include <vector>

namespace swingsim {

struct HipMomentProfile {
  enum class Kind { kBiphasicSine, kTable };
  Kind kind = Kind::kBiphasicSine;

  // kBiphasicSine: a hip-flexion half-sine then a hip-extension half-sine (the
  // concentric/concentric flexion-extension cycle of the dynamometer), then zero.
  double flexionAmplitude = 30;     ///< N m, peak hip flexion moment
  double flexionDuration = 0.20;    ///< s
  double extensionAmplitude = 15;   ///< N m, peak hip extension moment (magnitude)
  double extensionDuration = 0.20;  ///< s

  // kTable: moment (N m, + = flexion) at strictly increasing times (s); monotone cubic
  // (PCHIP slopes, knee/monotone_cubic.h) between samples, held at the end values outside.
  std::vector<double> times, moments;

  /// Time scale tau, the one calibrated number per participant (`swingsim calibrate`):
  /// the profile runs tau times slower with moments divided by tau^2, i.e.
  /// M(t) = base(t / tau) / tau^2. For a purely inertial chain this stretches the whole
  /// swing by exactly tau (dimensional analysis); gravity and knee damping make it
  /// approximate, and the calibration scan checks that swing time rises monotonically.
  /// (An amplitude scale was tried first and rejected: swing time is not monotonic in it.)
  double timeScale = 1.0;

  /// Hip moment at time t (s), N m, positive = flexion.
  double calcMoment(double t) const;
  /// Times (s, increasing, > 0) where the moment's time derivative jumps: the ends of the
  /// half-sines, or the first and last table samples (the monotone cubic is C1 between).
  /// An integrator that ends a step there keeps its order (Hairer I, Sec. II.6).
  std::vector<double> calcBreakpoints() const;
  /// The least and the greatest moment at any time from t (s) on, N m: bounds of what the
  /// hip can still do (the half-sines' remaining peaks, the table's remaining samples, which
  /// the monotone cubic never passes, and the held end value).
  std::pair<double, double> calcRangeFrom(double t) const;
  /// Throws std::invalid_argument with a description if the profile is unusable.
  void validate() const;
  std::string describe() const;
};

}  // namespace swingsim
