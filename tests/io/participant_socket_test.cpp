// A participant's `socket:` (docs/socket.md): MyoSuite's values by default, each key
// overridable, the written file loads back the same, and a bad value is refused at its line
// with its key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/input_error.h"
#include "core/units.h"
#include "io/participant_loader.h"

namespace swingsim {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::StartsWith;

const std::string kWithSocket = R"(name: PS
height_m: 1.80
body_mass_kg: 75
segments:
  thigh: {length_m: 0.410, mass_kg: 3.350, com_from_distal_m: 0.284, inertia_kgm2: 0.0264}
  shank: {length_m: 0.515, mass_kg: 0.785, com_from_distal_m: 0.260, inertia_kgm2: 0.0161}
  foot:  {length_m: 0.240, mass_kg: 1.030, com_from_distal_m: 0.140, inertia_kgm2: 0.0059}
knee_friction_Nm: 10
knee_model: ../models/damping-table-default.yaml
socket:
  piston_stiffness_N_per_m: 15000
  rotation_range_deg: 5
hip_moment:
  profile: biphasic_sine
  flexion_amplitude_Nm: 30
  flexion_duration_s: 0.2
  extension_amplitude_Nm: 15
  extension_duration_s: 0.2
)";

std::string errorFor(const std::string& text) {
  try {
    parseParticipant(text, "participants/ps.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string replaced(const std::string& from, const std::string& to) {
  std::string t = kWithSocket;
  const auto at = t.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return t.replace(at, from.size(), to);
}

TEST(ParticipantSocket, KeysOverrideMyoSuitesValuesAndTheRestStay) {
  const Participant p = parseParticipant(kWithSocket, "participants/ps.yaml");
  ASSERT_TRUE(p.socket.has_value());
  EXPECT_DOUBLE_EQ(p.socket->pistonStiffness, 15000);
  EXPECT_NEAR(p.socket->rotationRange, 5 * kDegToRad, 1e-15);
  const SocketCompliance myo;
  EXPECT_DOUBLE_EQ(p.socket->pistonDamping, myo.pistonDamping);
  EXPECT_DOUBLE_EQ(p.socket->mass, myo.mass);
  // Off unless written.
  EXPECT_FALSE(parseParticipant(replaced("socket:\n  piston_stiffness_N_per_m: 15000\n  rotation_range_deg: 5\n", ""),
                                "participants/ps.yaml")
                   .socket.has_value());
}

TEST(ParticipantSocket, WrittenFileLoadsBackTheSame) {
  const Participant p = parseParticipant(kWithSocket, "participants/ps.yaml");
  const std::string text = formatParticipantYaml(p, "participants");
  EXPECT_THAT(text, HasSubstr("socket"));
  const Participant back = parseParticipant(text, "participants/ps.yaml");
  EXPECT_EQ(formatParticipantYaml(back, "participants"), text);
  ASSERT_TRUE(back.socket.has_value());
  EXPECT_DOUBLE_EQ(back.socket->pistonStiffness, 15000);
  EXPECT_DOUBLE_EQ(back.socket->inertia, p.socket->inertia);
}

TEST(ParticipantSocket, BadValuesNameTheirLineAndKey) {
  EXPECT_THAT(
      errorFor(replaced("piston_stiffness_N_per_m: 15000", "mass_kg: 850")),
      AllOf(StartsWith("participants/ps.yaml:11:"), HasSubstr("mass_kg"), HasSubstr("grams"), HasSubstr("850")));
  EXPECT_THAT(errorFor(replaced("piston_stiffness_N_per_m: 15000", "piston_stiffness_N_per_m: -1")),
              AllOf(StartsWith("participants/ps.yaml:11:"), HasSubstr("piston_stiffness_N_per_m")));
  EXPECT_THAT(errorFor(replaced("piston_stiffness_N_per_m: 15000", "piston_stiffnes_N_per_m: 1")),
              HasSubstr("piston_stiffnes_N_per_m"));
}

}  // namespace
}  // namespace swingsim
