#include "report/swing_json.h"

#include <cmath>
#include <cstdlib>

#include "core/input_error.h"

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

AddedMass parseAddedMass(const std::string& text) {
  auto at = text.find('@');
  char* e1 = nullptr;
  char* e2 = nullptr;
  AddedMass m;
  if (at != std::string::npos) {
    const std::string a = text.substr(0, at), b = text.substr(at + 1);
    m.mass = std::strtod(a.c_str(), &e1);
    m.distanceBelowKnee = std::strtod(b.c_str(), &e2);
    if (!a.empty() && !b.empty() && e1 == a.c_str() + a.size() && e2 == b.c_str() + b.size() &&
        std::isfinite(m.mass) && std::isfinite(m.distanceBelowKnee) && m.mass >= 0 && m.distanceBelowKnee >= 0)
      return m;
  }
  throw InputError("--add-mass: expected KG@METRES below the knee, e.g. 0.5@0.20 (got '" + text + "')");
}

}  // namespace swingsim
