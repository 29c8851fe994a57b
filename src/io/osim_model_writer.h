#pragma once
// swingsim's leg as an OpenSim 4 model (.osim XML, written with tinyxml2), in the structs the
// reader (io/osim_model.h) fills, so that what is written is what `import-osim` reads back:
// ground -> pelvis (welded, placing the hip) -> femur_r (PinJoint hip, coordinate
// hip_flexion) -> tibia_r (PinJoint knee, knee_flexion, flexion positive) -> talus_r (welded
// at the ankle, the whole foot) -> calcn_r -> toes_r (massless, welded; toes_r's origin is the
// toe tip). `swingsim export-osim`, docs/export-osim.md.
#include <array>
#include <optional>
#include <string>

#include "io/osim_model.h"
#include "model/leg_parameters.h"

namespace swingsim {

/// Where the leg stands and how its coordinates start and range (besides its segments).
struct OsimLegPlacement {
  std::string modelName;
  double hipHeight = 0;  ///< m, the hip joint centre above the ground
  /// m, the hip joint centre in the pelvis frame (x forward, y up); nullopt = at its origin.
  std::optional<std::array<double, 2>> hipOffsetInPelvis;
  /// kg, the whole body; what the leg does not carry is the pelvis's (welded to the ground, so
  /// it does not move), so that the model's mass is the body mass. 0 = a massless pelvis.
  double bodyMass = 0;
  InitialConditions initial;  ///< the coordinates' default values and speeds
  HipRange hipRange;          ///< hip_flexion's range, rad
  double kneeMinFlexion = 0;  ///< rad, knee_flexion's range: the hyperextension stop
  double kneeMaxFlexion = 0;  ///< rad
};

/// The leg `geometry` (calcLegGeometry at the lowering wanted) as bodies and joints. Body
/// frames: origin at the segment's proximal joint, y along the segment towards that joint
/// (femur and tibia), x forward along the foot (talus); the COM at (0, -com) or (com, 0).
/// Inertias: Izz is the geometry's; Ixx and Iyy those of a thin rod along the segment (the
/// tensor must be physical, and a planar swing never uses them). Throws std::invalid_argument
/// if the geometry has an added shank mass (not exported) or a range is empty.
OsimModel makeOsimLegModel(const LegGeometry& geometry, const OsimLegPlacement& placement);

/// The OpenSim 4 XML of `model` (Version 40000): gravity -y (9.81 m/s^2, swingsim's), each
/// body, each joint with offset frames `<body>_offset` and its coordinates, `header` (several
/// lines allowed) as the first comment. Numbers in full precision (formatNumber).
std::string formatOsimModel(const OsimModel& model, const std::string& header);

}  // namespace swingsim
