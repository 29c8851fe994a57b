#pragma once
// swingsim's leg as an OpenSim 4 model (.osim XML, written with tinyxml2), in the structs the
// reader (io/osim_model.h) fills, so that what is written is what `import-osim` reads back:
// ground -> pelvis (welded, placing the hip) -> femur_<s> (PinJoint hip_<s>, coordinate
// hip_flexion_<s>) -> tibia_<s> (PinJoint knee_<s>, knee_angle_<s>, negative in flexion, as
// OpenSim's gait models) -> talus_<s> (welded at the ankle, the whole foot) -> calcn_<s> ->
// toes_<s> (massless, welded; toes_<s>'s origin is the toe tip), an added shank mass welded to
// tibia_<s>, and shapes to see it by. `swingsim export-osim`, docs/export-osim.md.
#include <array>
#include <optional>
#include <string>

#include "io/osim_model.h"
#include "model/leg_parameters.h"

namespace swingsim {

/// The pelvis of a measured drive at toe-off, in the ground frame (x forward, y up), as a
/// lab's IK file gives it (pelvis_tilt, pelvis_tx, pelvis_ty).
struct OsimPelvisPose {
  double tilt = 0;      ///< rad, about +z (forward tilt positive, as OpenSim's pelvis_tilt)
  double x = 0, y = 0;  ///< m, the pelvis origin
};

/// Where the leg stands and how its coordinates start and range (besides its segments).
struct OsimLegPlacement {
  std::string modelName;
  char side = 'r';       ///< 'r' or 'l': the bodies, joints and coordinates are named for that leg
  double hipHeight = 0;  ///< m, the hip joint centre above the ground
  /// m, the hip joint centre in the pelvis frame (x forward, y up); nullopt = at its origin.
  std::optional<std::array<double, 2>> hipOffsetInPelvis;
  /// kg, the whole body; what the leg does not carry is the pelvis's (welded to the ground, so
  /// it does not move), so that the model's mass is the body mass. 0 = a massless pelvis.
  double bodyMass = 0;
  InitialConditions initial;  ///< the coordinates' default values and speeds
  HipRange hipRange;          ///< hip flexion's range, rad
  double kneeMinFlexion = 0;  ///< rad, knee flexion's range (flexion positive): the hyperextension stop
  double kneeMaxFlexion = 0;  ///< rad
  /// A measured pelvis (a drive with pelvis columns): the pelvis moves in the plane on a
  /// PlanarJoint ground_pelvis with the gait models' pelvis_tilt, pelvis_tx, pelvis_ty,
  /// starting here, so a lab's IK file moves it; nullopt: welded with the hip at hipHeight.
  std::optional<OsimPelvisPose> measuredPelvis;
};

/// The leg `geometry` (calcLegGeometry at the lowering wanted) as bodies and joints. Body
/// frames: origin at the segment's proximal joint, y along the segment towards that joint
/// (femur and tibia), x forward along the foot (talus); the COM at (0, -com) or (com, 0).
/// Inertias: Izz is the geometry's; Ixx and Iyy those of a thin rod along the segment (the
/// tensor must be physical, and a planar swing never uses them). The geometry's added shank
/// mass, if any, is a point mass on body added_mass_<s>, welded to the tibia on its axis at its
/// distance below the knee (the model's mass is then the body mass plus the added mass).
/// Shapes: io/osim_leg_shapes.h. Throws std::invalid_argument for a side other than r or l, an
/// added mass off the shank, or an empty range.
OsimModel makeOsimLegModel(const LegGeometry& geometry, const OsimLegPlacement& placement);

/// The OpenSim 4 XML of `model` (Version 40000): gravity -y (9.81 m/s^2, swingsim's), each
/// body, each joint with offset frames `<body>_offset` and its coordinates, `header` (several
/// lines allowed) as the first comment. Numbers in full precision (formatNumber).
std::string formatOsimModel(const OsimModel& model, const std::string& header);

}  // namespace swingsim
