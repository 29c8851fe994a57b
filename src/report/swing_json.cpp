#include "report/swing_json.h"

namespace swingsim {

Json makeSwingResultJson(const std::string& participant, double lowering, const SwingResult& r) {
  Json events = Json::array();
  for (const auto& e : r.events) events.push_back({{"name", e.name}, {"time_s", e.time}});
  return {{"participant", participant},
          {"lowering_m", lowering},
          {"swing_time_s", r.swingTime},
          {"peak_knee_flexion_deg", r.peakKneeFlexion * kRadToDeg},
          {"peak_knee_flexion_time_s", r.peakKneeFlexionTime},
          {"bounce", r.bounce},
          {"min_toe_clearance_m", r.minToeClearance},
          {"events", events}};
}

}  // namespace swingsim
