// The .osim reader and the participant built from one leg: a small inline model whose
// segments are computed here by hand, the shipped scaled Gait2354 model as it is, the
// splines against closed forms, and every bad input's message.
#include "io/osim_model.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "core/input_error.h"
#include "io/participant_loader.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

// Sums of a few products of short decimals: a few ulps of 1.
constexpr double kArithmetic = 1e-12;

// A planar right leg: pelvis, femur, tibia, talus, calcn, toes. The knee's centre is a
// MultiplierFunction (scale 1.1) of a SimmSpline of the linear y = -0.40 + 0.01 q, so at
// q = 0 it lies 0.44 m below the hip. Numbers chosen for the hand computation below.
const std::string kLeg = R"(<?xml version="1.0" encoding="UTF-8" ?>
<OpenSimDocument Version="40000">
<Model name="tiny">
<BodySet name="bodyset"><objects>
  <Body name="pelvis"><mass>10</mass><mass_center>0 0 0</mass_center><inertia>0.1 0.1 0.1 0 0 0</inertia></Body>
  <Body name="femur_r"><mass>8</mass><mass_center>0 -0.17 0</mass_center><inertia>0.11 0.03 0.12 0 0 0</inertia></Body>
  <Body name="tibia_r"><mass>3</mass><mass_center>0 -0.18 0</mass_center><inertia>0.04 0.005 0.05 0 0 0</inertia></Body>
  <Body name="talus_r"><mass>0.1</mass><mass_center>0 0 0</mass_center><inertia>0.001 0.001 0.001 0 0 0</inertia></Body>
  <Body name="calcn_r"><mass>1.0</mass><mass_center>0.10 0.03 0</mass_center><inertia>0.001 0.003 0.004 0 0 0</inertia></Body>
  <Body name="toes_r"><mass>0.2</mass><mass_center>0.035 0.006 0</mass_center><inertia>0.0001 0.0002 0.0001 0 0 0</inertia></Body>
</objects></BodySet>
<JointSet name="jointset"><objects>
  <PinJoint name="hip_r">
    <socket_parent_frame>pelvis_offset</socket_parent_frame><socket_child_frame>femur_r_offset</socket_child_frame>
    <frames>
      <PhysicalOffsetFrame name="pelvis_offset"><socket_parent>/bodyset/pelvis</socket_parent><translation>-0.07 -0.08 0.09</translation><orientation>0 0 0</orientation></PhysicalOffsetFrame>
      <PhysicalOffsetFrame name="femur_r_offset"><socket_parent>/bodyset/femur_r</socket_parent><translation>0 0 0</translation><orientation>0 0 0</orientation></PhysicalOffsetFrame>
    </frames>
  </PinJoint>
  <CustomJoint name="knee_r">
    <socket_parent_frame>/bodyset/femur_r</socket_parent_frame><socket_child_frame>/bodyset/tibia_r</socket_child_frame>
    <SpatialTransform>
      <TransformAxis name="rotation1"><coordinates>knee_angle_r</coordinates><axis>0 0 1</axis><LinearFunction name="function"><coefficients> 1 0</coefficients></LinearFunction></TransformAxis>
      <TransformAxis name="translation2"><coordinates>knee_angle_r</coordinates><axis>0 1 0</axis>
        <MultiplierFunction name="function"><function><SimmSpline><x> -2 -1 0.5 1 2</x><y> -0.42 -0.41 -0.395 -0.39 -0.38</y></SimmSpline></function><scale>1.1</scale></MultiplierFunction>
      </TransformAxis>
    </SpatialTransform>
  </CustomJoint>
  <PinJoint name="ankle_r">
    <socket_parent_frame>tibia_r_offset</socket_parent_frame><socket_child_frame>/bodyset/talus_r</socket_child_frame>
    <frames><PhysicalOffsetFrame name="tibia_r_offset"><socket_parent>/bodyset/tibia_r</socket_parent><translation>0 -0.43 0</translation><orientation>0 0 0</orientation></PhysicalOffsetFrame></frames>
  </PinJoint>
  <WeldJoint name="subtalar_r">
    <socket_parent_frame>talus_r_offset</socket_parent_frame><socket_child_frame>/bodyset/calcn_r</socket_child_frame>
    <frames><PhysicalOffsetFrame name="talus_r_offset"><socket_parent>/bodyset/talus_r</socket_parent><translation>-0.05 -0.04 0.008</translation><orientation>0 0 0</orientation></PhysicalOffsetFrame></frames>
  </WeldJoint>
  <WeldJoint name="mtp_r">
    <socket_parent_frame>calcn_r_offset</socket_parent_frame><socket_child_frame>/bodyset/toes_r</socket_child_frame>
    <frames><PhysicalOffsetFrame name="calcn_r_offset"><socket_parent>/bodyset/calcn_r</socket_parent><translation>0.18 -0.002 0</translation><orientation>0 0 0</orientation></PhysicalOffsetFrame></frames>
  </WeldJoint>
</objects></JointSet>
</Model>
</OpenSimDocument>
)";

const std::string kShipped =
    std::string(SWINGSIM_SOURCE_DIR) + "/studies/data/opensim-subject01/gait2354_subject01_simbody.osim";

// kLeg with each (from, to) replaced in turn (first occurrence).
std::string withReplaced(const std::string& from, const std::string& to, const std::string& from2 = "",
                         const std::string& to2 = "") {
  std::string t = kLeg;
  for (const auto& [f, r] : {std::pair{from, to}, std::pair{from2, to2}}) {
    if (f.empty()) continue;
    const auto at = t.find(f);
    EXPECT_NE(at, std::string::npos) << f;
    if (at != std::string::npos) t.replace(at, f.size(), r);
  }
  return t;
}

std::string errorFor(const std::string& xml, char side = 'r') {
  try {
    OsimImportOptions o;
    o.side = side;
    calcOsimParticipant(parseOsimModel(xml, "tiny.osim"), o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(OsimSpline, SimmSplineReproducesACubicAndNaturalSplineMatchesItsClosedForm) {
  // FMM's end conditions are exact for a cubic, so the spline is the cubic itself.
  const auto cubic = [](double x) { return 0.3 - 0.2 * x + 0.05 * x * x + 0.01 * x * x * x; };
  const std::vector<double> xs = {-2, -1.2, -0.3, 0.4, 1.1, 2};
  std::vector<double> ys;
  for (double x : xs) ys.push_back(cubic(x));
  for (double at : {-1.7, 0.0, 0.77, 1.9})
    EXPECT_NEAR(calcOsimSplineValue(xs, ys, at, false), cubic(at), kArithmetic) << at;
  // Natural spline through (-1, 0), (0, 1), (1, 0): second derivative -3 at 0 (from
  // 4 M1 = 6 (-2)), so S(0.5) = -3 (0.5^3)/6 + (1 + 3/6) 0.5 = 0.6875.
  EXPECT_NEAR(calcOsimSplineValue({-1, 0, 1}, {0, 1, 0}, 0.5, true), 0.6875, kArithmetic);
  EXPECT_NEAR(calcOsimSplineValue({-1, 0, 1}, {0, 1, 0}, -0.5, true), 0.6875, kArithmetic);
  // Two points: the line.
  EXPECT_NEAR(calcOsimSplineValue({0, 2}, {1, 3}, 0.5, false), 1.5, kArithmetic);
}

TEST(OsimModel, ReadsBodiesAndJointsOfTheInlineModel) {
  const OsimModel m = parseOsimModel(kLeg, "tiny.osim");
  EXPECT_EQ(m.name, "tiny");
  ASSERT_EQ(m.bodies.size(), 6u);
  ASSERT_EQ(m.joints.size(), 5u);
  EXPECT_DOUBLE_EQ(m.getBody("calcn_r").massCenter.x(), 0.10);
  EXPECT_DOUBLE_EQ(m.getBody("femur_r").inertia(2, 2), 0.12);
  const OsimJoint& knee = m.getJointTo("tibia_r");
  EXPECT_EQ(knee.parentBody, "femur_r");
  EXPECT_TRUE(knee.centreMoves);
  EXPECT_NEAR(knee.calcCentreInParent().y(), -0.44, kArithmetic);  // 1.1 x (-0.40)
  EXPECT_FALSE(m.getJointTo("talus_r").centreMoves);
  EXPECT_NEAR(m.calcTotalMass(), 22.3, kArithmetic);
}

TEST(OsimParticipant, SegmentsOfTheInlineModelMatchTheHandComputation) {
  const OsimParticipant imported = calcOsimParticipant(parseOsimModel(kLeg, "tiny.osim"), {});
  const Participant& p = imported.participant;
  EXPECT_NEAR(p.thigh.length, 0.44, kArithmetic);
  EXPECT_NEAR(p.thigh.comFromDistal, 0.44 - 0.17, kArithmetic);
  EXPECT_DOUBLE_EQ(p.thigh.mass, 8);
  EXPECT_DOUBLE_EQ(p.thigh.inertia, 0.12);
  EXPECT_NEAR(p.shank.length, 0.43, kArithmetic);
  EXPECT_NEAR(p.shank.comFromDistal, 0.43 - 0.18, kArithmetic);
  // Foot, in the talus frame (ankle at the origin): talus COM (0, 0); calcn COM
  // (-0.05 + 0.10, -0.04 + 0.03) = (0.05, -0.01); toes COM (-0.05 + 0.18 + 0.035,
  // -0.04 - 0.002 + 0.006) = (0.165, -0.036).
  const double m = 0.1 + 1.0 + 0.2;
  const double cx = (1.0 * 0.05 + 0.2 * 0.165) / m, cy = (1.0 * -0.01 + 0.2 * -0.036) / m;
  const double izz = 0.001 + 0.004 + 0.0001 + 0.1 * (cx * cx + cy * cy) +
                     1.0 * ((0.05 - cx) * (0.05 - cx) + (-0.01 - cy) * (-0.01 - cy)) +
                     0.2 * ((0.165 - cx) * (0.165 - cx) + (-0.036 - cy) * (-0.036 - cy));
  EXPECT_NEAR(p.foot.mass, m, kArithmetic);
  EXPECT_EQ(p.footComFrom, FootComFrom::kAnkle);
  EXPECT_NEAR(p.foot.comFromDistal, cx, kArithmetic);
  EXPECT_NEAR(p.foot.inertia, izz, kArithmetic);
  // Toe tip: MTP centre x (-0.05 + 0.18) plus twice the toes' COM x (0.035).
  EXPECT_NEAR(p.foot.length, 0.13 + 0.07, kArithmetic);
  ASSERT_TRUE(p.hipOffsetInPelvis);
  EXPECT_DOUBLE_EQ((*p.hipOffsetInPelvis)[0], -0.07);
  EXPECT_DOUBLE_EQ((*p.hipOffsetInPelvis)[1], -0.08);
  EXPECT_NEAR(p.bodyMass, 22.3, kArithmetic);
  EXPECT_NEAR(p.height, (0.44 + 0.43) / 0.491, kArithmetic);
  EXPECT_EQ(p.name, "tiny_r");
  EXPECT_THAT(imported.provenance, HasSubstr("knee_r is a CustomJoint whose centre moves with the knee angle"));
  EXPECT_THAT(imported.provenance, HasSubstr("taken at full extension, knee angle 0"));
}

TEST(OsimParticipant, ProsthesisOptionsReplaceMassesKeepingGyrationRadius) {
  OsimImportOptions o;
  o.shankMass = 1.5;
  o.footMass = 0.65;
  o.footLength = 0.25;
  o.height = 1.75;
  const Participant p = calcOsimParticipant(parseOsimModel(kLeg, "tiny.osim"), o).participant;
  EXPECT_DOUBLE_EQ(p.shank.mass, 1.5);
  EXPECT_NEAR(p.shank.inertia, 0.05 * 1.5 / 3, kArithmetic);
  EXPECT_NEAR(p.shank.comFromDistal, 0.25, kArithmetic);
  EXPECT_DOUBLE_EQ(p.foot.mass, 0.65);
  EXPECT_DOUBLE_EQ(p.foot.length, 0.25);
  EXPECT_DOUBLE_EQ(p.height, 1.75);
}

TEST(OsimParticipant, ShippedGait2354ModelGivesAPlausibleSymmetricLeg) {
  const OsimModel model = loadOsimModel(kShipped);
  OsimImportOptions right, left;
  left.side = 'l';
  const Participant r = calcOsimParticipant(model, right).participant;
  const Participant l = calcOsimParticipant(model, left).participant;
  // Scaled Gait2354: knee centre at q = 0 is 1.14724 x the SimmSpline's (-0.00525..,
  // -0.3960..) below the hip, i.e. about 0.45 m; the tibia's ankle offset is 0.425065 m.
  EXPECT_NEAR(r.thigh.length, 0.4545, 0.001);  // mm: the spline value at 0 read off its knots
  EXPECT_NEAR(r.shank.length, 0.425065, kArithmetic);
  EXPECT_NEAR(r.thigh.mass, 8.98403823076288, kArithmetic);
  // Plausibility of the whole person (an adult male, subject01 of the OpenSim gait example).
  EXPECT_GT(r.bodyMass, 60);
  EXPECT_LT(r.bodyMass, 90);
  EXPECT_GT(r.height, 1.6);
  EXPECT_LT(r.height, 2.0);
  EXPECT_GT(r.foot.length, 0.15);
  EXPECT_LT(r.foot.length, 0.30);
  // The model is mirror-symmetric: the left leg's planar segments are the right's.
  EXPECT_NEAR(l.thigh.length, r.thigh.length, kArithmetic);
  EXPECT_NEAR(l.foot.comFromDistal, r.foot.comFromDistal, kArithmetic);
  EXPECT_NEAR(l.foot.inertia, r.foot.inertia, kArithmetic);
  ASSERT_TRUE(r.hipOffsetInPelvis);
  EXPECT_DOUBLE_EQ((*r.hipOffsetInPelvis)[0], -0.072437600000000005);
  EXPECT_DOUBLE_EQ((*r.hipOffsetInPelvis)[1], -0.067724500000000007);
}

TEST(OsimParticipant, WrittenFileLoadsBackToTheSameParticipant) {
  OsimImportOptions o;
  o.kneeModelPath = std::string(SWINGSIM_SOURCE_DIR) + "/models/damping-table-default.yaml";
  const OsimParticipant imported = calcOsimParticipant(loadOsimModel(kShipped), o);
  const std::string dir = std::string(SWINGSIM_SOURCE_DIR) + "/participants";
  const std::string text = formatParticipantYaml(imported.participant, dir, imported.provenance);
  const Participant back = parseParticipant(text, dir + "/imported.yaml");
  EXPECT_EQ(formatParticipantYaml(back, dir), formatParticipantYaml(imported.participant, dir));
  EXPECT_EQ(back.thigh.length, imported.participant.thigh.length);
  EXPECT_EQ(back.foot.inertia, imported.participant.foot.inertia);
  EXPECT_EQ(back.hipOffsetInPelvis, imported.participant.hipOffsetInPelvis);
  EXPECT_THAT(text, HasSubstr("# thigh: femur_r <mass>"));
}

// export-osim's foot is all in talus_r, calcn_r and toes_r massless: only the three together
// need a mass.
TEST(OsimModelErrors, AFootNeedsMassInOneOfItsBodiesNotInEach) {
  std::string leg = withReplaced("<mass>1.0</mass>", "<mass>0</mass>", "<mass>0.2</mass>", "<mass>0</mass>");
  const Participant p = calcOsimParticipant(parseOsimModel(leg, "tiny.osim"), OsimImportOptions{}).participant;
  EXPECT_DOUBLE_EQ(p.foot.mass, 0.1);  // talus_r's alone
  leg.replace(leg.find("<mass>0.1</mass>"), std::string("<mass>0.1</mass>").size(), "<mass>0</mass>");
  EXPECT_THAT(errorFor(leg), HasSubstr(std::string("tiny.osim:8") +  // talus_r is line 8 of kLeg
                                       ": <Body name=\"talus_r\">: <mass>: expected a positive mass in kg for the "
                                       "foot, talus_r + calcn_r + toes_r (got 0)"));
}

TEST(OsimModelErrors, EachBadInputNamesFileLineElementAndWhatWasFound) {
  EXPECT_THAT(errorFor("this is not xml <"),
              HasSubstr("tiny.osim:1: expected an OpenSim model (.osim XML) (got text that is not XML"));
  EXPECT_THAT(
      errorFor(withReplaced("Version=\"40000\"", "Version=\"30000\"")),
      HasSubstr(
          "tiny.osim:2: <OpenSimDocument Version>: expected an OpenSim 4 model, Version 40000 or later (got 30000"));
  EXPECT_THAT(
      errorFor(kLeg, 'l'),
      HasSubstr(
          "tiny.osim:4: <Body name=\"femur_l\">: expected a body of that name in the BodySet (got pelvis, femur_r"));
  EXPECT_THAT(errorFor(withReplaced("/bodyset/toes_r</socket_child_frame>", "/bodyset/ground</socket_child_frame>")),
              HasSubstr("expected a joint whose child frame is on body toes_r (got none)"));
  EXPECT_THAT(
      errorFor(withReplaced("<mass>3</mass>", "<mass>0</mass>")),
      HasSubstr(
          "tiny.osim:7: <Body name=\"tibia_r\">: <mass>: expected a positive mass in kg for a leg segment (got 0)"));
  EXPECT_THAT(errorFor(withReplaced("<mass>3</mass>", "<mass>-3</mass>")),
              HasSubstr("tiny.osim:7: <Body name=\"tibia_r\">: <mass>: expected a mass >= 0 kg (got -3)"));
  EXPECT_THAT(errorFor(withReplaced("<mass>3</mass>", "<mass>three</mass>")),
              HasSubstr("tiny.osim:7: <Body name=\"tibia_r\">: <mass>: expected 1 finite numbers (got \"three\")"));
  EXPECT_THAT(errorFor(withReplaced("<SimmSpline>", "<GCVSpline>", "</SimmSpline>", "</GCVSpline>")),
              HasSubstr("TransformAxis function: expected Constant, LinearFunction"));
  EXPECT_THAT(errorFor(withReplaced("<BodySet name=\"bodyset\"><objects>", "<BodySetX><objects>",
                                    "</objects></BodySet>", "</objects></BodySetX>")),
              HasSubstr("<Model name=\"tiny\">: expected a <BodySet> element (got none)"));
}

}  // namespace
}  // namespace swingsim
