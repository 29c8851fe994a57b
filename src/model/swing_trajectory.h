#pragma once
// A simulated swing sampled over time (what the trajectory CSV and .sto files hold).
#include <array>
#include <cstddef>
#include <vector>

#include "model/leg_parameters.h"

namespace swingsim {

struct SwingTrajectory {
  std::vector<double> time, hipFlexion, kneeFlexion, hipFlexionRate, kneeFlexionRate, hipMoment, kneeMoment;
  std::vector<double> kneeX, kneeY, ankleX, ankleY, toeX, toeY;  ///< ground frame, hip at (0, hipHeight)
  /// A compliant socket's deflection at each sample (empty without one; not a file column).
  std::vector<SocketDeflection> socket;
  std::size_t size() const { return time.size(); }
  /// Every column, in declaration order (to reserve or cut them all alike).
  std::array<std::vector<double>*, 13> columns() {
    return {&time,      &hipFlexion, &kneeFlexion, &hipFlexionRate, &kneeFlexionRate,
            &hipMoment, &kneeMoment, &kneeX,       &kneeY,          &ankleX,
            &ankleY,    &toeX,       &toeY};
  }
};

}  // namespace swingsim
