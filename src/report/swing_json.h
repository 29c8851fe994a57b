#pragma once
// JSON for one swing result.
#include <string>

#include "io/json_file.h"
#include "sweep/swing_time_jumps.h"
#include "swing/swing_simulation.h"

namespace swingsim {

/// Writes {"participant", "lowering_m", "swing_time_s", "first_zone_entry_s" (calcFirstZoneEntry,
/// null if none), "peak_knee_flexion_deg",
/// "peak_knee_flexion_time_s", "bounce", "bounces", "bounce_height_deg", "stop_impacts":
/// [{time_s, impact_rate_rad_s, rebound_rate_rad_s, restitution, max_penetration_deg,
/// rebound_height_deg, kinetic_energy_at_contact_J, work_to_rebound_top_J: {cause: J}}],
/// "min_toe_clearance_m", "events": [{name, time_s}], "trial_end" (a measured trial cut
/// before the swing ended)}. A quantity the swing did not have is null, never a marker:
/// swing_time_s (no swing end), peak_knee_flexion_deg and _time_s (no knee peak),
/// bounce_height_deg (no bounce peak), min_toe_clearance_m (no knee peak),
/// trial_end.settle_dwell_done_s (unless the unmet condition is the settle dwell).
/// {time_s, impact_rate_rad_s, rebound_rate_rad_s, restitution, max_penetration_deg,
/// rebound_height_deg, kinetic_energy_at_contact_J, work_to_rebound_top_J: {cause: J}}.
Json makeStopImpactJson(const StopImpact& im);

Json makeSwingResultJson(const std::string& participant, double lowering, const SwingResult& r);

/// What `swingsim simulate --json` writes: makeSwingResultJson of the setup's participant
/// and lowering, plus "drive" (driveKey) and "drive_description" (describeDrive).
Json makeSimulateJson(const SwingSetup& setup, const SwingResult& r);

/// One jump of the swing time along the lowering (sweep/swing_time_jumps.h): {"lowering_m",
/// "from_m", "to_m", "swing_time_from_s", "swing_time_to_s", "bounces_from", "bounces_to",
/// "first_zone_entry_from_s", "first_zone_entry_to_s" (null if the knee never entered),
/// "cause", "text"}; "from" is the smaller lowering.
Json makeSwingTimeJumpJson(const SwingTimeJump& jump);

}  // namespace swingsim
