#pragma once
// The missing knee moment as a figure (docs/diagnosis.md, "The missing moment, where it
// acts"): over measured knee flexion, one panel while the knee flexes and one while it
// extends; each sample's missing moment, the 95 % noise band of one sample (the median of the
// samples' bands in 5-deg bins), and the regions that depart from zero beyond their band
// shaded and labelled with their mean moment.
#include <string>

#include "identify/missing_moment.h"

namespace swingsim {

/// The standalone SVG; `title` heads it. Only for a map with samples (`missing.kneeDeg`).
std::string renderMissingMomentSvg(const MissingMoment& missing, const std::string& title);

}  // namespace swingsim
