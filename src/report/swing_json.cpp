#include "report/swing_json.h"

#include <cmath>
#include <optional>

namespace swingsim {

Json makeStopImpactJson(const StopImpact& im) {
  Json work = Json::object();
  for (const auto& w : im.work) work[w.cause] = w.work;
  return {{"time_s", im.time},
          {"impact_rate_rad_s", im.impactRate},
          {"rebound_rate_rad_s", im.reboundRate},
          {"restitution", im.restitution},
          {"max_penetration_deg", im.maxPenetration * kRadToDeg},
          {"rebound_height_deg", im.reboundHeight * kRadToDeg},
          {"kinetic_energy_at_contact_J", im.kineticEnergy},
          {"work_to_rebound_top_J", work}};
}

Json makeSwingResultJson(const std::string& participant, double lowering, const SwingResult& r) {
  Json events = Json::array();
  for (const auto& e : r.events) events.push_back({{"name", e.name}, {"time_s", e.time}});
  Json impacts = Json::array();
  for (const auto& im : r.impacts) impacts.push_back(makeStopImpactJson(im));
  // Absent quantities are null (swing time: NaN when the swing did not end).
  const std::optional<KneePeak>& peak = r.peakKneeFlexion;
  Json json = {{"participant", participant},
               {"lowering_m", lowering},
               {"swing_time_s", std::isfinite(r.swingTime) ? Json(r.swingTime) : Json(nullptr)},
               {"first_zone_entry_s", jsonOrNull(calcFirstZoneEntry(r))},
               {"peak_knee_flexion_deg", peak ? Json(peak->flexion * kRadToDeg) : Json(nullptr)},
               {"peak_knee_flexion_time_s", peak ? Json(peak->time) : Json(nullptr)},
               {"bounce", r.bounce},
               {"bounces", r.bounces},
               {"bounce_height_deg", jsonOrNull(r.bounceHeight, kRadToDeg)},
               {"stop_impacts", impacts},
               {"min_toe_clearance_m", jsonOrNull(r.minToeClearance)},
               {"events", events}};
  if (r.socketPeak)
    json["socket_peak"] = {{"piston_m", r.socketPeak->piston}, {"rotation_deg", r.socketPeak->rotation * kRadToDeg}};
  if (const auto& e = r.trialEnd) {
    json["trial_end"] = {{"unmet", e->unmet},
                         {"time_s", e->time},
                         {"knee_flexion_deg", e->kneeFlexion * kRadToDeg},
                         {"thigh_flexion_deg", e->thighFlexion * kRadToDeg},
                         {"thigh_peak_deg", e->thighPeak * kRadToDeg},
                         {"thigh_target_deg", e->thighTarget * kRadToDeg},
                         {"zone_of_stability_deg", e->zoneOfStability * kRadToDeg},
                         {"settle_dwell_done_s", jsonOrNull(e->dwellDone)},
                         {"description", e->describe()}};
  }
  return json;
}

Json makeSimulateJson(const SwingSetup& setup, const SwingResult& r) {
  Json json = makeSwingResultJson(setup.participant.name, setup.lowering, r);
  json["drive"] = driveKey(setup.participant.drive);
  json["drive_description"] = describeDrive(setup.participant);
  return json;
}

Json makeSwingTimeJumpJson(const SwingTimeJump& jump) {
  const auto entry = [](const PieceSample& s) { return s.firstZoneEntry ? Json(*s.firstZoneEntry) : Json(nullptr); };
  return {{"lowering_m", jump.calcLowering()},
          {"from_m", jump.below.lowering},
          {"to_m", jump.above.lowering},
          {"swing_time_from_s", jump.below.swingTime},
          {"swing_time_to_s", jump.above.swingTime},
          {"bounces_from", jump.below.bounces},
          {"bounces_to", jump.above.bounces},
          {"first_zone_entry_from_s", entry(jump.below)},
          {"first_zone_entry_to_s", entry(jump.above)},
          {"cause", jump.describeCause()},
          {"text", jump.describe()}};
}

}  // namespace swingsim
