#pragma once
// A scaled OpenSim model (.osim, OpenSim 4 XML) read with tinyxml2, as far as a planar
// swing leg needs it: each body's mass, COM and inertia, each joint's parent and child
// frames and its pose at the reference configuration (every coordinate 0), and the
// participant built from one leg of it (`swingsim import-osim`, docs/import-osim.md). The
// writer of swingsim's own leg as a model (`swingsim export-osim`) is io/osim_model_writer.h.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "model/leg_parameters.h"

namespace swingsim {

/// A shape OpenSim draws on a body (its analytic Geometry components, no mesh file): in a
/// PhysicalOffsetFrame of the body at `centre`; `kind` the element, `size` its numbers in m:
/// Cylinder {radius, half_height} (axis along the frame's y), Ellipsoid {radii x, y, z},
/// Brick {half_lengths x, y, z}, Sphere {radius}. For display only: no mass.
struct OsimShape {
  std::string name, kind;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< m, in the body frame
  std::vector<double> size;
};

struct OsimBody {
  std::string name;
  int line = 0;                   ///< XML line of <Body>
  double mass = 0;                ///< kg
  Eigen::Vector3d massCenter;     ///< m, in the body frame
  Eigen::Matrix3d inertia;        ///< kg m^2, about the COM, in the body frame
  std::vector<OsimShape> shapes;  ///< written, not read (the reader leaves it empty)
};

/// The names of the exported model's hip and knee coordinates on `side` ('r' or 'l'), as
/// OpenSim's gait models name them (hip_flexion_r, knee_angle_r: Gait2354, Gait10dof18musc),
/// which are also the angle columns of the trajectory .sto that `simulate` writes
/// (io/trajectory_writer.h), so that OpenSim plays that .sto, and a lab's IK file, on the model.
std::string makeOsimHipCoordinate(char side);
std::string makeOsimKneeCoordinate(char side);

/// One of a joint's coordinates (OpenSim's <Coordinate>).
struct OsimCoordinate {
  std::string name;
  double defaultValue = 0;            ///< rad (a rotation) or m, <default_value>
  double rangeMin = 0, rangeMax = 0;  ///< rad or m, <range>
  bool clamped = false;               ///< <clamped>: OpenSim holds the coordinate inside its range
  std::string note;                   ///< written as an XML comment before it ("" = none); not read
};

struct OsimJoint {
  std::string name, type;  ///< type: the element (CustomJoint, PinJoint, WeldJoint, ...)
  int line = 0;
  std::string parentBody, childBody;  ///< body names ("ground" for the ground)
  Eigen::Isometry3d parentFrame;      ///< joint frame F in the parent body (its offset frame)
  Eigen::Isometry3d childFrame;       ///< joint frame M in the child body
  /// M in F with every coordinate at 0 (a CustomJoint's SpatialTransform evaluated there,
  /// so a knee whose centre moves along a spline is taken at full extension).
  Eigen::Isometry3d motionAtZero;
  bool centreMoves = false;                 ///< a translation of the SpatialTransform depends on a coordinate
  std::vector<OsimCoordinate> coordinates;  ///< the joint's <coordinates>, in file order

  /// The joint centre (origin of M) in the parent body frame at the reference pose.
  Eigen::Vector3d calcCentreInParent() const { return (parentFrame * motionAtZero).translation(); }
  /// The child body's pose in the parent body frame at the reference pose.
  Eigen::Isometry3d calcChildInParent() const { return parentFrame * motionAtZero * childFrame.inverse(); }
};

struct OsimModel {
  std::string path, name;
  int bodySetLine = 0, jointSetLine = 0;  ///< XML lines of <BodySet> and <JointSet>
  std::vector<OsimBody> bodies;
  std::vector<OsimJoint> joints;

  /// Throws InputError `file: body NAME: ...` when no body has that name.
  const OsimBody& getBody(const std::string& name) const;
  /// The joint whose child frame is on body `child`; throws InputError if none.
  const OsimJoint& getJointTo(const std::string& child) const;
  /// Sum of every body's mass, kg.
  double calcTotalMass() const;
};

/// Reads a .osim file. Throws InputError `file:line: element: expected ... (got ...)` for
/// text that is not XML, a model without a BodySet or JointSet, a body without a positive
/// finite mass or in grams, a negative inertia, a body or joint name given twice, two joints
/// into one body (io/osim_model_checks.h), a frame that names no body, or a transform
/// function it cannot evaluate.
OsimModel loadOsimModel(const std::string& path);
/// Same, from XML text (tests); `path` names it in messages.
OsimModel parseOsimModel(const std::string& text, const std::string& path);

/// OpenSim's SimmSpline (Forsythe, Malcolm & Moler 1977, Computer Methods for Mathematical
/// Computations, routine SPLINE: end third derivatives from cubics through the 4 end points)
/// at `x`; `natural`: NaturalCubicSpline (zero second derivative at both ends).
double calcOsimSplineValue(const std::vector<double>& xs, const std::vector<double>& ys, double x, bool natural);

/// What `import-osim` takes besides the model.
struct OsimImportOptions {
  char side = 'r';                            ///< 'r' or 'l': the bodies femur_r, tibia_r, talus_r, ...
  std::string name;                           ///< participant name ("" = the model's name and side)
  std::string kneeModelPath;                  ///< knee model YAML written as knee_model
  double kneeFriction = 0;                    ///< N m
  std::optional<double> shankMass, footMass;  ///< kg: the prosthesis's parts (inertia scales with mass)
  std::optional<double> footLength;           ///< m, ankle to toe
  std::optional<double> height;               ///< m, standing height
  /// The prosthesis by its catalogue parts (model/prosthesis_parts.h): they replace the
  /// model's shank and foot masses for the segments they make.
  std::optional<ProsthesisPartsChoice> parts;
};

/// The participant and, line by line, where each of its numbers comes from.
struct OsimParticipant {
  Participant participant;
  std::string provenance;  ///< comment lines (without '#') for the file's header
};

/// Thigh from femur_<side>, shank from tibia_<side>, foot from talus, calcn and toes combined
/// (planar, sagittal x-y plane, inertia about z), lengths from joint centres at the reference
/// pose, hip_offset_in_pelvis from the hip's centre in the pelvis; every other field the
/// project's default. Throws InputError, at the element concerned, for a missing body or
/// joint, a chain pelvis-femur-tibia-talus-calcn-toes with a link missing or an extra body
/// in it, or a segment the participant file would refuse (checkOsimLeg).
OsimParticipant calcOsimParticipant(const OsimModel& model, const OsimImportOptions& options);

}  // namespace swingsim
