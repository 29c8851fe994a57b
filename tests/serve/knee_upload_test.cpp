// A knee model uploaded to swingsim serve (serve/leg_request.h, "knee_yaml"): read from its
// text through the knee loader, the same swing as the shipped file of the same text, an
// uploaded participant may name it, its bad values are named by key without a server path,
// and the tuning sets its numbers.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

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
  Json shipped = callServeApi(&ServeApi::simulate, {{"participant", "p2"}, {"knee", "microprocessor-knee-osl"}, {"lowering_m", 0.03}});
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
  EXPECT_EQ(callServeApi(&ServeApi::simulate, {{"participant", "p1"}, {"knee_yaml", "{ not: [yaml"}}, 400)["key"], "knee_yaml");
  EXPECT_EQ(callServeApi(&ServeApi::simulate, {{"participant", "p1"}, {"knee_yaml", text}, {"knee", "passive-knee"}}, 400)["key"], "knee_yaml");
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
