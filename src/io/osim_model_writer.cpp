#include "io/osim_model_writer.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/input_error.h"
#include "core/units.h"
#include "io/osim_leg_shapes.h"

namespace swingsim {

namespace {

using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;

Eigen::Isometry3d makeTranslation(double x, double y) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(x, y, 0);
  return t;
}

// Izz as given; Ixx, Iyy of a thin rod along `axis` (0 = x, 1 = y): zero about the rod, Izz
// about the other axis, so the tensor satisfies the triangle inequality OpenSim checks.
Eigen::Matrix3d makeRodInertia(double izz, int axis) {
  Eigen::Matrix3d i = Eigen::Matrix3d::Zero();
  i(2, 2) = izz;
  i(1 - axis, 1 - axis) = izz;
  return i;
}

OsimBody makeBody(const std::string& name, double mass, const Eigen::Vector3d& com, const Eigen::Matrix3d& inertia) {
  OsimBody b;
  b.name = name;
  b.mass = mass;
  b.massCenter = com;
  b.inertia = inertia;
  return b;
}

OsimJoint makeJoint(const std::string& name, const std::string& type, const std::string& parent,
                    const Eigen::Isometry3d& inParent, const std::string& child, const Eigen::Isometry3d& inChild) {
  OsimJoint j;
  j.name = name;
  j.type = type;
  j.parentBody = parent;
  j.childBody = child;
  j.parentFrame = inParent;
  j.childFrame = inChild;
  j.motionAtZero = Eigen::Isometry3d::Identity();
  return j;
}

OsimCoordinate makeCoordinate(const std::string& name, double defaultValue, double rangeMin, double rangeMax,
                              const std::string& note) {
  if (!(rangeMin < rangeMax))
    throw std::invalid_argument("makeOsimLegModel: " + name + ": empty range [" + formatNumber(rangeMin) + ", " +
                                formatNumber(rangeMax) + "] rad");
  OsimCoordinate c;
  c.name = name;
  c.defaultValue = defaultValue + 0.0;  // (+ 0.0 writes -0 as 0)
  c.rangeMin = rangeMin + 0.0;
  c.rangeMax = rangeMax + 0.0;
  c.note = note;
  return c;
}

std::string formatDegrees(double rad) { return formatNumber(std::round(rad * kRadToDeg * 1000) / 1000 + 0.0); }

// ---- XML ----------------------------------------------------------------------------------

// (+ 0.0 writes -0 as 0.)
std::string formatVector(const Eigen::Vector3d& v) {
  return formatNumber(v.x() + 0.0) + " " + formatNumber(v.y() + 0.0) + " " + formatNumber(v.z() + 0.0);
}

XMLElement* addText(XMLElement* parent, const char* name, const std::string& text) {
  XMLElement* e = parent->InsertNewChildElement(name);
  e->SetText(text.c_str());
  return e;
}

XMLElement* addNamed(XMLElement* parent, const char* type, const std::string& name) {
  XMLElement* e = parent->InsertNewChildElement(type);
  e->SetAttribute("name", name.c_str());
  return e;
}

// XML comment text: "--" may not occur inside a comment.
std::string makeCommentText(std::string text) {
  for (std::size_t at = text.find("--"); at != std::string::npos; at = text.find("--", at)) text.replace(at, 2, "- -");
  return " " + text + " ";
}

std::string framePath(const std::string& body) { return body == "ground" ? "/ground" : "/bodyset/" + body; }

// A shape in its own PhysicalOffsetFrame among the body's <components> (OpenSim 4's analytic
// Geometry: Cylinder radius/half_height, Ellipsoid radii, Brick half_lengths, Sphere radius).
void addShape(XMLElement* components, const OsimShape& shape) {
  XMLElement* frame = addNamed(components, "PhysicalOffsetFrame", shape.name + "_frame");
  addText(frame, "socket_parent", "..");
  addText(frame, "translation", formatVector(shape.centre));
  addText(frame, "orientation", "0 0 0");
  XMLElement* g = addNamed(frame->InsertNewChildElement("attached_geometry"), shape.kind.c_str(), shape.name);
  addText(g, "socket_frame", "..");
  std::string numbers;
  for (double x : shape.size) numbers += (numbers.empty() ? "" : " ") + formatNumber(x);
  if (shape.kind == "Cylinder") {
    addText(g, "radius", formatNumber(shape.size.at(0)));
    addText(g, "half_height", formatNumber(shape.size.at(1)));
  } else if (shape.kind == "Ellipsoid") {
    addText(g, "radii", numbers);
  } else if (shape.kind == "Brick") {
    addText(g, "half_lengths", numbers);
  } else {
    addText(g, "radius", formatNumber(shape.size.at(0)));
  }
}

void addBody(XMLElement* objects, const OsimBody& b) {
  XMLElement* e = addNamed(objects, "Body", b.name);
  addText(e, "mass", formatNumber(b.mass));
  addText(e, "mass_center", formatVector(b.massCenter));
  const Eigen::Matrix3d& i = b.inertia;  // OpenSim's order: Ixx Iyy Izz Ixy Ixz Iyz, about the COM
  addText(e, "inertia",
          formatNumber(i(0, 0)) + " " + formatNumber(i(1, 1)) + " " + formatNumber(i(2, 2)) + " " +
              formatNumber(i(0, 1)) + " " + formatNumber(i(0, 2)) + " " + formatNumber(i(1, 2)));
  if (b.shapes.empty()) return;
  XMLElement* components = e->InsertNewChildElement("components");
  for (const auto& shape : b.shapes) addShape(components, shape);
}

// OpenSim's orientation: body-fixed x-y-z angles (a, b, c), R = Rx(a) Ry(b) Rz(c), rad; away
// from b = +-90 deg, which the writer never needs.
Eigen::Vector3d calcBodyFixedXyz(const Eigen::Matrix3d& r) {
  const double b = std::asin(std::clamp(r(0, 2), -1.0, 1.0));
  return {std::atan2(-r(1, 2), r(2, 2)), b, std::atan2(-r(0, 1), r(0, 0))};
}

void addOffsetFrame(XMLElement* frames, const std::string& name, const std::string& body,
                    const Eigen::Isometry3d& pose) {
  XMLElement* f = addNamed(frames, "PhysicalOffsetFrame", name);
  addText(f, "socket_parent", framePath(body));
  addText(f, "translation", formatVector(pose.translation()));
  addText(f, "orientation", formatVector(calcBodyFixedXyz(pose.linear())));
}

void addCoordinate(XMLElement* coordinates, const OsimCoordinate& c) {
  if (!c.note.empty()) coordinates->InsertNewComment(makeCommentText(c.note).c_str());
  XMLElement* e = addNamed(coordinates, "Coordinate", c.name);
  addText(e, "default_value", formatNumber(c.defaultValue));
  addText(e, "default_speed_value", "0");
  addText(e, "range", formatNumber(c.rangeMin) + " " + formatNumber(c.rangeMax));
  addText(e, "clamped", c.clamped ? "true" : "false");
  addText(e, "locked", "false");
}

void addJoint(XMLElement* objects, const OsimJoint& j) {
  XMLElement* e = addNamed(objects, j.type.c_str(), j.name);
  const std::string parentFrame = j.parentBody + "_offset", childFrame = j.childBody + "_offset";
  addText(e, "socket_parent_frame", parentFrame);
  addText(e, "socket_child_frame", childFrame);
  if (!j.coordinates.empty()) {
    XMLElement* coordinates = e->InsertNewChildElement("coordinates");
    for (const auto& c : j.coordinates) addCoordinate(coordinates, c);
  }
  XMLElement* frames = e->InsertNewChildElement("frames");
  addOffsetFrame(frames, parentFrame, j.parentBody, j.parentFrame);
  addOffsetFrame(frames, childFrame, j.childBody, j.childFrame);
}

// The leg's bodies on `side`: pelvis, femur, tibia, talus (the whole foot), calcn and toes
// (massless); the pelvis carries the body mass the leg does not.
std::vector<OsimBody> makeLegBodies(const LegGeometry& g, const OsimLegPlacement& place, const std::string& s) {
  const double legMass = g.thighMass + g.shankMass + g.footMass;
  return {makeBody("pelvis", std::max(0.0, place.bodyMass - legMass), Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero()),
          makeBody("femur_" + s, g.thighMass, {0, -g.thighCom, 0}, makeRodInertia(g.thighInertia, 1)),
          makeBody("tibia_" + s, g.shankMass, {0, -g.shankCom, 0}, makeRodInertia(g.shankInertia, 1)),
          makeBody("talus_" + s, g.footMass, {g.footComForward, 0, 0}, makeRodInertia(g.footInertia, 0)),
          makeBody("calcn_" + s, 0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero()),
          makeBody("toes_" + s, 0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero())};
}

// hip_flexion_<side> and knee_angle_<side>, signed as OpenSim's gait models: both turn about
// the joint's +z (x forward, y up, z to the subject's right, on either side), so hip flexion
// is positive and knee flexion negative (Gait2354_Simbody/gait2354_simbody.osim: knee_angle_r
// range -120..10 deg, axis 0 0 1; the same axis for hip_flexion_l and knee_angle_l).
void addLegCoordinates(OsimJoint& hip, OsimJoint& knee, const OsimLegPlacement& place) {
  const std::string hipName = makeOsimHipCoordinate(place.side), kneeName = makeOsimKneeCoordinate(place.side);
  hip.coordinates.push_back(
      makeCoordinate(hipName, place.initial.hipFlexion, place.hipRange.minFlexion, place.hipRange.maxFlexion,
                     hipName +
                         ", rad: + = flexion (the thigh swings forward), counter-clockwise about +z with the subject "
                         "facing +x, as OpenSim's gait models. Range [" +
                         formatDegrees(place.hipRange.minFlexion) + ", " + formatDegrees(place.hipRange.maxFlexion) +
                         "] deg: swingsim's hip range of motion, where a smooth stop acts (not clamped)."));
  knee.coordinates.push_back(makeCoordinate(
      kneeName, -place.initial.kneeFlexion, -place.kneeMaxFlexion, -place.kneeMinFlexion,
      kneeName +
          ", rad: - = FLEXION (the shank swings backwards), as OpenSim's gait models (Gait2354, Gait10dof18musc); "
          "swingsim's knee flexion is minus this. Range [" +
          formatDegrees(-place.kneeMaxFlexion) + ", " + formatDegrees(-place.kneeMinFlexion) +
          "] deg: the knee model's hyperextension stop at the high end (a simulated swing presses a few degrees past "
          "it, so not clamped)."));
}

// The pelvis on the ground: welded with the hip at (0, hipHeight), or, for a measured pelvis,
// on a PlanarJoint with Gait10dof18musc's pelvis coordinates and ranges (tilt +-90 deg, tx
// -5..5 m, ty -1..2 m; Models/Gait10dof18musc/gait10dof18musc.osim), from its toe-off pose.
OsimJoint makeGroundPelvis(const OsimLegPlacement& place, const std::array<double, 2>& hipInPelvis) {
  const Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
  if (!place.measuredPelvis)
    return makeJoint("ground_pelvis", "WeldJoint", "ground",
                     makeTranslation(-hipInPelvis[0], place.hipHeight - hipInPelvis[1]), "pelvis", origin);
  const OsimPelvisPose& at = *place.measuredPelvis;
  OsimJoint j = makeJoint("ground_pelvis", "PlanarJoint", "ground", origin, "pelvis", origin);
  j.coordinates.push_back(makeCoordinate("pelvis_tilt", at.tilt, -kPi / 2, kPi / 2,
                                         "pelvis_tilt, rad: + = the pelvis tilted forward (about +z), as the gait "
                                         "models; the measured drive's at toe-off"));
  j.coordinates.push_back(
      makeCoordinate("pelvis_tx", at.x, -5, 5, "pelvis_tx, m: forward; the measured drive's at toe-off"));
  j.coordinates.push_back(
      makeCoordinate("pelvis_ty", at.y, -1, 2, "pelvis_ty, m: up; the measured drive's at toe-off"));
  return j;
}

// An added shank mass (simulate --add-mass) as a point mass on its own body, welded to the
// tibia on the shank's axis at its distance below the knee.
void addAddedMass(OsimModel& m, const LegGeometry& g, const std::string& s) {
  const std::string name = "added_mass_" + s;
  m.bodies.push_back(makeBody(name, g.added.mass, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero()));
  m.joints.push_back(makeJoint(name + "_weld", "WeldJoint", "tibia_" + s,
                               makeTranslation(0, -g.added.distanceBelowKnee), name, Eigen::Isometry3d::Identity()));
}

}  // namespace

OsimModel makeOsimLegModel(const LegGeometry& g, const OsimLegPlacement& place) {
  if (place.side != 'r' && place.side != 'l')
    throw std::invalid_argument(std::string("makeOsimLegModel: side: expected r or l (got ") + place.side + ")");
  if (!(g.added.mass >= 0) ||
      (g.added.mass > 0 && !(g.added.distanceBelowKnee >= 0 && g.added.distanceBelowKnee <= g.shankLength)))
    throw std::invalid_argument("makeOsimLegModel: added mass: expected a mass >= 0 kg on the shank, 0 to " +
                                formatNumber(g.shankLength) + " m below the knee (got " + formatNumber(g.added.mass) +
                                " kg at " + formatNumber(g.added.distanceBelowKnee) + " m)");
  const std::string s(1, place.side);
  OsimModel m;
  m.name = place.modelName;
  m.bodies = makeLegBodies(g, place, s);
  const std::array<double, 2> hipInPelvis = place.hipOffsetInPelvis.value_or(std::array<double, 2>{0, 0});
  const Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
  OsimJoint ground = makeGroundPelvis(place, hipInPelvis);
  OsimJoint hip = makeJoint("hip_" + s, "PinJoint", "pelvis", makeTranslation(hipInPelvis[0], hipInPelvis[1]),
                            "femur_" + s, origin);
  OsimJoint knee =
      makeJoint("knee_" + s, "PinJoint", "femur_" + s, makeTranslation(0, -g.thighLength), "tibia_" + s, origin);
  addLegCoordinates(hip, knee, place);
  OsimJoint ankle =
      makeJoint("ankle_" + s, "WeldJoint", "tibia_" + s, makeTranslation(0, -g.shankLength), "talus_" + s, origin);
  OsimJoint subtalar = makeJoint("subtalar_" + s, "WeldJoint", "talus_" + s, origin, "calcn_" + s, origin);
  OsimJoint mtp =
      makeJoint("mtp_" + s, "WeldJoint", "calcn_" + s, makeTranslation(g.footLength, 0), "toes_" + s, origin);
  m.joints = {ground, hip, knee, ankle, subtalar, mtp};
  if (g.added.mass > 0) addAddedMass(m, g, s);
  addOsimLegShapes(m, g, place.side);
  return m;
}

std::string formatOsimModel(const OsimModel& model, const std::string& header) {
  XMLDocument doc;
  doc.InsertEndChild(doc.NewDeclaration(R"(xml version="1.0" encoding="UTF-8")"));
  XMLElement* root = doc.NewElement("OpenSimDocument");
  root->SetAttribute("Version", 40000);
  doc.InsertEndChild(root);
  root->InsertNewComment(makeCommentText(header).c_str());
  XMLElement* m = addNamed(root, "Model", model.name);
  addNamed(m, "Ground", "ground");
  addText(m, "gravity", formatVector({0, -kGravity, 0}));
  addText(m, "length_units", "meters");
  addText(m, "force_units", "N");
  XMLElement* bodies = addNamed(m, "BodySet", "bodyset")->InsertNewChildElement("objects");
  for (const auto& b : model.bodies) addBody(bodies, b);
  XMLElement* joints = addNamed(m, "JointSet", "jointset")->InsertNewChildElement("objects");
  for (const auto& j : model.joints) addJoint(joints, j);
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return printer.CStr();
}

}  // namespace swingsim
