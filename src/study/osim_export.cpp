#include "study/osim_export.h"

#include <algorithm>
#include <array>
#include <filesystem>

#include "core/input_error.h"
#include "io/osim_model.h"
#include "io/osim_model_writer.h"
#include "swing/swing_simulation.h"

namespace swingsim {
namespace {

// Under a measured drive the model starts where the swing does, at the record's toe-off (its
// first sample): the hip at the thigh's angle less the pelvis tilt (hip_flexion is in the
// pelvis), the knee at the record's when it has one and `knee_start` is measured; a measured
// pelvis moves on its planar joint from its toe-off pose (a column the record lacks keeps the
// welded pose's value).
void applyMeasuredDrive(const ThighKinematics& t, const InitialConditions& initial, OsimLegPlacement& place) {
  const bool hasPelvis = !t.pelvisX.empty() || !t.pelvisY.empty() || !t.pelvisTilt.empty();
  if (hasPelvis) {
    const std::array<double, 2> hip = place.hipOffsetInPelvis.value_or(std::array<double, 2>{0, 0});
    OsimPelvisPose at{0, -hip[0], place.hipHeight - hip[1]};
    if (!t.pelvisTilt.empty()) at.tilt = t.pelvisTilt.front();
    if (!t.pelvisX.empty()) at.x = t.pelvisX.front();
    if (!t.pelvisY.empty()) at.y = t.pelvisY.front();
    place.measuredPelvis = at;
  }
  if (!t.hipFlexion.empty())
    place.initial.hipFlexion = t.hipFlexion.front() - (t.pelvisTilt.empty() ? 0.0 : t.pelvisTilt.front());
  if (!t.kneeFlexion.empty() && initial.kneeStart == KneeStart::kMeasured)
    place.initial.kneeFlexion = t.kneeFlexion.front();
}

// The participant's hip height, body mass, initial state, hip range and its knee model's stop.
OsimLegPlacement makePlacement(const Participant& p, const KneeModel& knee, char side) {
  OsimLegPlacement place;
  place.modelName = p.name;
  place.side = side;
  place.hipHeight = calcHipHeight(p);
  place.hipOffsetInPelvis = p.hipOffsetInPelvis;
  place.bodyMass = p.bodyMass;
  place.initial = p.initial;
  place.hipRange = p.hipRange;
  place.kneeMinFlexion = knee.spec.stop.lower;
  // No flexion stop: the knee's physical range, 180 deg.
  place.kneeMaxFlexion = std::min(knee.spec.stop.upper.value_or(kKneeFlexionLimit), kKneeFlexionLimit);
  if (p.drive == SwingDrive::kThighKinematics) applyMeasuredDrive(p.thighKinematics, p.initial, place);
  return place;
}

std::string makeHeader(const Participant& p, const std::string& kneeName, const OsimExportOptions& a,
                       const std::string& stoName) {
  const char side = a.side;
  const std::string s(1, side);
  const std::string added = a.added ? ", added mass " + formatNumber(a.added->mass) + " kg " +
                                          formatNumber(a.added->distanceBelowKnee) +
                                          " m below the knee (body added_mass_" + s + ", welded to tibia_" + s + ")"
                                    : "";
  return "Written by `swingsim export-osim` from " + std::filesystem::path(p.path).filename().string() +
         " (participant " + p.name + "), " + (side == 'l' ? "left" : "right") + " leg, knee axis lowered " +
         formatNumber(a.lowering) + " m, knee model " + kneeName + added +
         ".\n  The planar leg swingsim simulates (docs/export-osim.md): pelvis welded to the ground with the hip at " +
         "0.530 x height (plus a stated toe_clearance.hip_rise_m), or, under a measured drive with a pelvis, on a "
         "PlanarJoint (pelvis_tilt, pelvis_tx, pelvis_ty) at its toe-off pose; femur, tibia: the thigh and shank (hip "
         "and knee pins); talus: the whole foot, welded at the ankle, "
         "perpendicular to the shank;\n  calcn and toes: massless, welded; toes' origin is the toe tip. Only Izz is "
         "swingsim's; "
         "Ixx, Iyy are a thin rod's. Shapes (cylinders, brick, ellipsoid) are for display only. No muscles, no knee "
         "damper: a model to play the swing on, not to simulate it again.\n"
         "  Play the swing: File > Load Motion " +
         stoName + " (written by `swingsim simulate" + (side == 'l' ? " --side l" : "") +
         "` for this participant at this lowering); its " + makeOsimHipCoordinate(side) + " and " +
         makeOsimKneeCoordinate(side) +
         " columns (degrees, inDegrees=yes, knee negative in flexion) are the coordinates, as in a lab's IK .mot.\n";
}

}  // namespace

std::string formatParticipantOsim(const Participant& p, const KneeModel& knee, const OsimExportOptions& o,
                                  const std::string& stoName) {
  const LegGeometry geometry = calcLegGeometry(p, o.lowering, o.added.value_or(AddedMass{}));
  return formatOsimModel(makeOsimLegModel(geometry, makePlacement(p, knee, o.side)),
                         makeHeader(p, knee.name, o, stoName));
}

std::string formatParticipantOsim(const Participant& p, const KneeModel& knee, double lowering,
                                  const std::string& stoName) {
  return formatParticipantOsim(p, knee, OsimExportOptions{'r', lowering, std::nullopt}, stoName);
}

}  // namespace swingsim
