#pragma once
// JSON for one swing result, and the `KG@METRES` added-mass syntax shared by the CLI.
#include <string>

#include "io/json_file.h"
#include "swing/swing_simulation.h"

namespace swingsim {

/// Writes {"participant", "lowering_m", "swing_time_s", "peak_knee_flexion_deg",
/// "peak_knee_flexion_time_s", "bounce", "min_toe_clearance_m", "events": [{name, time_s}]}.
Json makeSwingResultJson(const std::string& participant, double lowering, const SwingResult& r);

/// Parses "0.5@0.2" (0.5 kg at 0.2 m below the knee). Throws InputError.
AddedMass parseAddedMass(const std::string& text);

}  // namespace swingsim
