// A compliant socket from swingsim serve's form (docs/socket.md): a stiffness typed into a
// socket field turns the socket on with MyoSuite's other values, the reply carries its peak
// give, an empty form leaves the leg rigid, and a bad value is named by its key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "serve/leg_request.h"
#include "serve/serve_api.h"
#include "serve_api_calls.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

using serve_test::callServeApi;

/// P1 simulated on the page's API with one socket field typed.
Json simulateP1With(const char* key, const char* value) {
  return callServeApi(&ServeApi::simulate, {{"participant", "p1"}, {"edits", {{key, value}}}});
}

TEST(ServeSocket, ATypedStiffnessTurnsTheSocketOnAndTheReplyHasItsGive) {
  const Json rigid = callServeApi(&ServeApi::simulate, {{"participant", "p1"}});
  EXPECT_FALSE(rigid.contains("socket_peak"));
  const char* key = "socket.rotation_stiffness_Nm_per_rad";
  const Json myo = simulateP1With(key, "350"), loose = simulateP1With(key, "100");
  ASSERT_TRUE(myo.contains("socket_peak")) << myo.dump();
  ASSERT_TRUE(loose.contains("socket_peak")) << loose.dump();
  // The socket gives, the swing moves, and a looser socket turns further.
  EXPECT_GT(myo["socket_peak"]["piston_m"].get<double>(), 0);
  EXPECT_NE(myo["swing_time_s"].get<double>(), rigid["swing_time_s"].get<double>());
  EXPECT_GT(loose["socket_peak"]["rotation_deg"].get<double>(), myo["socket_peak"]["rotation_deg"].get<double>());
}

TEST(ServeSocket, ATypedDamperTurnsTheSocketOnAndALighterOneLetsItGiveMore) {
  // The dampers hold the socket over a swing (docs/socket.md): MyoSuite's 175 N m s/rad
  // against a tenth of it.
  const char* key = "socket.rotation_damping_Nm_s_per_rad";
  const Json myo = simulateP1With(key, "175"), light = simulateP1With(key, "17.5");
  ASSERT_TRUE(myo.contains("socket_peak")) << myo.dump();
  ASSERT_TRUE(light.contains("socket_peak")) << light.dump();
  EXPECT_GT(light["socket_peak"]["rotation_deg"].get<double>(), 2 * myo["socket_peak"]["rotation_deg"].get<double>());
}

TEST(ServeSocket, TheFormOffersTheSocketAndABadValueIsNamedByItsKey) {
  const auto& keys = editableParticipantKeys();
  for (const char* key :
       {"socket.piston_stiffness_N_per_m", "socket.piston_damping_N_s_per_m", "socket.rotation_stiffness_Nm_per_rad",
        "socket.rotation_damping_Nm_s_per_rad", "socket.mass_kg"})
    EXPECT_NE(std::find(keys.begin(), keys.end(), key), keys.end()) << key;
  const Json bad = callServeApi(&ServeApi::simulate,
                                {{"participant", "p1"}, {"edits", {{"socket.piston_stiffness_N_per_m", "-5"}}}}, 400);
  EXPECT_THAT(bad.dump(), HasSubstr("piston_stiffness_N_per_m"));
}

}  // namespace
}  // namespace swingsim
