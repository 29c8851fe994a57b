// A participant's `socket:` (docs/socket.md): MyoSuite's values by default, each key
// overridable, the written file loads back the same, and a bad value is refused at its line
// with its key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/units.h"
#include "io/participant_loader.h"
#include "participant_text.h"

namespace swingsim {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::StartsWith;

using testing::kParticipantPath;

const std::string kSocket = "socket:\n  piston_stiffness_N_per_m: 15000\n  rotation_range_deg: 5\n";
const std::string kWithSocket = testing::kParticipantText + kSocket;
constexpr int kSocketLine = 17;  // the socket's first key's line in kWithSocket

std::string errorFor(const std::string& text) { return testing::participantError(text); }
std::string replaced(const std::string& from, const std::string& to) {
  return testing::replacedIn(kWithSocket, from, to);
}

TEST(ParticipantSocket, KeysOverrideMyoSuitesValuesAndTheRestStay) {
  const Participant p = parseParticipant(kWithSocket, kParticipantPath);
  ASSERT_TRUE(p.socket.has_value());
  EXPECT_DOUBLE_EQ(p.socket->pistonStiffness, 15000);
  EXPECT_NEAR(p.socket->rotationRange, 5 * kDegToRad, 1e-15);
  const SocketCompliance myo;
  EXPECT_DOUBLE_EQ(p.socket->pistonDamping, myo.pistonDamping);
  EXPECT_DOUBLE_EQ(p.socket->mass, myo.mass);
  // Off unless written.
  EXPECT_FALSE(parseParticipant(testing::kParticipantText, kParticipantPath).socket.has_value());
}

TEST(ParticipantSocket, WrittenFileLoadsBackTheSame) {
  const Participant p = parseParticipant(kWithSocket, kParticipantPath);
  const std::string text = formatParticipantYaml(p, "participants");
  EXPECT_THAT(text, HasSubstr("socket"));
  const Participant back = parseParticipant(text, kParticipantPath);
  EXPECT_EQ(formatParticipantYaml(back, "participants"), text);
  ASSERT_TRUE(back.socket.has_value());
  EXPECT_DOUBLE_EQ(back.socket->pistonStiffness, 15000);
  EXPECT_DOUBLE_EQ(back.socket->inertia, p.socket->inertia);
}

TEST(ParticipantSocket, BadValuesNameTheirLineAndKey) {
  EXPECT_THAT(errorFor(replaced("piston_stiffness_N_per_m: 15000", "mass_kg: 850")),
              AllOf(StartsWith(kParticipantPath + ":" + std::to_string(kSocketLine) + ":"), HasSubstr("mass_kg"),
                    HasSubstr("grams"), HasSubstr("850")));
  EXPECT_THAT(errorFor(replaced("piston_stiffness_N_per_m: 15000", "piston_stiffness_N_per_m: -1")),
              AllOf(StartsWith(kParticipantPath + ":" + std::to_string(kSocketLine) + ":"),
                    HasSubstr("piston_stiffness_N_per_m")));
  EXPECT_THAT(errorFor(replaced("piston_stiffness_N_per_m: 15000", "piston_stiffnes_N_per_m: 1")),
              HasSubstr("piston_stiffnes_N_per_m"));
}

}  // namespace
}  // namespace swingsim
