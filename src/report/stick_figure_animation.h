#pragma once
// One swing as an animated stick figure for the HTML report: hip-thigh, knee-shank and
// ankle-foot lines whose endpoints follow the sampled trajectory in real time (SVG SMIL
// <animate>, no script), looping, with the toe's path and the ground drawn still.
#include <string>

#include "swing/swing_simulation.h"

namespace swingsim {

constexpr double kStickFigurePxPerMetre = 300;  ///< the figure's scale, px per m, equal on both axes
constexpr double kStickFigureFrameStep = 0.02;  ///< s between the trajectory samples used as frames
constexpr double kStickFigureHold = 0.5;        ///< s the last pose stays before the loop restarts

/// An inline <svg> of `r`'s swing from toe-off (t = 0) to its swing end (r.swingTime), hip
/// at (0, hipHeight) m as in the trajectory, ground at 0. Each line (class "thigh", "shank",
/// "foot") animates x1, y1, x2, y2 through trajectory samples about kStickFigureFrameStep
/// apart (values= with keyTimes= at their times), so every frame is a pose the simulation
/// computed; the duration is the swing time plus kStickFigureHold, repeated indefinitely.
/// Throws std::invalid_argument if the trajectory is empty or the swing time not positive.
std::string renderStickFigureAnimation(const SwingResult& r, double hipHeight);

}  // namespace swingsim
