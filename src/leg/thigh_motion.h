#pragma once
// A measured thigh angle as a smooth function of time, for prescribing it on the hip
// (the measured thigh drive): a quintic smoothing spline through the samples, its smoothing chosen
// by generalized cross-validation (GCVSPL: Woltring 1986, "A Fortran package for
// generalized, cross-validatory spline smoothing and differentiation", Adv. Eng. Software
// 8:104-113; the standard smoother of joint angles in gait analysis, here Simbody's
// SimTK::SplineFitter). A quintic spline has continuous first to fourth derivatives, so
// the prescribed angle, rate and acceleration are consistent (each the exact derivative of
// the one before) and the acceleration has no jumps for an integrator to stumble over.
//
// The interface is plain doubles: the Simbody chain (PrescribedThighMotion) and the
// reference integrator (swing/reference_swing.h) evaluate the same function.
#include <memory>

#include "model/leg_parameters.h"

namespace swingsim {

class ThighMotion {
 public:
  /// Fewest samples the quintic fit accepts (GCVSPL needs at least 2 x 3 for degree 5).
  static constexpr int kMinSamples = 6;
  /// Fits the spline. Throws InputError naming kinematics.path if there are fewer than
  /// kMinSamples samples, a time does not increase strictly, the first time is not 0 or an
  /// angle is not finite.
  explicit ThighMotion(const ThighKinematics& kinematics);

  double calcAngle(double t) const;         ///< rad
  double calcRate(double t) const;          ///< rad/s
  double calcAcceleration(double t) const;  ///< rad/s^2
  /// s: the last sample. Past it the spline continues as its last polynomial piece, so a
  /// swing driven by it must end by then (simulateSwing caps its time limit there).
  double getEndTime() const;
  /// RMS of spline minus samples, rad: what the smoothing removed.
  double getFitRms() const;
  const ThighKinematics& getKinematics() const;

 private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
};

}  // namespace swingsim
