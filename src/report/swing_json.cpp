#include "report/swing_json.h"

#include <cmath>
#include <cstdlib>

#include "core/input_error.h"

namespace swingsim {

void writeSwingResultJson(JsonWriter& j, const std::string& participant, double lowering, const SwingResult& r) {
  j.beginObject();
  j.field("participant", participant);
  j.field("lowering_m", lowering);
  j.field("swing_time_s", r.swingTime);
  j.field("peak_knee_flexion_deg", r.peakKneeFlexion * kRadToDeg);
  j.field("peak_knee_flexion_time_s", r.peakKneeFlexionTime);
  j.field("bounce", r.bounce);
  j.field("min_toe_clearance_m", r.minToeClearance);
  j.key("events").beginArray();
  for (const auto& e : r.events) {
    j.beginObject().field("name", e.name).field("time_s", e.time).endObject();
  }
  j.endArray();
  j.endObject();
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
