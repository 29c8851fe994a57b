#include "io/osim_leg_shapes.h"

#include <cmath>

#include "core/units.h"

namespace swingsim {

void addOsimLegShapes(OsimModel& m, const LegGeometry& g, char side, const OsimShapeSizes& z) {
  const std::string s(1, side);
  for (OsimBody& b : m.bodies) {
    if (b.name == "pelvis") {
      b.shapes.push_back({"pelvis_shape",
                          "Ellipsoid",
                          Eigen::Vector3d::Zero(),
                          {z.pelvisRadii[0], z.pelvisRadii[1], z.pelvisRadii[2]}});
    } else if (b.name == "femur_" + s) {
      b.shapes.push_back(
          {"femur_" + s + "_shape", "Cylinder", {0, -g.thighLength / 2, 0}, {z.thighRadius, g.thighLength / 2}});
    } else if (b.name == "tibia_" + s) {
      b.shapes.push_back(
          {"tibia_" + s + "_shape", "Cylinder", {0, -g.shankLength / 2, 0}, {z.pylonRadius, g.shankLength / 2}});
    } else if (b.name == "talus_" + s) {
      b.shapes.push_back({"talus_" + s + "_shape",
                          "Brick",
                          {g.footLength / 2, 0, 0},
                          {g.footLength / 2, z.footHalfHeight, z.footHalfWidth}});
    } else if (b.name == "added_mass_" + s && b.mass > 0) {
      // A sphere of the mass's volume: r = (3 m / (4 pi rho))^(1/3).
      b.shapes.push_back({"added_mass_" + s + "_shape",
                          "Sphere",
                          Eigen::Vector3d::Zero(),
                          {std::cbrt(3 * b.mass / (4 * kPi * z.addedMassDensity))}});
    }
  }
}

}  // namespace swingsim
