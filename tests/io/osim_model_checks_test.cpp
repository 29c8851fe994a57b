// The checks of an imported OpenSim model (io/osim_model_checks.h): names given twice, two
// joints into one body, a link of the leg's chain missing or an extra body in it, a model in
// millimetres or grams, and every message at the .osim element, never at a participant YAML.
#include "io/osim_model_checks.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "../cli/run_swingsim.h"
#include "core/input_error.h"
#include "io/osim_model.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// A planar right leg of six bodies (pelvis line 5 ... toes_r line 10) and five joints
// (hip_r line 13, knee_r 20, ankle_r 29, subtalar_r 33, mtp_r 37); the fuzzer's seed too.
std::string tinyLeg() { return testing::slurp(std::string(SWINGSIM_SOURCE_DIR) + "/tests/data/osim-tiny-leg.osim"); }

// The tiny leg with `from` replaced by `to` (first occurrence; the text must be there).
std::string withReplaced(const std::string& from, const std::string& to) {
  std::string t = tinyLeg();
  const auto at = t.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) t.replace(at, from.size(), to);
  return t;
}

// What reading the model and importing its right leg throws ("(no error)" if nothing).
std::string errorFor(const std::string& xml) {
  try {
    calcOsimParticipant(parseOsimModel(xml, "tiny.osim"), OsimImportOptions{});
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(OsimModelChecks, ABodyNameGivenTwiceIsRefusedAtTheSecond) {
  const std::string second =
      "  <Body name=\"femur_r\"><mass>1</mass><mass_center>0 0 0</mass_center><inertia>0.1 0.1 0.1 0 0 "
      "0</inertia></Body>\n";
  EXPECT_THAT(
      errorFor(withReplaced("</objects></BodySet>", second + "</objects></BodySet>")),
      HasSubstr("tiny.osim:11: <Body name=\"femur_r\">: expected each body name once in the BodySet (got a second "
                "femur_r; the first is at line 6)"));
}

TEST(OsimModelChecks, AJointNameGivenTwiceIsRefusedAtTheSecond) {
  EXPECT_THAT(
      errorFor(withReplaced("<PinJoint name=\"ankle_r\">", "<PinJoint name=\"knee_r\">")),
      HasSubstr("tiny.osim:29: <PinJoint name=\"knee_r\">: expected each joint name once in the JointSet (got a "
                "second knee_r; the first is at line 20)"));
}

TEST(OsimModelChecks, TwoJointsIntoOneBodyAreAmbiguous) {
  const std::string second =
      "  <WeldJoint name=\"brace_r\"><socket_parent_frame>/bodyset/pelvis</socket_parent_frame>"
      "<socket_child_frame>/bodyset/femur_r</socket_child_frame></WeldJoint>\n";
  EXPECT_THAT(errorFor(withReplaced("</objects></JointSet>", second + "</objects></JointSet>")),
              HasSubstr("<WeldJoint name=\"brace_r\">: expected one joint into body femur_r (got a second: <PinJoint "
                        "name=\"hip_r\"> at line 13 is the first; which one places it is ambiguous)"));
}

TEST(OsimModelChecks, AMissingLinkOfTheChainIsRefusedNamingIt) {
  // No subtalar joint: calcn_r hangs from nothing.
  EXPECT_THAT(errorFor(withReplaced("/bodyset/calcn_r</socket_child_frame>", "/bodyset/nothing</socket_child_frame>")),
              HasSubstr("tiny.osim:12: <JointSet>: expected a joint whose child frame is on body calcn_r (got none); a "
                        "link of the leg's chain is missing"));
  // The femur on the ground: the pelvis link is missing (the hip offset would be the ground's).
  EXPECT_THAT(
      errorFor(
          withReplaced("<socket_parent>/bodyset/pelvis</socket_parent>", "<socket_parent>/ground</socket_parent>")),
      HasSubstr("tiny.osim:13: <PinJoint name=\"hip_r\">: expected a joint from pelvis to femur_r (got one from "
                "ground: the chain pelvis, femur, tibia, talus, calcn, toes has a link missing)"));
}

TEST(OsimModelChecks, AnExtraBodyInTheChainIsRefused) {
  // A pylon between the tibia and the talus: the ankle joint is the pylon's.
  std::string xml = withReplaced("<socket_parent>/bodyset/tibia_r</socket_parent>",
                                 "<socket_parent>/bodyset/pylon_r</socket_parent>");
  xml.replace(xml.find("</objects></BodySet>"), 0,
              "  <Body name=\"pylon_r\"><mass>0.5</mass><mass_center>0 0 0</mass_center><inertia>0.01 0.01 0.01 0 0 "
              "0</inertia></Body>\n");
  xml.replace(xml.find("</objects></JointSet>"), 0,
              "  <WeldJoint name=\"pylon_r\"><socket_parent_frame>/bodyset/tibia_r</socket_parent_frame>"
              "<socket_child_frame>/bodyset/pylon_r</socket_child_frame></WeldJoint>\n");
  EXPECT_THAT(errorFor(xml),
              HasSubstr("<PinJoint name=\"ankle_r\">: expected a joint from tibia_r to talus_r (got one from "
                        "pylon_r: the chain pelvis, femur, tibia, talus, calcn, toes has a link missing or "
                        "an extra body in it)"));
}

TEST(OsimModelChecks, AModelInMillimetresIsNamedAsSuch) {
  // The ankle 430 below the knee: 430 m, a model in millimetres.
  EXPECT_THAT(errorFor(withReplaced("<translation>0 -0.43 0</translation>", "<translation>0 -430 0</translation>")),
              HasSubstr("tiny.osim:29: <PinJoint name=\"ankle_r\">: the shank, from the knee_r centre to the ankle_r "
                        "centre: expected a length above 0 and at most 1.5 m (is the model in millimetres? OpenSim "
                        "lengths are in metres) (got 430 m)"));
}

TEST(OsimModelChecks, AModelInGramsIsNamedAsSuch) {
  EXPECT_THAT(errorFor(withReplaced("<mass>8</mass>", "<mass>8000</mass>")),
              HasSubstr("tiny.osim:6: <Body name=\"femur_r\">: <mass>: expected at most 500 kg, heavier than a whole "
                        "body (is the model in grams? OpenSim masses are in kg) (got 8000)"));
  // A leg segment's own limit: a 200 kg thigh.
  EXPECT_THAT(
      errorFor(withReplaced("<mass>8</mass>", "<mass>200</mass>")),
      HasSubstr("tiny.osim:6: <Body name=\"femur_r\">: <mass>: expected at most 150 kg for the thigh (is the model "
                "in grams? OpenSim masses are in kg) (got 200)"));
  // Every body, not only the leg's: a torso of 1e30 kg.
  EXPECT_THAT(errorFor(withReplaced("<mass>10</mass>", "<mass>1e30</mass>")),
              HasSubstr("tiny.osim:5: <Body name=\"pelvis\">: <mass>: expected at most 500 kg"));
}

TEST(OsimModelChecks, ANegativeInertiaOrACOMOffTheSegmentNamesTheBodyNotAYaml) {
  const std::string inertia =
      errorFor(withReplaced("<inertia>0.04 0.005 0.05 0 0 0</inertia>", "<inertia>0.04 0.005 -0.05 0 0 0</inertia>"));
  EXPECT_THAT(inertia, HasSubstr("tiny.osim:7: <Body name=\"tibia_r\">: <inertia>: expected moments of inertia >= 0 kg "
                                 "m^2 (got -0.05 as Izz)"));
  EXPECT_THAT(inertia, Not(HasSubstr(".yaml")));
  const std::string com =
      errorFor(withReplaced("<mass_center>0 -0.17 0</mass_center>", "<mass_center>0 0.3 0</mass_center>"));
  EXPECT_THAT(
      com, HasSubstr("tiny.osim:6: <Body name=\"femur_r\">: <mass_center>: expected the COM on the thigh, 0 to 0.44"));
  EXPECT_THAT(com, HasSubstr(" m from the knee_r centre along it (got 0.74 m)"));
  EXPECT_THAT(com, Not(HasSubstr(".yaml")));
}

}  // namespace
}  // namespace swingsim
