// The exported model as OpenSim's gait models name and sign it, on either side: coordinate
// names, the knee negative in flexion (checked by turning the written frames by hand against
// swingsim's own planar kinematics), ranges and defaults from the participant, the shapes
// OpenSim draws (well-formed XML, no meshes), the added mass as a welded body (masses and
// COM by hand), and the round trip through import-osim for both sides.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "core/units.h"
#include "io/osim_model_writer.h"
#include "io/participant_loader.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;
using tinyxml2::XMLElement;

// Numbers are written in full (formatNumber round-trips a double); sums and rotations add a
// few ulps of the largest length or mass (1 m, 100 kg).
constexpr double kRoundTrip = 1e-12;
constexpr double kMassSum = 1e-12 * 100;
constexpr double kLowering = 0.04;  // m

Participant loadP1() { return loadParticipant(std::string(SWINGSIM_SOURCE_DIR) + "/participants/p1.yaml"); }

OsimLegPlacement makePlacement(const Participant& p, char side) {
  OsimLegPlacement place;
  place.modelName = p.name;
  place.side = side;
  place.hipHeight = 0.95;
  place.hipOffsetInPelvis = std::array<double, 2>{-0.07, -0.065};
  place.bodyMass = p.bodyMass;
  place.initial = p.initial;
  place.hipRange = p.hipRange;
  place.kneeMinFlexion = -2 * kDegToRad;
  place.kneeMaxFlexion = 150 * kDegToRad;
  return place;
}

std::vector<double> numbersIn(const XMLElement* e, const char* child) {
  const XMLElement* c = e ? e->FirstChildElement(child) : nullptr;
  std::vector<double> v;
  std::istringstream in(c && c->GetText() ? c->GetText() : "");
  for (double x; in >> x;) v.push_back(x);
  return v;
}

const XMLElement* findNamed(const XMLElement* parent, const char* type, const std::string& name) {
  for (const XMLElement* e = parent->FirstChildElement(type); e; e = e->NextSiblingElement(type))
    if (e->Attribute("name", name.c_str())) return e;
  return nullptr;
}

struct Written {
  tinyxml2::XMLDocument doc;
  const XMLElement* bodies = nullptr;
  const XMLElement* joints = nullptr;
};

void parseInto(const std::string& text, Written& w) {
  ASSERT_EQ(w.doc.Parse(text.c_str()), tinyxml2::XML_SUCCESS) << "well-formed XML";
  const XMLElement* model = w.doc.RootElement()->FirstChildElement("Model");
  w.bodies = model->FirstChildElement("BodySet")->FirstChildElement("objects");
  w.joints = model->FirstChildElement("JointSet")->FirstChildElement("objects");
}

const XMLElement* coordinateOf(const XMLElement* joint) {
  return joint ? joint->FirstChildElement("coordinates")->FirstChildElement("Coordinate") : nullptr;
}

class OsimExportSide : public ::testing::TestWithParam<char> {
 protected:
  Participant p = loadP1();
  LegGeometry g = calcLegGeometry(p, kLowering);
  char side = GetParam();
  std::string s = std::string(1, side);
  OsimLegPlacement place = makePlacement(p, side);
  std::string text = formatOsimModel(makeOsimLegModel(g, place), "header");
};

TEST_P(OsimExportSide, NamesAreTheGaitModelsForThatSide) {
  Written w;
  parseInto(text, w);
  for (const std::string& body :
       std::vector<std::string>{"pelvis", "femur_" + s, "tibia_" + s, "talus_" + s, "calcn_" + s, "toes_" + s})
    EXPECT_NE(findNamed(w.bodies, "Body", body), nullptr) << body;
  const XMLElement* hip = findNamed(w.joints, "PinJoint", "hip_" + s);
  const XMLElement* knee = findNamed(w.joints, "PinJoint", "knee_" + s);
  ASSERT_TRUE(hip && knee);
  EXPECT_STREQ(coordinateOf(hip)->Attribute("name"), ("hip_flexion_" + s).c_str());
  EXPECT_STREQ(coordinateOf(knee)->Attribute("name"), ("knee_angle_" + s).c_str());
  const std::string other = side == 'r' ? "_l" : "_r";
  EXPECT_EQ(text.find(other + "\""), std::string::npos) << "no body, joint or coordinate of the other side";
  EXPECT_EQ(text.find(other + "<"), std::string::npos) << "no frame of the other side";
}

// OpenSim's PinJoint turns the child frame about the joint frame's z by the coordinate. Turning
// the written frames by hand, the ankle must land where swingsim's own planar kinematics puts
// it for the same hip and knee flexion: so + hip_flexion is flexion and knee_angle = -flexion.
TEST_P(OsimExportSide, KneeAngleIsMinusFlexionAsSwingsimsKinematicsSaysTurningTheFrames) {
  const double hipFlexion = 20 * kDegToRad, kneeFlexion = 60 * kDegToRad;
  Written w;
  parseInto(text, w);
  const XMLElement* hip = findNamed(w.joints, "PinJoint", "hip_" + s);
  const XMLElement* knee = findNamed(w.joints, "PinJoint", "knee_" + s);
  ASSERT_TRUE(hip && knee);
  for (const XMLElement* j : {hip, knee})
    for (const XMLElement* f = j->FirstChildElement("frames")->FirstChildElement(); f; f = f->NextSiblingElement())
      EXPECT_EQ(numbersIn(f, "orientation"), (std::vector<double>{0, 0, 0}))
          << "frames along the body axes, as the gait models'";
  const auto kneeInFemur = numbersIn(
      findNamed(knee->FirstChildElement("frames"), "PhysicalOffsetFrame", "femur_" + s + "_offset"), "translation");
  const XMLElement* ankle = findNamed(w.joints, "WeldJoint", "ankle_" + s);
  const auto ankleInTibia = numbersIn(
      findNamed(ankle->FirstChildElement("frames"), "PhysicalOffsetFrame", "tibia_" + s + "_offset"), "translation");
  ASSERT_EQ(kneeInFemur.size(), 3u);
  ASSERT_EQ(ankleInTibia.size(), 3u);
  const auto rotateZ = [](double q, double x, double y) {
    return std::array<double, 2>{std::cos(q) * x - std::sin(q) * y, std::sin(q) * x + std::cos(q) * y};
  };
  const double qHip = hipFlexion, qKnee = -kneeFlexion;  // the coordinates' values for that pose
  const auto knee2 = rotateZ(qHip, kneeInFemur[0], kneeInFemur[1]);
  const auto shank = rotateZ(qHip + qKnee, ankleInTibia[0], ankleInTibia[1]);
  const PlanarPose pose = calcPlanarPoseXY(g, 0, hipFlexion, kneeFlexion);
  EXPECT_NEAR(knee2[0], pose.knee[0] - pose.hip[0], kRoundTrip);
  EXPECT_NEAR(knee2[1], pose.knee[1] - pose.hip[1], kRoundTrip);
  EXPECT_NEAR(knee2[0] + shank[0], pose.ankle[0] - pose.hip[0], kRoundTrip);
  EXPECT_NEAR(knee2[1] + shank[1], pose.ankle[1] - pose.hip[1], kRoundTrip);
  EXPECT_LT(shank[0], 0) << "a 60 deg flexed knee puts the ankle behind the knee with the thigh at 20 deg";
}

TEST_P(OsimExportSide, RangesAndDefaultsComeFromTheParticipantInTheGaitModelsSign) {
  Written w;
  parseInto(text, w);
  const XMLElement* hipQ = coordinateOf(findNamed(w.joints, "PinJoint", "hip_" + s));
  const XMLElement* kneeQ = coordinateOf(findNamed(w.joints, "PinJoint", "knee_" + s));
  ASSERT_TRUE(hipQ && kneeQ);
  EXPECT_EQ(numbersIn(hipQ, "default_value"), std::vector<double>{p.initial.hipFlexion});
  EXPECT_EQ(numbersIn(hipQ, "range"), (std::vector<double>{p.hipRange.minFlexion, p.hipRange.maxFlexion}));
  EXPECT_EQ(numbersIn(kneeQ, "default_value"), std::vector<double>{-p.initial.kneeFlexion});
  // Flexion to 150 deg and 2 deg of hyperextension: [-150, 2] deg, as Gait2354's [-120, 10].
  EXPECT_EQ(numbersIn(kneeQ, "range"), (std::vector<double>{-place.kneeMaxFlexion, -place.kneeMinFlexion}));
  EXPECT_LT(numbersIn(kneeQ, "range")[0], 0);
  EXPECT_GT(numbersIn(kneeQ, "range")[1], 0);
}

// Every body OpenSim should draw has one analytic shape in an offset frame of its own, sized
// and placed from the leg (a cylinder from joint to joint, a brick from ankle to toe tip).
TEST_P(OsimExportSide, ShapesAreOpenSimsAnalyticGeometryAlongEachSegment) {
  Written w;
  parseInto(text, w);
  EXPECT_EQ(text.find("<Mesh"), std::string::npos);
  EXPECT_EQ(text.find("mesh_file"), std::string::npos);
  struct Expected {
    std::string body, kind;
    std::vector<double> centre, size;
    const char* sizeElement;
  };
  for (const Expected& e :
       std::vector<Expected>{{"femur_" + s, "Cylinder", {0, -g.thighLength / 2, 0}, {g.thighLength / 2}, "half_height"},
                             {"tibia_" + s, "Cylinder", {0, -g.shankLength / 2, 0}, {g.shankLength / 2}, "half_height"},
                             {"talus_" + s, "Brick", {g.footLength / 2, 0, 0}, {g.footLength / 2}, "half_lengths"},
                             {"pelvis", "Ellipsoid", {0, 0, 0}, {}, "radii"}}) {
    const XMLElement* body = findNamed(w.bodies, "Body", e.body);
    ASSERT_NE(body, nullptr) << e.body;
    const XMLElement* components = body->FirstChildElement("components");
    ASSERT_NE(components, nullptr) << e.body;
    const XMLElement* frame = components->FirstChildElement("PhysicalOffsetFrame");
    ASSERT_NE(frame, nullptr) << e.body;
    EXPECT_STREQ(frame->FirstChildElement("socket_parent")->GetText(), "..") << "the frame is on its body";
    EXPECT_EQ(numbersIn(frame, "translation"), e.centre) << e.body;
    const XMLElement* shape = frame->FirstChildElement("attached_geometry")->FirstChildElement(e.kind.c_str());
    ASSERT_NE(shape, nullptr) << e.body << " " << e.kind;
    EXPECT_STREQ(shape->FirstChildElement("socket_frame")->GetText(), "..");
    const auto size = numbersIn(shape, e.sizeElement);
    ASSERT_FALSE(size.empty()) << e.body;
    for (double x : size) EXPECT_GT(x, 0) << e.body;
    if (!e.size.empty()) {
      EXPECT_EQ(size[0], e.size[0]) << e.body;
    }
    if (e.kind == "Cylinder") {
      EXPECT_GT(numbersIn(shape, "radius").at(0), 0) << e.body;
    }
  }
}

TEST_P(OsimExportSide, ImportOsimGivesTheLoweredLegBackOnThatSide) {
  const OsimModel m = parseOsimModel(text, "exported.osim");
  OsimImportOptions o;
  o.side = side;
  o.kneeModelPath = p.kneeModelPath;
  const Participant back = calcOsimParticipant(m, o).participant;
  const LegGeometry h = calcLegGeometry(back, 0);
  const std::vector<std::pair<double, double>> pairs = {
      {h.thighLength, g.thighLength},   {h.thighMass, g.thighMass},           {h.thighCom, g.thighCom},
      {h.thighInertia, g.thighInertia}, {h.shankLength, g.shankLength},       {h.shankMass, g.shankMass},
      {h.shankCom, g.shankCom},         {h.shankInertia, g.shankInertia},     {h.footLength, g.footLength},
      {h.footMass, g.footMass},         {h.footComForward, g.footComForward}, {h.footInertia, g.footInertia}};
  for (std::size_t i = 0; i < pairs.size(); ++i)
    EXPECT_NEAR(pairs[i].first, pairs[i].second, kRoundTrip) << "field " << i;
  EXPECT_NEAR(back.bodyMass, p.bodyMass, kMassSum);
  ASSERT_TRUE(back.hipOffsetInPelvis.has_value());
  EXPECT_NEAR((*back.hipOffsetInPelvis)[1], (*place.hipOffsetInPelvis)[1], kRoundTrip);
  EXPECT_EQ(back.name, p.name + "_" + s);
}

INSTANTIATE_TEST_SUITE_P(BothSides, OsimExportSide, ::testing::Values('r', 'l'),
                         [](const ::testing::TestParamInfo<char>& info) { return std::string(1, info.param); });

// ---- Added mass ---------------------------------------------------------------------------

TEST(OsimExportAddedMass, WeldedPointMassWhereSimulatePutsItAndTheMassesAddUp) {
  const Participant p = loadP1();
  const AddedMass added{0.8, 0.25};  // kg, m below the knee
  const LegGeometry g = calcLegGeometry(p, kLowering, added);
  const OsimLegPlacement place = makePlacement(p, 'r');
  const std::string text = formatOsimModel(makeOsimLegModel(g, place), "header");
  Written w;
  parseInto(text, w);
  const XMLElement* body = findNamed(w.bodies, "Body", "added_mass_r");
  ASSERT_NE(body, nullptr);
  EXPECT_EQ(numbersIn(body, "mass"), std::vector<double>{0.8});
  EXPECT_EQ(numbersIn(body, "inertia"), (std::vector<double>{0, 0, 0, 0, 0, 0})) << "a point mass";
  const XMLElement* weld = findNamed(w.joints, "WeldJoint", "added_mass_r_weld");
  ASSERT_NE(weld, nullptr);
  EXPECT_STREQ(weld->FirstChildElement("socket_parent_frame")->GetText(), "tibia_r_offset");
  EXPECT_EQ(
      numbersIn(findNamed(weld->FirstChildElement("frames"), "PhysicalOffsetFrame", "tibia_r_offset"), "translation"),
      (std::vector<double>{0, -0.25, 0}));
  const XMLElement* sphere = body->FirstChildElement("components")
                                 ->FirstChildElement("PhysicalOffsetFrame")
                                 ->FirstChildElement("attached_geometry")
                                 ->FirstChildElement("Sphere");
  ASSERT_NE(sphere, nullptr);
  // A steel sphere of 0.8 kg: r = (3 * 0.8 / (4 pi 7850))^(1/3) = 0.0290 m.
  EXPECT_NEAR(numbersIn(sphere, "radius").at(0), 0.0290, 0.0001);

  // Masses from the file alone: the model is the body plus the added mass.
  double total = 0;
  for (const XMLElement* b = w.bodies->FirstChildElement("Body"); b; b = b->NextSiblingElement("Body"))
    total += numbersIn(b, "mass").at(0);
  EXPECT_NEAR(total, p.bodyMass + 0.8, kMassSum);
  // The shank with its added mass, by hand: COM (m_s c_s + m_a d) / (m_s + m_a) below the knee.
  const OsimModel m = parseOsimModel(text, "exported.osim");
  const OsimBody& tibia = m.getBody("tibia_r");
  const double shankAndAdded = tibia.mass + 0.8;
  const double comBelowKnee = (tibia.mass * -tibia.massCenter.y() + 0.8 * 0.25) / shankAndAdded;
  EXPECT_NEAR(shankAndAdded, p.shank.mass + 0.8, kMassSum);
  EXPECT_NEAR(comBelowKnee,
              (g.shankMass * g.shankCom + added.mass * added.distanceBelowKnee) / (g.shankMass + added.mass),
              kRoundTrip);
  EXPECT_NEAR(m.getJointTo("added_mass_r").calcCentreInParent().y(), -0.25, kRoundTrip);
}

TEST(OsimExportAddedMass, RefusesAMassOffTheShankAndASideOtherThanRightOrLeft) {
  const Participant p = loadP1();
  LegGeometry g = calcLegGeometry(p, 0);
  OsimLegPlacement place = makePlacement(p, 'r');
  g.added = AddedMass{0.5, g.shankLength + 0.01};
  EXPECT_THROW(makeOsimLegModel(g, place), std::invalid_argument);
  g.added = AddedMass{-0.5, 0.1};
  EXPECT_THROW(makeOsimLegModel(g, place), std::invalid_argument);
  g.added = AddedMass{};
  place.side = 'x';
  try {
    makeOsimLegModel(g, place);
    ADD_FAILURE() << "side x accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("side: expected r or l (got x)"));
  }
}

}  // namespace
}  // namespace swingsim
