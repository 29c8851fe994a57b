#include "io/osim_model.h"

#include <tinyxml2.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "core/input_error.h"
#include "core/output_files.h"
#include "io/osim_model_checks.h"
#include "model/prosthesis_parts.h"

namespace swingsim {

namespace {

using tinyxml2::XMLElement;

// `file:line: what` for an element.
[[noreturn]] void failAt(const std::string& path, const XMLElement* e, const std::string& what) {
  throw InputError(path + ":" + std::to_string(e ? e->GetLineNum() : 0) + ": " + what);
}

std::string describe(const XMLElement* e) {
  const char* name = e->Attribute("name");
  return std::string("<") + e->Name() + (name ? std::string(" name=\"") + name + "\"" : "") + ">";
}

const XMLElement* requireChild(const std::string& path, const XMLElement* parent, const char* child) {
  const XMLElement* c = parent->FirstChildElement(child);
  if (!c) failAt(path, parent, describe(parent) + ": expected a <" + child + "> element (got none)");
  return c;
}

std::string textOf(const XMLElement* e) { return e->GetText() ? e->GetText() : ""; }

// The `count` whitespace-separated numbers of element `child` of `parent`.
std::vector<double> readNumbers(const std::string& path, const XMLElement* parent, const char* child,
                                std::size_t count) {
  const XMLElement* c = requireChild(path, parent, child);
  std::istringstream in(textOf(c));
  std::vector<double> v;
  std::string word;
  while (in >> word) {
    char* end = nullptr;
    const double x = std::strtod(word.c_str(), &end);
    if (*end != '\0' || !std::isfinite(x))
      v.push_back(NAN);
    else
      v.push_back(x);
  }
  bool ok = count == 0 ? !v.empty() : v.size() == count;
  for (double x : v) ok = ok && std::isfinite(x);
  if (!ok)
    failAt(path, c,
           describe(parent) + ": <" + child + ">: expected " + (count ? std::to_string(count) : "some") +
               " finite numbers (got \"" + textOf(c) + "\")");
  return v;
}

Eigen::Vector3d vec3(const std::vector<double>& v) { return {v[0], v[1], v[2]}; }

Eigen::Isometry3d makePose(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation) {
  Eigen::Isometry3d x = Eigen::Isometry3d::Identity();
  x.linear() = rotation;
  x.translation() = translation;
  return x;
}

// OpenSim's orientation property: body-fixed x-y-z rotations, rad.
Eigen::Matrix3d bodyFixedXyz(const Eigen::Vector3d& a) {
  using Eigen::AngleAxisd;
  return (AngleAxisd(a.x(), Eigen::Vector3d::UnitX()) * AngleAxisd(a.y(), Eigen::Vector3d::UnitY()) *
          AngleAxisd(a.z(), Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

// "/bodyset/femur_r", "../femur_r", "femur_r" -> "femur_r"; "/ground" -> "ground".
std::string lastPathPart(const std::string& p) {
  const auto slash = p.find_last_of('/');
  return slash == std::string::npos ? p : p.substr(slash + 1);
}

OsimBody readBody(const std::string& path, const XMLElement* e) {
  OsimBody b;
  b.name = e->Attribute("name") ? e->Attribute("name") : "";
  b.line = e->GetLineNum();
  b.mass = readNumbers(path, e, "mass", 1)[0];
  if (b.mass < 0)
    failAt(path, e->FirstChildElement("mass"),
           describe(e) + ": <mass>: expected a mass >= 0 kg (got " + formatNumber(b.mass) + ")");
  b.massCenter = vec3(readNumbers(path, e, "mass_center", 3));
  const auto i = readNumbers(path, e, "inertia", 6);  // [Ixx Iyy Izz Ixy Ixz Iyz] about the COM
  b.inertia << i[0], i[3], i[4], i[3], i[1], i[5], i[4], i[5], i[2];
  checkOsimBodyUnits(path, b);
  return b;
}

// The value at coordinate 0 of a TransformAxis function (OpenSim's Function classes).
double calcFunctionAtZero(const std::string& path, const XMLElement* f) {
  const std::string type = f->Name();
  if (type == "function") {  // a wrapper property: the function is its child
    const XMLElement* inner = f->FirstChildElement();
    if (!inner) failAt(path, f, "<function>: expected a function element inside (got none)");
    return calcFunctionAtZero(path, inner);
  }
  if (type == "Constant") return readNumbers(path, f, "value", 1)[0];
  if (type == "LinearFunction") return readNumbers(path, f, "coefficients", 2)[1];          // slope, intercept
  if (type == "PolynomialFunction") return readNumbers(path, f, "coefficients", 0).back();  // highest order first
  if (type == "MultiplierFunction")
    return readNumbers(path, f, "scale", 1)[0] * calcFunctionAtZero(path, requireChild(path, f, "function"));
  if (type == "SimmSpline" || type == "NaturalCubicSpline") {
    const auto xs = readNumbers(path, f, "x", 0), ys = readNumbers(path, f, "y", 0);
    if (xs.size() != ys.size() || xs.size() < 2)
      failAt(path, f,
             describe(f) + ": expected as many <y> as <x> values, at least 2 (got " + std::to_string(xs.size()) +
                 " and " + std::to_string(ys.size()) + ")");
    for (std::size_t i = 1; i < xs.size(); ++i)
      if (!(xs[i] > xs[i - 1]))
        failAt(path, f,
               describe(f) + ": <x>: expected increasing values (got " + formatNumber(xs[i]) + " after " +
                   formatNumber(xs[i - 1]) + ")");
    return calcOsimSplineValue(xs, ys, 0.0, type == "NaturalCubicSpline");
  }
  failAt(path, f,
         "TransformAxis function: expected Constant, LinearFunction, PolynomialFunction, MultiplierFunction, "
         "SimmSpline or NaturalCubicSpline (got " +
             describe(f) + ")");
}

// A CustomJoint's SpatialTransform at every coordinate 0: rotations about rotation1..3 in
// turn, then the translation along translation1..3, expressed in the parent frame F.
void readSpatialTransform(const std::string& path, const XMLElement* st, OsimJoint& j) {
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  for (const XMLElement* ax = st->FirstChildElement("TransformAxis"); ax;
       ax = ax->NextSiblingElement("TransformAxis")) {
    const std::string axisName = ax->Attribute("name") ? ax->Attribute("name") : "";
    Eigen::Vector3d axis = vec3(readNumbers(path, ax, "axis", 3));
    if (!(axis.norm() > 0)) failAt(path, ax, describe(ax) + ": <axis>: expected a non-zero axis (got 0 0 0)");
    axis.normalize();
    const XMLElement* f = nullptr;
    for (const XMLElement* c = ax->FirstChildElement(); c; c = c->NextSiblingElement())
      if (std::string(c->Name()) != "coordinates" && std::string(c->Name()) != "axis") f = c;
    const double value = f ? calcFunctionAtZero(path, f) : 0.0;
    const bool dependent = ax->FirstChildElement("coordinates") &&
                           !textOf(ax->FirstChildElement("coordinates")).empty() &&
                           textOf(ax->FirstChildElement("coordinates")).find_first_not_of(" \t\n") != std::string::npos;
    if (axisName.rfind("rotation", 0) == 0) {
      r = r * Eigen::AngleAxisd(value, axis).toRotationMatrix();
    } else {
      t += value * axis;
      j.centreMoves = j.centreMoves || (dependent && f && std::string(f->Name()) != "Constant");
    }
  }
  j.motionAtZero = makePose(r, t);
}

// A <Coordinate>: name, and <default_value>, <range>, <clamped> when given.
OsimCoordinate readCoordinate(const std::string& path, const XMLElement* e) {
  OsimCoordinate c;
  c.name = e->Attribute("name") ? e->Attribute("name") : "";
  if (e->FirstChildElement("default_value")) c.defaultValue = readNumbers(path, e, "default_value", 1)[0];
  if (e->FirstChildElement("range")) {
    const auto range = readNumbers(path, e, "range", 2);
    c.rangeMin = range[0];
    c.rangeMax = range[1];
  }
  if (const XMLElement* clamped = e->FirstChildElement("clamped"))
    c.clamped = textOf(clamped).find("true") != std::string::npos;
  return c;
}

OsimJoint readJoint(const std::string& path, const XMLElement* e) {
  OsimJoint j;
  j.name = e->Attribute("name") ? e->Attribute("name") : "";
  j.type = e->Name();
  j.line = e->GetLineNum();
  j.motionAtZero = Eigen::Isometry3d::Identity();
  // A socket names one of the joint's own offset frames, or a body by its path.
  auto resolve = [&](const char* socket, std::string& body, Eigen::Isometry3d& frame) {
    const std::string target = textOf(requireChild(path, e, socket));
    frame = Eigen::Isometry3d::Identity();
    body = lastPathPart(target);
    if (const XMLElement* frames = e->FirstChildElement("frames"))
      for (const XMLElement* f = frames->FirstChildElement(); f; f = f->NextSiblingElement()) {
        if (!f->Attribute("name") || target != f->Attribute("name")) continue;
        body = lastPathPart(textOf(requireChild(path, f, "socket_parent")));
        frame = makePose(bodyFixedXyz(vec3(readNumbers(path, f, "orientation", 3))),
                         vec3(readNumbers(path, f, "translation", 3)));
      }
  };
  if (const XMLElement* coordinates = e->FirstChildElement("coordinates"))
    for (const XMLElement* c = coordinates->FirstChildElement("Coordinate"); c; c = c->NextSiblingElement("Coordinate"))
      j.coordinates.push_back(readCoordinate(path, c));
  resolve("socket_parent_frame", j.parentBody, j.parentFrame);
  resolve("socket_child_frame", j.childBody, j.childFrame);
  if (const XMLElement* st = e->FirstChildElement("SpatialTransform")) readSpatialTransform(path, st, j);
  return j;
}

const XMLElement* requireObjects(const std::string& path, const XMLElement* model, const char* set) {
  return requireChild(path, requireChild(path, model, set), "objects");
}

}  // namespace

double calcOsimSplineValue(const std::vector<double>& x, const std::vector<double>& y, double at, bool natural) {
  const std::size_t n = x.size();
  if (n == 2) return y[0] + (y[1] - y[0]) * (at - x[0]) / (x[1] - x[0]);
  // b: first derivative, c: second derivative / 2, d: third derivative / 6 on each interval.
  std::vector<double> h(n - 1), b(n), c(n), d(n);
  for (std::size_t i = 0; i + 1 < n; ++i) h[i] = x[i + 1] - x[i];
  // The tridiagonal system for sigma = second derivative / 6 (FMM SPLINE's c before scaling).
  std::vector<double> diag(n), rhs(n), off(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) off[i] = h[i];
  for (std::size_t i = 1; i + 1 < n; ++i) {
    diag[i] = 2 * (h[i - 1] + h[i]);
    rhs[i] = (y[i + 1] - y[i]) / h[i] - (y[i] - y[i - 1]) / h[i - 1];
  }
  if (natural) {
    diag[0] = diag[n - 1] = 1;
    off[0] = 0;  // sigma_0 = 0 (the row's coupling to sigma_1 removed)
    rhs[0] = rhs[n - 1] = 0;
  } else if (n == 3) {  // FMM: zero end third derivatives, the parabola through the 3 points
    diag[0] = -h[0];
    diag[n - 1] = -h[n - 2];
    rhs[0] = rhs[n - 1] = 0;
  } else {
    // FMM end conditions: the third derivative at each end matches the cubic through the 4 end points.
    diag[0] = -h[0];
    diag[n - 1] = -h[n - 2];
    const auto dd = [&](std::size_t i) { return (y[i + 1] - y[i]) / h[i]; };
    const double c2 = dd(1) - dd(0), c3 = dd(2) - dd(1);
    const double cm2 = dd(n - 2) - dd(n - 3), cm3 = dd(n - 3) - dd(n - 4);
    rhs[0] = (c3 / (x[3] - x[1]) - c2 / (x[2] - x[0])) * h[0] * h[0] / (x[3] - x[0]);
    rhs[n - 1] =
        -(cm2 / (x[n - 1] - x[n - 3]) - cm3 / (x[n - 2] - x[n - 4])) * h[n - 2] * h[n - 2] / (x[n - 1] - x[n - 4]);
  }
  // Forward elimination and back substitution; the lower coupling of row i is h[i-1], except
  // the natural last row (sigma_{n-1} = 0), which has none.
  for (std::size_t i = 1; i < n; ++i) {
    const double lower = (natural && i == n - 1) ? 0 : h[i - 1];
    const double t = lower / diag[i - 1];
    diag[i] -= t * off[i - 1];
    rhs[i] -= t * rhs[i - 1];
  }
  std::vector<double> sigma(n);
  sigma[n - 1] = rhs[n - 1] / diag[n - 1];
  for (std::size_t i = n - 1; i-- > 0;) sigma[i] = (rhs[i] - off[i] * sigma[i + 1]) / diag[i];
  // Evaluate on the interval holding `at` (the end intervals extend the cubic beyond the knots).
  std::size_t i = 0;
  while (i + 2 < n && at >= x[i + 1]) ++i;
  const double bi = (y[i + 1] - y[i]) / h[i] - h[i] * (sigma[i + 1] + 2 * sigma[i]);
  const double di = (sigma[i + 1] - sigma[i]) / h[i];
  const double dx = at - x[i];
  return y[i] + dx * (bi + dx * (3 * sigma[i] + dx * di));
}

OsimModel parseOsimModel(const std::string& text, const std::string& path) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS)
    throw InputError(path + ":" + std::to_string(doc.ErrorLineNum()) +
                     ": expected an OpenSim model (.osim XML) (got text that is not XML: " + doc.ErrorName() + ")");
  const XMLElement* root = doc.RootElement();
  if (!root || std::string(root->Name()) != "OpenSimDocument")
    failAt(path, root,
           std::string("expected an <OpenSimDocument> root element (got <") + (root ? root->Name() : "") + ">)");
  const int version = root->IntAttribute("Version", 0);
  if (version < 40000)
    failAt(path, root,
           "<OpenSimDocument Version>: expected an OpenSim 4 model, Version 40000 or later (got " +
               std::to_string(version) + "; open and save it in OpenSim 4 to convert it)");
  const XMLElement* model = requireChild(path, root, "Model");
  OsimModel m;
  m.path = path;
  m.name = model->Attribute("name") ? model->Attribute("name") : fileStem(path);
  m.bodySetLine = requireChild(path, model, "BodySet")->GetLineNum();
  m.jointSetLine = requireChild(path, model, "JointSet")->GetLineNum();
  for (const XMLElement* b = requireObjects(path, model, "BodySet")->FirstChildElement("Body"); b;
       b = b->NextSiblingElement("Body"))
    m.bodies.push_back(readBody(path, b));
  for (const XMLElement* j = requireObjects(path, model, "JointSet")->FirstChildElement(); j;
       j = j->NextSiblingElement())
    m.joints.push_back(readJoint(path, j));
  checkOsimModelNames(m);
  return m;
}

OsimModel loadOsimModel(const std::string& path) { return parseOsimModel(readFile(path), path); }

std::string makeOsimHipCoordinate(char side) { return std::string("hip_flexion_") + side; }
std::string makeOsimKneeCoordinate(char side) { return std::string("knee_angle_") + side; }

const OsimBody& OsimModel::getBody(const std::string& bodyName) const {
  for (const auto& b : bodies)
    if (b.name == bodyName) return b;
  std::string names;
  for (const auto& b : bodies) names += (names.empty() ? "" : ", ") + b.name;
  throw InputError(path + ":" + std::to_string(bodySetLine) + ": <Body name=\"" + bodyName +
                   "\">: expected a body of that name in the BodySet (got " + names + ")");
}

const OsimJoint& OsimModel::getJointTo(const std::string& child) const {
  for (const auto& j : joints)
    if (j.childBody == child) return j;
  throw InputError(path + ":" + std::to_string(jointSetLine) +
                   ": <JointSet>: expected a joint whose child frame is on body " + child +
                   " (got none); a link of the leg's chain is missing");
}

double OsimModel::calcTotalMass() const {
  double sum = 0;
  for (const auto& b : bodies) sum += b.mass;
  return sum;
}

// ---- The participant from one leg ---------------------------------------------------------

namespace {

// Winter 2009 (Biomechanics and Motor Control of Human Movement, 4th ed.) Fig. 4.1: hip
// (greater trochanter) at 0.530 H, ankle at 0.039 H above the floor, so hip to ankle is 0.491 H.
constexpr double kHipToAnkleOfHeight = 0.530 - 0.039;

Eigen::Vector2d xy(const Eigen::Vector3d& v) { return {v.x(), v.y()}; }

const OsimBody& requireLegBody(const OsimModel& m, const std::string& name) {
  const OsimBody& b = m.getBody(name);
  if (!(b.mass > 0))
    throw InputError(m.path + ":" + std::to_string(b.line) + ": <Body name=\"" + name +
                     "\">: <mass>: expected a positive mass in kg for a leg segment (got " + formatNumber(b.mass) +
                     ")");
  return b;
}

const OsimJoint& requireJoint(const OsimModel& m, const std::string& parent, const std::string& child) {
  const OsimJoint& j = m.getJointTo(child);
  if (j.parentBody != parent)
    throw InputError(m.path + ":" + std::to_string(j.line) + ": <" + j.type + " name=\"" + j.name +
                     "\">: expected a joint from " + parent + " to " + child + " (got one from " + j.parentBody +
                     ": the chain pelvis, femur, tibia, talus, calcn, toes " +
                     (j.parentBody == "ground" ? "has a link missing" : "has a link missing or an extra body in it") +
                     ")");
  return j;
}

// A segment from its proximal and distal joint centres and its COM, all in one frame (x-y):
// length between the centres, the COM's distance from the distal centre along the segment.
SegmentParams makeSegment(const Eigen::Vector2d& proximal, const Eigen::Vector2d& distal, const Eigen::Vector2d& com,
                          double mass, double izz) {
  SegmentParams s;
  s.length = (proximal - distal).norm();
  s.mass = mass;
  s.comFromDistal = s.length > 0 ? (com - distal).dot((proximal - distal) / s.length) : 0;
  s.inertia = izz;
  return s;
}

std::string fmt(const Eigen::Vector2d& v) { return "(" + formatNumber(v.x()) + ", " + formatNumber(v.y()) + ")"; }

// Rigidly joined bodies, each placed by its pose in a common frame.
struct RigidPart {
  const OsimBody* body;
  Eigen::Isometry3d pose;
};
struct PlanarMass {
  double mass = 0;
  Eigen::Vector2d com = Eigen::Vector2d::Zero();  ///< x-y of the common frame
  double izz = 0;                                 ///< about the combined COM
};

// Masses summed, COM the mass-weighted mean, Izz each part's (turned into the common frame)
// plus m d^2 in the x-y plane (parallel-axis theorem).
PlanarMass calcCombinedPlanarMass(const std::vector<RigidPart>& parts) {
  PlanarMass c;
  for (const auto& part : parts) {
    c.mass += part.body->mass;
    c.com += part.body->mass * xy(part.pose * part.body->massCenter);
  }
  c.com /= c.mass;
  for (const auto& part : parts) {
    const Eigen::Matrix3d r = part.pose.linear();
    c.izz += (r * part.body->inertia * r.transpose())(2, 2) +
             part.body->mass * (xy(part.pose * part.body->massCenter) - c.com).squaredNorm();
  }
  return c;
}

// Scales a segment's mass, keeping its COM and radius of gyration (inertia in proportion).
void replaceMass(SegmentParams& s, double mass) {
  s.inertia *= mass / s.mass;
  s.mass = mass;
}

/// The leg's bodies and joints on one side, found by OpenSim's gait-model names.
struct LegParts {
  std::string side, femurName, tibiaName, talusName, calcnName, toesName;
  const OsimBody *femur, *tibia, *talus, *calcn, *toes;
  const OsimJoint *hip, *knee, *ankle, *subtalar, *mtp;
};

/// Finds the leg's bodies and joints; throws InputError for one missing or a massless foot.
LegParts findLegParts(const OsimModel& m, char sideLetter) {
  LegParts leg;
  leg.side = std::string(1, sideLetter);
  leg.femurName = "femur_" + leg.side;
  leg.tibiaName = "tibia_" + leg.side;
  leg.talusName = "talus_" + leg.side;
  leg.calcnName = "calcn_" + leg.side;
  leg.toesName = "toes_" + leg.side;
  leg.femur = &requireLegBody(m, leg.femurName);
  leg.tibia = &requireLegBody(m, leg.tibiaName);
  // The foot's parts may each be massless (export-osim's calcn and toes are) but not all three.
  leg.talus = &m.getBody(leg.talusName);
  leg.calcn = &m.getBody(leg.calcnName);
  leg.toes = &m.getBody(leg.toesName);
  if (!(leg.talus->mass + leg.calcn->mass + leg.toes->mass > 0))
    throw InputError(m.path + ":" + std::to_string(leg.talus->line) + ": <Body name=\"" + leg.talusName +
                     "\">: <mass>: expected a positive mass in kg for the foot, " + leg.talusName + " + " +
                     leg.calcnName + " + " + leg.toesName + " (got 0)");
  leg.hip = &requireJoint(m, "pelvis", leg.femurName);
  leg.knee = &requireJoint(m, leg.femurName, leg.tibiaName);
  leg.ankle = &requireJoint(m, leg.tibiaName, leg.talusName);
  leg.subtalar = &requireJoint(m, leg.talusName, leg.calcnName);
  leg.mtp = &requireJoint(m, leg.calcnName, leg.toesName);
  return leg;
}

/// Thigh, in the femur frame: hip centre (hip's child frame) to knee centre.
void importThigh(const LegParts& leg, Participant& p, std::ostream& why) {
  const OsimJoint &hip = *leg.hip, &knee = *leg.knee;
  const Eigen::Vector2d hipInFemur = xy(hip.childFrame.translation()), kneeInFemur = xy(knee.calcCentreInParent());
  p.thigh = makeSegment(hipInFemur, kneeInFemur, xy(leg.femur->massCenter), leg.femur->mass, leg.femur->inertia(2, 2));
  why << "thigh: " << leg.femurName << " <mass>, <mass_center>, <inertia> Izz; length hip centre " << fmt(hipInFemur)
      << " (" << hip.name << " child frame) to knee centre " << fmt(kneeInFemur) << " (" << knee.name
      << " parent frame";
  if (knee.centreMoves) why << " and its SpatialTransform translation";
  why << "), m in " << leg.femurName << "\n";
  if (knee.centreMoves)
    why << "  " << knee.name << " is a " << knee.type
        << " whose centre moves with the knee angle (spline): taken at full extension, knee angle 0\n";
}

/// Shank, in the tibia frame: knee centre (knee's child frame) to ankle centre. Bodies welded
/// to the tibia other than the foot (an added mass, as export-osim writes one) move with it:
/// they are part of the shank's mass, COM and Izz.
void importShank(const OsimModel& m, const LegParts& leg, Participant& p, std::ostream& why) {
  const Eigen::Vector2d kneeInTibia = xy(leg.knee->childFrame.translation()),
                        ankleInTibia = xy(leg.ankle->calcCentreInParent());
  std::vector<RigidPart> parts = {{leg.tibia, Eigen::Isometry3d::Identity()}};
  std::string welded;
  for (const auto& j : m.joints)
    if (j.type == "WeldJoint" && j.parentBody == leg.tibiaName && j.childBody != leg.talusName && &j != leg.ankle) {
      parts.push_back({&m.getBody(j.childBody), j.calcChildInParent()});
      welded += " + " + j.childBody + " (" + j.name + ")";
    }
  const PlanarMass shank = calcCombinedPlanarMass(parts);
  p.shank = makeSegment(kneeInTibia, ankleInTibia, shank.com, shank.mass, shank.izz);
  why << "shank: " << leg.tibiaName << welded << " <mass>, <mass_center>, <inertia> Izz"
      << (welded.empty() ? "" : " combined (welded to it)") << "; length knee centre " << fmt(kneeInTibia) << " ("
      << leg.knee->name << " child frame) to ankle centre " << fmt(ankleInTibia) << " (" << leg.ankle->name
      << " parent frame), m in " << leg.tibiaName << "\n";
}

/// Foot: talus, calcn and toes as one rigid body, in the tibia frame at the reference pose.
void importFoot(const LegParts& leg, const OsimImportOptions& o, Participant& p, std::ostream& why) {
  const Eigen::Vector2d kneeInTibia = xy(leg.knee->childFrame.translation()),
                        ankleInTibia = xy(leg.ankle->calcCentreInParent());
  const Eigen::Isometry3d talusPose = leg.ankle->calcChildInParent();
  const Eigen::Isometry3d calcnPose = talusPose * leg.subtalar->calcChildInParent();
  const Eigen::Isometry3d toesPose = calcnPose * leg.mtp->calcChildInParent();
  const PlanarMass foot =
      calcCombinedPlanarMass({{leg.talus, talusPose}, {leg.calcn, calcnPose}, {leg.toes, toesPose}});
  const double footMass = foot.mass;
  const Eigen::Vector2d footCom = foot.com;
  const double footIzz = foot.izz;
  // The foot link is perpendicular to the shank, pointing forward.
  const Eigen::Vector2d up = (kneeInTibia - ankleInTibia).normalized(), forward(up.y(), -up.x());
  const Eigen::Vector2d mtpCentre = xy(calcnPose * leg.mtp->calcCentreInParent());
  const Eigen::Vector2d toesCom = xy(toesPose * leg.toes->massCenter);
  // The toe tip: the toes taken as a uniform link from the MTP joint, COM at its middle.
  const double modelFootLength = (mtpCentre + 2 * (toesCom - mtpCentre) - ankleInTibia).dot(forward);
  p.foot.length = o.footLength.value_or(modelFootLength);
  p.foot.mass = footMass;
  p.foot.comFromDistal = (footCom - ankleInTibia).dot(forward);
  p.foot.inertia = footIzz;
  p.footComFrom = FootComFrom::kAnkle;
  why << "foot: " << leg.talusName << " + " << leg.calcnName << " + " << leg.toesName << " (" << leg.subtalar->name
      << ", " << leg.mtp->name << " at 0): masses summed, combined COM " << fmt(footCom) << " m in " << leg.tibiaName
      << ", Izz about it by parallel axes; "
      << "com_from_distal_m measured forward from the ankle\n";
  why << "  foot length: "
      << (o.footLength ? "--foot-length-m"
                       : "ankle to the toe tip, taken as the MTP centre " + fmt(mtpCentre) +
                             " plus twice the toes' COM offset from it (toes as a uniform link)")
      << "\n";
}

/// The prosthesis's masses given on the command line replace the model's shank and foot:
/// as masses, or as catalogue parts (the participant then names them, and its loader makes
/// the segments from them).
void replaceProsthesisMasses(const OsimImportOptions& o, Participant& p, std::ostream& why) {
  if (o.parts) {
    const ProsthesisPartsChoice& c = *o.parts;
    if ((c.makesShank() && o.shankMass) || (c.makesFoot() && o.footMass))
      throw InputError("import-osim: a segment's mass given both as a mass and as catalogue parts; give one");
    p.parts = c;
    std::string named;
    for (PartCategory category : kPartCategories)
      if (!partId(c, category).empty())
        named += std::string(named.empty() ? "" : ", ") + partCategoryKey(category) + " " + partId(c, category);
    why << "prosthesis_parts: " << named << " (their catalogue's masses, COMs and inertias make the "
        << (c.makesShank() ? (c.makesFoot() ? "shank and foot" : "shank") : "foot")
        << " in place of the model's masses above; the model gives only the lengths)\n";
  }
  if (o.shankMass) {
    replaceMass(p.shank, *o.shankMass);
    why << "shank mass: --shank-mass-kg (the prosthesis); COM kept, inertia scaled with the mass\n";
  }
  if (o.footMass) {
    replaceMass(p.foot, *o.footMass);
    why << "foot mass: --foot-mass-kg (the prosthesis); COM kept, inertia scaled with the mass\n";
  }
}

/// The hip's place in the pelvis, the body mass and the height.
void importWholeBody(const OsimModel& m, const LegParts& leg, const OsimImportOptions& o, Participant& p,
                     std::ostream& why) {
  const Eigen::Vector3d hipInPelvis = leg.hip->calcCentreInParent();
  p.hipOffsetInPelvis = std::array<double, 2>{hipInPelvis.x(), hipInPelvis.y()};
  why << "hip_offset_in_pelvis_m: " << leg.hip->name << " centre in " << leg.hip->parentBody
      << " (its parent frame's <translation>)\n";
  p.bodyMass = m.calcTotalMass();
  why << "body_mass_kg: the sum of every body's <mass> (" << m.bodies.size() << " bodies)\n";
  p.height = o.height.value_or((p.thigh.length + p.shank.length) / kHipToAnkleOfHeight);
  why << "height_m: "
      << (o.height ? "--height-m" : "(thigh + shank) / 0.491 (hip 0.530 H, ankle 0.039 H: Winter 2009 Fig. 4.1)")
      << "\n";
}

}  // namespace

OsimParticipant calcOsimParticipant(const OsimModel& m, const OsimImportOptions& o) {
  const LegParts leg = findLegParts(m, o.side);
  const std::string& side = leg.side;
  std::ostringstream why;
  const std::string file = std::filesystem::path(m.path).filename().string();
  why << "Imported by `swingsim import-osim` from " << file << " (model " << m.name << "), side " << side
      << ", at the model's reference pose (every coordinate 0), in the sagittal x-y plane (x forward, y up), inertias "
         "about z.\n";
  OsimParticipant out;
  Participant& p = out.participant;
  importThigh(leg, p, why);
  importShank(m, leg, p, why);
  importFoot(leg, o, p, why);
  replaceProsthesisMasses(o, p, why);
  importWholeBody(m, leg, o, p, why);
  checkOsimLeg(m,
               {leg.femur, leg.tibia, leg.talus, leg.hip, leg.knee, leg.ankle, leg.mtp, o.footLength.has_value(),
                o.height.has_value()},
               p);
  p.name = o.name.empty() ? m.name + "_" + side : o.name;
  p.source = "OpenSim model " + file + ", " + side + " leg (swingsim import-osim)";
  p.kneeModelPath = o.kneeModelPath;
  p.kneeFriction = o.kneeFriction;
  why << "DEFAULTS (not from the model): knee_model and knee_friction_Nm as given to import-osim (--knee, "
         "--knee-friction-Nm);\n"
      << "  the hip drive (biphasic hip moment), initial state, hip range and swing-end rule are the project's "
         "defaults;\n"
      << "  toe clearance for walking.";
  out.provenance = why.str();
  return out;
}

}  // namespace swingsim
