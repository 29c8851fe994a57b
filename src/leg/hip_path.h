#pragma once
// The hip joint centre's path in space when the measured drive has the pelvis: the hip sits
// at (pelvisX, pelvisY) + R(pelvisTilt) * hipOffsetInPelvis, and each of its x and y is
// smoothed by the same GCV quintic spline as the thigh angle (ThighMotion; Woltring 1986),
// so position, velocity and acceleration are consistent (each the exact derivative of the
// one before). The pelvis is smoothed through the hip centre, not column by column, so the
// hip's acceleration is the derivative of the smoothed position the swing feels.
//
// The interface is plain doubles: the Simbody chain (LegModel's hip carrier) and the
// reference integrator (swing/reference_swing.h) evaluate the same function.
#include <array>
#include <memory>
#include <optional>
#include <string>

#include "model/leg_parameters.h"

namespace swingsim {

class HipPath {
 public:
  /// The kinematics has the pelvis's translation (pelvisX or pelvisY): the hip moves.
  static bool hasPelvis(const ThighKinematics& kinematics);
  /// Fits the path. Throws InputError naming `participantPath` and hip_offset_in_pelvis_m if
  /// the offset is missing, and naming kinematics.path if a pelvis column does not have one
  /// value per time or a value is not finite (the times are ThighMotion's to check).
  HipPath(const ThighKinematics& kinematics, const std::optional<std::array<double, 2>>& hipOffsetInPelvis,
          const std::string& participantPath = "");

  /// The hip joint centre in the ground frame of the recording, m (x forward, y up). Outside
  /// the samples the path continues as its end's polynomial piece.
  std::array<double, 2> calcPosition(double t) const;
  std::array<double, 2> calcVelocity(double t) const;      ///< m/s
  std::array<double, 2> calcAcceleration(double t) const;  ///< m/s^2
  /// The hip centre at sample i before smoothing, m.
  std::array<double, 2> getSample(std::size_t i) const;
  /// RMS distance of the smoothed path from the samples, m: what the smoothing removed.
  double getFitRms() const;

 private:
  std::array<double, 2> calcDerivative(int order, double t) const;
  struct Impl;
  std::shared_ptr<const Impl> impl_;
};

}  // namespace swingsim
