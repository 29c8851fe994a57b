#pragma once
// Figures of one simulated swing.
#include <string>

#include "model/swing_trajectory.h"

namespace swingsim {

/// Hip and knee moments (N m, + = flexion) over the swing, SVG: with the measured thigh
/// drive the hip moment is the one the prescribed motion needs.
std::string formatSwingMomentsSvg(const SwingTrajectory& trajectory, const std::string& title);

}  // namespace swingsim
