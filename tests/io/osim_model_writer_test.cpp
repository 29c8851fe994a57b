// The .osim writer: the file read back with tinyxml2 alone holds every number of the leg at
// the lowering given; the reader and the import path give the participant's segments back;
// the trajectory .sto's angle columns are the model's coordinates.
#include "io/osim_model_writer.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/input_error.h"
#include "core/units.h"
#include "io/participant_loader.h"
#include "io/trajectory_writer.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;
using tinyxml2::XMLElement;

// Numbers are written in full (formatNumber round-trips a double exactly); the import path
// adds a norm and a dot product: a few ulps of the largest length (1 m).
constexpr double kRoundTrip = 1e-12;
constexpr double kLowering = 0.03;  // m: a lowering other than 0, so the lowered lengths are checked

Participant loadP1() { return loadParticipant(std::string(SWINGSIM_SOURCE_DIR) + "/participants/p1.yaml"); }

OsimLegPlacement makeTestPlacement(const Participant& p) {
  OsimLegPlacement place;
  place.modelName = p.name;
  place.hipHeight = 0.97;
  place.hipOffsetInPelvis = std::array<double, 2>{-0.071, -0.066};
  place.bodyMass = p.bodyMass;
  place.initial = p.initial;
  place.hipRange = p.hipRange;
  place.kneeMinFlexion = -0.01;
  place.kneeMaxFlexion = 2.5;
  return place;
}

std::vector<double> numbersIn(const XMLElement* e, const char* child) {
  const XMLElement* c = e->FirstChildElement(child);
  EXPECT_NE(c, nullptr) << child;
  std::vector<double> v;
  std::istringstream in(c && c->GetText() ? c->GetText() : "");
  for (double x; in >> x;) v.push_back(x);
  return v;
}

const XMLElement* findNamed(const XMLElement* objects, const char* type, const std::string& name) {
  for (const XMLElement* e = objects->FirstChildElement(type); e; e = e->NextSiblingElement(type))
    if (e->Attribute("name", name.c_str())) return e;
  ADD_FAILURE() << "no <" << type << " name=\"" << name << "\">";
  return nullptr;
}

// The <PhysicalOffsetFrame> of joint `j` that its socket `socket` names.
const XMLElement* socketFrame(const XMLElement* j, const char* socket) {
  const std::string name = j->FirstChildElement(socket)->GetText();
  return findNamed(j->FirstChildElement("frames"), "PhysicalOffsetFrame", name);
}

class OsimModelWriter : public ::testing::Test {
 protected:
  Participant p = loadP1();
  LegGeometry g = calcLegGeometry(p, kLowering);
  OsimLegPlacement place = makeTestPlacement(p);
  std::string text = formatOsimModel(makeOsimLegModel(g, place), "test header -- with dashes");
};

TEST_F(OsimModelWriter, BodiesHoldTheLegsMassesComsAndInertias) {
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(text.c_str()), tinyxml2::XML_SUCCESS);
  const XMLElement* root = doc.RootElement();
  EXPECT_EQ(root->IntAttribute("Version"), 40000);
  const XMLElement* model = root->FirstChildElement("Model");
  EXPECT_STREQ(model->Attribute("name"), "P1");
  EXPECT_EQ(numbersIn(model, "gravity"), (std::vector<double>{0, -kGravity, 0}));
  const XMLElement* bodies = model->FirstChildElement("BodySet")->FirstChildElement("objects");
  struct Expected {
    const char* name;
    double mass;
    std::vector<double> com, inertia;
  };
  const double legMass = g.thighMass + g.shankMass + g.footMass;
  for (const Expected& e : std::vector<Expected>{
           {"pelvis", p.bodyMass - legMass, {0, 0, 0}, {0, 0, 0, 0, 0, 0}},
           {"femur_r", g.thighMass, {0, -g.thighCom, 0}, {g.thighInertia, 0, g.thighInertia, 0, 0, 0}},
           {"tibia_r", g.shankMass, {0, -g.shankCom, 0}, {g.shankInertia, 0, g.shankInertia, 0, 0, 0}},
           {"talus_r", g.footMass, {g.footComForward, 0, 0}, {0, g.footInertia, g.footInertia, 0, 0, 0}},
           {"calcn_r", 0, {0, 0, 0}, {0, 0, 0, 0, 0, 0}},
           {"toes_r", 0, {0, 0, 0}, {0, 0, 0, 0, 0, 0}}}) {
    const XMLElement* b = findNamed(bodies, "Body", e.name);
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(numbersIn(b, "mass"), std::vector<double>{e.mass}) << e.name;
    EXPECT_EQ(numbersIn(b, "mass_center"), e.com) << e.name;
    EXPECT_EQ(numbersIn(b, "inertia"), e.inertia) << e.name;
  }
  // The lowered P1: thigh 0.410 + 0.03 m, shank COM at the knee's side fixed (fixed_from_proximal).
  EXPECT_DOUBLE_EQ(g.thighLength, p.thigh.length + kLowering);
  EXPECT_DOUBLE_EQ(g.shankCom, p.shank.length - p.shank.comFromDistal);
}

TEST_F(OsimModelWriter, JointsSitAtTheLoweredJointCentresWithSwingsimsCoordinates) {
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(text.c_str()), tinyxml2::XML_SUCCESS);
  const XMLElement* joints =
      doc.RootElement()->FirstChildElement("Model")->FirstChildElement("JointSet")->FirstChildElement("objects");
  const XMLElement* weld = findNamed(joints, "WeldJoint", "ground_pelvis");
  const XMLElement* hip = findNamed(joints, "PinJoint", "hip_r");
  const XMLElement* knee = findNamed(joints, "PinJoint", "knee_r");
  const XMLElement* ankle = findNamed(joints, "WeldJoint", "ankle_r");
  const XMLElement* mtp = findNamed(joints, "WeldJoint", "mtp_r");
  ASSERT_TRUE(weld && hip && knee && ankle && mtp);
  const auto& offset = *place.hipOffsetInPelvis;
  // The hip lands at (0, hipHeight) in the ground.
  const auto pelvisInGround = numbersIn(socketFrame(weld, "socket_parent_frame"), "translation");
  const auto hipInPelvis = numbersIn(socketFrame(hip, "socket_parent_frame"), "translation");
  EXPECT_EQ(hipInPelvis, (std::vector<double>{offset[0], offset[1], 0}));
  EXPECT_NEAR(pelvisInGround[0] + hipInPelvis[0], 0, kRoundTrip);
  EXPECT_NEAR(pelvisInGround[1] + hipInPelvis[1], place.hipHeight, kRoundTrip);
  EXPECT_EQ(numbersIn(socketFrame(knee, "socket_parent_frame"), "translation"),
            (std::vector<double>{0, -g.thighLength, 0}));
  EXPECT_EQ(numbersIn(socketFrame(ankle, "socket_parent_frame"), "translation"),
            (std::vector<double>{0, -g.shankLength, 0}));
  EXPECT_EQ(numbersIn(socketFrame(mtp, "socket_parent_frame"), "translation"),
            (std::vector<double>{g.footLength, 0, 0}));
  // Knee frames unturned, as the gait models': + rotation about z is an extension.
  for (const char* socket : {"socket_parent_frame", "socket_child_frame"})
    EXPECT_EQ(numbersIn(socketFrame(knee, socket), "orientation"), (std::vector<double>{0, 0, 0})) << socket;
  const XMLElement* hipQ = hip->FirstChildElement("coordinates")->FirstChildElement("Coordinate");
  const XMLElement* kneeQ = knee->FirstChildElement("coordinates")->FirstChildElement("Coordinate");
  EXPECT_STREQ(hipQ->Attribute("name"), "hip_flexion_r");
  EXPECT_STREQ(kneeQ->Attribute("name"), "knee_angle_r");
  EXPECT_EQ(numbersIn(hipQ, "default_value"), std::vector<double>{p.initial.hipFlexion});
  EXPECT_EQ(numbersIn(hipQ, "range"), (std::vector<double>{p.hipRange.minFlexion, p.hipRange.maxFlexion}));
  EXPECT_EQ(numbersIn(kneeQ, "default_value"), std::vector<double>{-p.initial.kneeFlexion});
  EXPECT_EQ(numbersIn(kneeQ, "range"), (std::vector<double>{-place.kneeMaxFlexion, -place.kneeMinFlexion}));
  EXPECT_STREQ(kneeQ->FirstChildElement("clamped")->GetText(), "false");
  // The sign, said in the file just before the coordinate.
  const auto* note = kneeQ->PreviousSibling() ? kneeQ->PreviousSibling()->ToComment() : nullptr;
  ASSERT_NE(note, nullptr);
  EXPECT_THAT(note->Value(), HasSubstr("- = FLEXION"));
  EXPECT_THAT(note->Value(), HasSubstr("Range [-143.239, 0.573] deg"));
  EXPECT_THAT(text, HasSubstr("test header - - with dashes"));  // "--" may not occur in a comment
}

TEST_F(OsimModelWriter, ReaderAndImportGiveTheLoweredLegBack) {
  const OsimModel m = parseOsimModel(text, "exported.osim");
  EXPECT_EQ(m.getJointTo("tibia_r").coordinates.at(0).name, makeOsimKneeCoordinate('r'));
  EXPECT_EQ(m.getJointTo("tibia_r").coordinates.at(0).rangeMin, -place.kneeMaxFlexion);
  EXPECT_EQ(m.getJointTo("femur_r").coordinates.at(0).defaultValue, p.initial.hipFlexion);
  OsimImportOptions o;
  o.kneeModelPath = p.kneeModelPath;
  const Participant back = calcOsimParticipant(m, o).participant;
  const LegGeometry h = calcLegGeometry(back, 0);  // the exported leg is the lowered one
  const std::vector<std::pair<double, double>> pairs = {
      {h.thighLength, g.thighLength},   {h.thighMass, g.thighMass},           {h.thighCom, g.thighCom},
      {h.thighInertia, g.thighInertia}, {h.shankLength, g.shankLength},       {h.shankMass, g.shankMass},
      {h.shankCom, g.shankCom},         {h.shankInertia, g.shankInertia},     {h.footLength, g.footLength},
      {h.footMass, g.footMass},         {h.footComForward, g.footComForward}, {h.footInertia, g.footInertia}};
  for (std::size_t i = 0; i < pairs.size(); ++i)
    EXPECT_NEAR(pairs[i].first, pairs[i].second, kRoundTrip) << "field " << i;
  ASSERT_TRUE(back.hipOffsetInPelvis.has_value());
  EXPECT_NEAR((*back.hipOffsetInPelvis)[0], (*place.hipOffsetInPelvis)[0], kRoundTrip);
  EXPECT_NEAR((*back.hipOffsetInPelvis)[1], (*place.hipOffsetInPelvis)[1], kRoundTrip);
  EXPECT_NEAR(back.bodyMass, p.bodyMass, kRoundTrip);
}

TEST_F(OsimModelWriter, TrajectoryStoColumnsNameTheModelsCoordinates) {
  SwingTrajectory t;
  t.time = {0, 0.01};
  t.hipFlexion = {-0.26, -0.25};
  t.kneeFlexion = {0.17, 0.2};
  t.hipFlexionRate = t.kneeFlexionRate = t.hipMoment = t.kneeMoment = {0, 0};
  const std::string sto = formatTrajectorySto(t, "swing");
  EXPECT_THAT(sto, HasSubstr("\ninDegrees=yes\n"));
  std::istringstream in(sto.substr(sto.find("endheader\n") + 10));
  std::string header;
  std::getline(in, header);
  std::vector<std::string> columns;
  std::istringstream cells(header);
  for (std::string c; std::getline(cells, c, '\t');) columns.push_back(c);
  std::vector<std::string> coordinates;
  for (const auto& j : parseOsimModel(text, "exported.osim").joints)
    for (const auto& c : j.coordinates) coordinates.push_back(c.name);
  ASSERT_EQ(coordinates, (std::vector<std::string>{"hip_flexion_r", "knee_angle_r"}));
  for (const auto& c : coordinates) EXPECT_THAT(columns, ::testing::Contains(c));
  // In degrees, as the header says: the first row's knee angle.
  std::string row;
  std::getline(in, row);
  EXPECT_THAT(row, HasSubstr("\t-" + formatNumber(0.17 * kRadToDeg).substr(0, 6)));  // knee_angle_r: - = flexion
}

TEST_F(OsimModelWriter, RefusesAnEmptyRange) {
  place.kneeMaxFlexion = place.kneeMinFlexion;
  EXPECT_THROW(makeOsimLegModel(g, place), std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
