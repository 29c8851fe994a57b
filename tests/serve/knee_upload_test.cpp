// A knee model uploaded to swingsim serve (serve/leg_request.h, "knee_yaml"): read from its
// text through the knee loader, the same swing as the shipped file of the same text, an
// uploaded participant may name it, its bad values are named by key without a server path,
// and the tuning sets its numbers.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "core/output_files.h"
#include "serve/serve_api.h"
#include "serve_api_calls.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

using serve_test::callServeApi;

const std::string kSource = SWINGSIM_SOURCE_DIR;
std::string readShipped(const std::string& relative) { return readFile(kSource + "/" + relative); }

TEST(KneeUpload, SwingsAsTheShippedFileOfTheSameText) {
  const std::string text = readShipped("models/microprocessor-knee-osl.yaml");
  Json shipped = callServeApi(&ServeApi::simulate,
                              {{"participant", "p2"}, {"knee", "microprocessor-knee-osl"}, {"lowering_m", 0.03}});
  Json uploaded = callServeApi(&ServeApi::simulate, {{"participant", "p2"}, {"knee_yaml", text}, {"lowering_m", 0.03}});
  EXPECT_EQ(uploaded["knee_model"], "upload-knee");
  ASSERT_TRUE(shipped["swing_time_s"].is_number());
  EXPECT_EQ(uploaded["swing_time_s"], shipped["swing_time_s"]);
  EXPECT_EQ(uploaded["trajectory"], shipped["trajectory"]);
}

TEST(KneeUpload, AnUploadedParticipantMayNameIt) {
  std::string p1 = readShipped("participants/p1.yaml");
  const std::string from = "../models/damping-table-default.yaml";
  p1.replace(p1.find(from), from.size(), "my-own-knee.yaml");
  const Json refused = callServeApi(&ServeApi::describeParticipant, {{"participant_yaml", p1}}, 400);
  EXPECT_EQ(refused["key"], "knee_model");
  EXPECT_THAT(refused["error"].get<std::string>(), HasSubstr("uploaded with it"));
  const Json request = {{"participant_yaml", p1}, {"knee_yaml", readShipped("models/damping-table-default.yaml")}};
  EXPECT_EQ(callServeApi(&ServeApi::describeParticipant, request)["knee_model"], "upload-knee");
  const Json own = callServeApi(&ServeApi::simulate, request);
  const Json shipped = callServeApi(&ServeApi::simulate, {{"participant", "p1"}});
  EXPECT_EQ(own["swing_time_s"], shipped["swing_time_s"]);
}

TEST(KneeUpload, ABadValueIsNamedByKeyWithoutAServerPath) {
  std::string text = readShipped("models/damping-table-default.yaml");
  text += "knee_effects:\n  model_scale: -2\n";
  const Json bad = callServeApi(&ServeApi::simulate, {{"participant", "p1"}, {"knee_yaml", text}}, 400);
  EXPECT_THAT(bad["error"].get<std::string>(), HasSubstr("upload-knee.yaml"));
  EXPECT_THAT(bad["error"].get<std::string>(), Not(HasSubstr(kSource)));
  EXPECT_THAT(bad["key"].get<std::string>(), HasSubstr("model_scale"));
  EXPECT_EQ(callServeApi(&ServeApi::simulate, {{"participant", "p1"}, {"knee_yaml", "{ not: [yaml"}}, 400)["key"],
            "knee_yaml");
  EXPECT_EQ(callServeApi(&ServeApi::simulate, {{"participant", "p1"}, {"knee_yaml", text}, {"knee", "passive-knee"}},
                         400)["key"],
            "knee_yaml");
}

// No answer shows where the server's files are: the data folder is taken out of every path,
// in errors (a knee setting or a tuning range the uploaded knee refuses) and in results (the
// report names the knee file it used).
TEST(KneeUpload, NoAnswerNamesTheServersFolder) {
  const std::string knee = readShipped("models/damping-table-default.yaml");
  const std::vector<std::pair<ApiReply (ServeApi::*)(const std::string&) const, Json>> requests = {
      {&ServeApi::simulate,
       {{"participant", "p1"}, {"knee_yaml", knee}, {"knee_settings", {{"knee_effects.model_scale", -2}}}}},
      {&ServeApi::tune,
       {{"participant", "p1"},
        {"knee_yaml", knee},
        {"knobs", {{{"key", "knee_effects.model_scale"}, {"min", -1}, {"max", 2}}}}}},
      {&ServeApi::report, {{"participant", "p1"}, {"lowering_step_m", 0.1}}},
      {&ServeApi::sweep, {{"participant", "p1"}, {"knee_yaml", knee}, {"lowering_step_m", 0.1}}},
  };
  for (const auto& [call, body] : requests) {
    const ApiReply r = (serve_test::shippedServeApi().*call)(body.dump());
    EXPECT_THAT(r.body, Not(HasSubstr(kSource))) << body.dump().substr(0, 200);
  }
  const ApiReply report = serve_test::shippedServeApi().report(requests[2].second.dump());
  EXPECT_THAT(report.body, HasSubstr("models/damping-table-default.yaml"));
}

// A long file name of multi-byte characters is cut at a character's start: the refusal is a
// 400 with valid JSON, not a 500.
TEST(KneeUpload, ALongNonAsciiFileNameIsStillAClearRefusal) {
  std::string name;
  for (int k = 0; k < 80; ++k) name += "\xc3\xa9";  // e acute, 2 bytes each
  const Json j = callServeApi(&ServeApi::importOsim, {{"osim_text", "<not xml"}, {"file_name", name + ".osim"}}, 400);
  EXPECT_THAT(j["error"].get<std::string>(), HasSubstr("\xc3\xa9:1:"));
}

TEST(KneeUpload, TheTuningSetsItsNumbers) {
  const std::string key = "impedance_state_machine.states[1].damping_Nm_s_per_rad";
  const Json request = {{"participant", "p1"},
                        {"knee_yaml", readShipped("models/microprocessor-knee-osl.yaml")},
                        {"knobs", {{{"key", key}, {"min", 0.5}, {"max", 12}, {"log_scale", true}}}}};
  const Json tuned = callServeApi(&ServeApi::tune, request);
  ASSERT_EQ(tuned["knobs"].size(), 1u);
  const Json swing = callServeApi(&ServeApi::simulate, {{"participant", "p1"},
                                                        {"knee_yaml", request["knee_yaml"]},
                                                        {"knee_settings", {{key, tuned["knobs"][0]["value"]}}}});
  EXPECT_EQ(swing["swing_time_s"], tuned["swing_time_s"]);
}

}  // namespace
}  // namespace swingsim
