#pragma once
// A simulated swing sampled over time (what the trajectory CSV and .sto files hold).
#include <cstddef>
#include <vector>

namespace swingsim {

struct SwingTrajectory {
  std::vector<double> time, hipFlexion, kneeFlexion, hipFlexionRate, kneeFlexionRate, hipMoment, kneeMoment;
  std::vector<double> kneeX, kneeY, ankleX, ankleY, toeX, toeY;  ///< ground frame, hip at (0, hipHeight)
  std::size_t size() const { return time.size(); }
};

}  // namespace swingsim
