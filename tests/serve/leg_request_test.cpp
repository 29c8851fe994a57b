// The leg a request to swingsim serve describes (serve/leg_request.h): shipped files by
// name only, uploads that name no file, the form's edits through the participant loader,
// and the simulation budget.
#include "serve/leg_request.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/input_error.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

const ShippedFiles& shipped() {
  static const ShippedFiles files(SWINGSIM_SOURCE_DIR);
  return files;
}

std::string readP1() {
  std::ifstream in(std::string(SWINGSIM_SOURCE_DIR) + "/participants/p1.yaml");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The InputError message `f()` throws ("" if none).
template <class F>
std::string messageOf(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

Leg load(const Json& body) { return loadLeg(readLegRequest(body), shipped(), ServeLimits{}); }

TEST(ShippedFilesTest, ListsTheShippedFilesByName) {
  EXPECT_THAT(shipped().getParticipantNames(), ::testing::Contains("p1"));
  EXPECT_THAT(shipped().getKneeNames(), ::testing::Contains("damping-table-default"));
  EXPECT_EQ(shipped().findParticipantPath("p1"), std::string(SWINGSIM_SOURCE_DIR) + "/participants/p1.yaml");
}

TEST(ShippedFilesTest, RefusesPathTraversalNames) {
  for (const char* name : {"../../etc/passwd", "/etc/passwd", "p1/../p2", "../participants/p1", "p1.yaml", ""}) {
    EXPECT_THAT(messageOf([&] { shipped().findParticipantPath(name); }),
                HasSubstr("participant: expected a shipped participant by name, one of"))
        << name;
    EXPECT_THAT(messageOf([&] { shipped().findKneePath(name); }),
                HasSubstr("knee: expected a shipped knee model by name"))
        << name;
  }
}

TEST(LegRequestTest, AMassEditKeepsTheSegmentsRadiusOfGyrationUnlessTheInertiaIsEditedToo) {
  const Leg intact = load({{"participant", "p1"}});
  const double mass = intact.participant.shank.mass, inertia = intact.participant.shank.inertia;
  // Half the shank's mass: its inertia about the COM halves with it (the same radius of gyration).
  const Leg lighter = load({{"participant", "p1"}, {"edits", {{"segments.shank.mass_kg", std::to_string(mass / 2)}}}});
  EXPECT_NEAR(lighter.participant.shank.inertia, inertia * std::stod(std::to_string(mass / 2)) / mass, 1e-15);
  EXPECT_DOUBLE_EQ(lighter.participant.thigh.inertia, intact.participant.thigh.inertia);
  // Both edited: the inertia as given.
  const Leg both = load(
      {{"participant", "p1"}, {"edits", {{"segments.shank.mass_kg", "0.5"}, {"segments.shank.inertia_kgm2", "0.01"}}}});
  EXPECT_DOUBLE_EQ(both.participant.shank.inertia, 0.01);
}

TEST(LegRequestTest, LoadsAShippedParticipantAndItsKnee) {
  const Leg leg = load({{"participant", "p1"}});
  EXPECT_EQ(leg.participant.name, "P1");
  EXPECT_EQ(leg.knee.name, "damping-table-default");
}

TEST(LegRequestTest, ABadMassIsTheLoadersMessageNamingTheKey) {
  const std::string message = messageOf([] {
    load({{"participant", "p1"}, {"edits", {{"segments.shank.mass_kg", "-1"}}}});
  });
  EXPECT_THAT(message, HasSubstr("segments.shank.mass_kg: must be positive (got -1)"));
  EXPECT_EQ(findErrorKey(message), "segments.shank.mass_kg");
  const std::string text = messageOf([] { load({{"participant", "p1"}, {"edits", {{"body_mass_kg", "abc"}}}}); });
  EXPECT_EQ(findErrorKey(text), "body_mass_kg") << text;
}

TEST(LegRequestTest, AnEditOutsideTheFormIsRefused) {
  EXPECT_THAT(messageOf([] {
                load({{"participant", "p1"}, {"edits", {{"knee_model", "/etc/passwd"}}}});
              }),
              HasSubstr("edits: expected a main number of the form"));
  EXPECT_THAT(messageOf([] {
                load({{"participant", "p1"}, {"knee_settings", {{"kind", 1}}}});
              }),
              HasSubstr("knee_settings: expected knee_effects.model_scale"));
}

TEST(LegRequestTest, AnUploadLoadsAsTheShippedFileDoes) {
  const Leg uploaded = load({{"participant_yaml", readP1()}});
  const Leg shippedLeg = load({{"participant", "p1"}});
  EXPECT_EQ(uploaded.participant.bodyMass, shippedLeg.participant.bodyMass);
  EXPECT_EQ(uploaded.knee.path, shippedLeg.knee.path);
}

TEST(LegRequestTest, AnUploadNamesNoFileOutsideTheShippedModels) {
  std::string text = readP1();
  const std::string from = "knee_model: ../models/damping-table-default.yaml";
  ASSERT_NE(text.find(from), std::string::npos);
  for (const char* path : {"../../etc/passwd", "/etc/passwd", "../models/../../etc/passwd.yaml"}) {
    std::string bad = text;
    bad.replace(bad.find(from), from.size(), std::string("knee_model: ") + path);
    const std::string message = messageOf([&] { load({{"participant_yaml", bad}}); });
    EXPECT_THAT(message, HasSubstr("knee_model: expected a shipped knee model by name")) << path;
    EXPECT_EQ(findErrorKey(message), "knee_model");
  }
  // An upload's messages name it upload.yaml, not a path in the server's folders.
  std::string badMass = text;
  badMass.replace(badMass.find("body_mass_kg: 70"), 16, "body_mass_kg: -70");
  EXPECT_THAT(messageOf([&] {
                load({{"participant_yaml", badMass}});
              }),
              ::testing::StartsWith("upload.yaml:8: body_mass_kg:"));
  std::string byName = text;
  byName.replace(byName.find(from), from.size(), "knee_model: mauch-2phase");
  EXPECT_EQ(load({{"participant_yaml", byName}}).knee.name, "mauch-2phase");
  EXPECT_THAT(messageOf([&] {
                load({{"participant_yaml", text + "thigh_kinematics: /etc/passwd\n"}});
              }),
              HasSubstr("thigh_kinematics: expected none in an uploaded participant"));
}

TEST(LegRequestTest, ASwingTimeLimitAboveTheBudgetIsRefused) {
  std::string text = readP1();
  const std::string from = "time_limit_s: 1.5";
  ASSERT_NE(text.find(from), std::string::npos);
  text.replace(text.find(from), from.size(), "time_limit_s: 5");  // the loader allows up to 10 s
  EXPECT_THAT(
      messageOf([&] {
        load({{"participant_yaml", text}});
      }),
      HasSubstr("swing_end.time_limit_s: expected at most 3 s on swingsim serve (its simulation budget) (got 5)"));
}

TEST(LegRequestTest, KnobsOutOfRangeNameTheirKey) {
  EXPECT_THAT(messageOf([] {
                readLegRequest({{"participant", "p1"}, {"added_mass_kg", -1}});
              }),
              HasSubstr("added_mass_kg: expected 0 to 150 kg (got -1)"));
  EXPECT_THAT(messageOf([] {
                readLegRequest({{"participant", "p1"}, {"added_mass_position_m", 9}});
              }),
              HasSubstr("added_mass_position_m: expected 0 to 1.5 m"));
  EXPECT_THAT(messageOf([] {
                readLegRequest({{"participant", "p1"}, {"lowering_m", "x"}});
              }),
              HasSubstr("lowering_m: expected a number"));
  const std::string scale = messageOf([] {
    load({{"participant", "p1"}, {"knee_settings", {{"knee_effects.model_scale", -2}}}});
  });
  EXPECT_EQ(findErrorKey(scale), "knee_effects.model_scale") << scale;
}

}  // namespace
}  // namespace swingsim

namespace swingsim {
namespace {

// Issue 57: a long key or message (under the body limit) ended `swingsim serve` with SIGSEGV
// in std::regex, which recursed once per character. The scans are plain loops now.
TEST(LegRequestTest, AVeryLongMessageOrKeyIsScannedWithoutRecursion) {
  const std::string longKey(200000, 'a');
  EXPECT_EQ(findErrorKey(longKey + ": expected a number"), longKey);
  EXPECT_EQ(findErrorKey("request.yaml:12: " + longKey), "");
  EXPECT_EQ(findErrorKey(std::string(200000, ':') + "1: x: y"), "x");
  EXPECT_EQ(findErrorKey("p.yaml:3: segments.shank.mass_kg: expected"), "segments.shank.mass_kg");
  EXPECT_EQ(findErrorKey("a:b:7: c[1].d: bad"), "c[1].d") << "the first prefix whose key follows";
  EXPECT_EQ(findErrorKey("no key here"), "");
  const auto settings = [](const std::string& key) {
    return readLegRequest(Json::parse(R"({"participant": "p1", "knee_settings": {")" + key + R"(": 2}})")).kneeSettings;
  };
  EXPECT_THROW(settings(std::string(100000, 'k')), InputError);
  EXPECT_THROW(settings("impedance_state_machine.states[1]." + std::string(100000, 'k') + "1"), InputError);
  EXPECT_EQ(settings("impedance_state_machine.states[12].stiffness").size(), 1u);
  EXPECT_EQ(settings("knee_effects.model_scale").size(), 1u);
  EXPECT_THROW(settings("impedance_state_machine.states[123].k"), InputError);
  EXPECT_THROW(settings("impedance_state_machine.states[].k"), InputError);
  EXPECT_THROW(settings("impedance_state_machine.states[1].k2"), InputError);
}

}  // namespace
}  // namespace swingsim

namespace swingsim {
namespace {

// Issue 57: a misspelt request key (lowring_m) was ignored and the unchanged swing answered.
TEST(LegRequestTest, AnUnknownRequestKeyIsRefusedWithTheClosestKnownOne) {
  const Json body = Json::parse(R"({"participant": "p1", "lowring_m": 0.02})");
  try {
    checkRequestKeys(body, {});
    FAIL() << "accepted a misspelt key";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("lowring_m: unknown request key (did you mean lowering_m?)"));
    EXPECT_EQ(findErrorKey(e.what()), "lowring_m");
  }
  EXPECT_NO_THROW(checkRequestKeys(Json::parse(R"({"participant": "p1", "lowering_m": 0.02, "side": "l"})"), {"side"}));
  EXPECT_THROW(checkRequestKeys(Json::parse(R"({"participant": "p1", "side": "l"})"), {}), InputError);
  // A long unknown key is cut in the message.
  const std::string longKey(5000, 'z');
  try {
    checkRequestKeys(Json::parse(R"({")" + longKey + R"(": 1})"), {});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_LT(std::string(e.what()).size(), 600u);
  }
}

}  // namespace
}  // namespace swingsim

#include "serve/api_reply.h"

namespace swingsim {
namespace {

// Issue 57: JSON nested 30,000 deep and a number beyond a double (a 500 naming no key).
TEST(LegRequestTest, DeepNestingAndAnOverflowingNumberAreRequestErrors) {
  const std::string deep =
      R"({"participant": "p1", "edits": )" + std::string(30000, '[') + std::string(30000, ']') + "}";
  const ApiReply nested = answerOrError([&] { return readRequestBody(deep); });
  EXPECT_EQ(nested.status, 400);
  EXPECT_THAT(nested.body, HasSubstr("nested at most 64 deep"));
  const ApiReply huge = answerOrError([&] { return readRequestBody(R"({"lowering_m": 1e400})"); });
  EXPECT_EQ(huge.status, 400);
  EXPECT_THAT(huge.body, HasSubstr("expected numbers a double holds"));
  EXPECT_EQ(answerOrError([&] { return readRequestBody(R"({"knee_settings": {"a": [1, {"b": 2}]}})"); }).status, 200);
}

}  // namespace
}  // namespace swingsim
