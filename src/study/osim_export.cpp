#include "study/osim_export.h"

#include <algorithm>
#include <filesystem>

#include "core/input_error.h"
#include "io/osim_model_writer.h"
#include "swing/swing_simulation.h"

namespace swingsim {
namespace {

// The participant's hip height, body mass, initial state, hip range and its knee model's stop.
OsimLegPlacement makePlacement(const Participant& p, const KneeModel& knee) {
  OsimLegPlacement place;
  place.modelName = p.name;
  place.hipHeight = calcHipHeight(p);
  place.hipOffsetInPelvis = p.hipOffsetInPelvis;
  place.bodyMass = p.bodyMass;
  place.initial = p.initial;
  place.hipRange = p.hipRange;
  place.kneeMinFlexion = knee.spec.stop.lower;
  // No flexion stop: the knee's physical range, 180 deg.
  place.kneeMaxFlexion = std::min(knee.spec.stop.upper.value_or(kKneeFlexionLimit), kKneeFlexionLimit);
  return place;
}

std::string makeHeader(const Participant& p, const std::string& kneeName, double lowering, const std::string& stoName) {
  return "Written by `swingsim export-osim` from " + std::filesystem::path(p.path).filename().string() + " (participant " + p.name +
         "), knee axis lowered " + formatNumber(lowering) + " m, knee model " + kneeName +
         ".\n  The planar leg swingsim simulates (docs/export-osim.md): pelvis welded to the ground with the hip at " +
         "0.530 x height (plus a stated toe_clearance.hip_rise_m); femur_r, tibia_r: the thigh and shank (hip and knee pins); talus_r: the whole foot, welded at the ankle, "
         "perpendicular to the shank;\n  calcn_r and toes_r: massless, welded; toes_r's origin is the toe tip. Only Izz is swingsim's; "
         "Ixx, Iyy are a thin rod's. No muscles, no knee damper: a model to play the swing on, not to simulate it again.\n"
         "  Play the swing: File > Load Motion " + stoName + " (written by `swingsim simulate` for this participant at this lowering);"
         " its hip_flexion and knee_flexion columns (degrees, inDegrees=yes) are the coordinates.\n";
}

}  // namespace

std::string formatParticipantOsim(const Participant& p, const KneeModel& knee, double lowering, const std::string& stoName) {
  const LegGeometry geometry = calcLegGeometry(p, lowering);
  return formatOsimModel(makeOsimLegModel(geometry, makePlacement(p, knee)), makeHeader(p, knee.name, lowering, stoName));
}

}  // namespace swingsim
