#pragma once
// What OpenSim draws of the exported leg: OpenSim 4's analytic shapes (no mesh files) on each
// body, sized from the leg's lengths; for display only (no mass). docs/export-osim.md.
#include "io/osim_model.h"
#include "model/leg_parameters.h"

namespace swingsim {

/// Radii of the drawn shapes, m. Display only, assumed: a thigh of about 0.38 m
/// circumference (radius 0.06 m; adult thighs measure roughly 0.45-0.60 m at mid-thigh, the
/// residual limb in its socket less), a 30 mm prosthetic pylon tube (radius 0.015 m, the
/// common tube diameter), a foot 0.08 m wide and 0.05 m high, a steel added mass (7850 kg/m^3),
/// a pelvis 0.16 m deep, 0.12 m high and 0.24 m wide.
struct OsimShapeSizes {
  double pelvisRadii[3] = {0.08, 0.06, 0.12};
  double thighRadius = 0.06;
  double pylonRadius = 0.015;
  double footHalfWidth = 0.04, footHalfHeight = 0.025;
  double addedMassDensity = 7850;  ///< kg/m^3
};

/// Adds to `model`'s bodies (named as makeOsimLegModel names them on `side`): an ellipsoid for
/// the pelvis, a cylinder along the thigh and one along the shank (each from its proximal
/// joint to its distal one), a brick for the foot from the ankle to the toe tip, a sphere of
/// the added mass's volume at its place. Bodies it does not know are left bare.
void addOsimLegShapes(OsimModel& model, const LegGeometry& geometry, char side, const OsimShapeSizes& sizes = {});

}  // namespace swingsim
