#pragma once
// Where the model's missing quantity acts, as a figure (docs/diagnosis.md, "The missing
// moment, where it acts" and "The cylinder's missing force"): over the measured state (knee
// flexion; piston position), one panel for each direction of motion; each sample's missing
// moment or force, the 95 % noise band of one sample (the median of the samples' bands in
// the regions' bins), and the regions that depart from zero beyond their band shaded and
// labelled with their mean.
#include <string>

#include "identify/missing_force.h"
#include "identify/missing_moment.h"

namespace swingsim {

/// The swing's missing knee moment, standalone SVG; `title` heads it. Only for a map with
/// samples (`missing.kneeDeg`).
std::string renderMissingMomentSvg(const MissingMoment& missing, const std::string& title);

/// The cylinder's missing force over piston position, standalone SVG; `title` heads it. Only
/// for a map with samples (`missing.positionMm`).
std::string renderMissingForceSvg(const MissingForce& missing, const std::string& title);

}  // namespace swingsim
