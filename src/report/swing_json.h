#pragma once
// JSON for one swing result.
#include <string>

#include "io/json_file.h"
#include "swing/swing_simulation.h"

namespace swingsim {

/// Writes {"participant", "lowering_m", "swing_time_s", "peak_knee_flexion_deg",
/// "peak_knee_flexion_time_s", "bounce", "min_toe_clearance_m", "events": [{name, time_s}]}.
Json makeSwingResultJson(const std::string& participant, double lowering, const SwingResult& r);

}  // namespace swingsim
