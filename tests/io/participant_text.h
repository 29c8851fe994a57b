#pragma once
// The participant file the loader tests start from (Burkett P1's segments, the default knee,
// a biphasic hip moment), and the two helpers they share: the loader's message for a text,
// and a text with one piece replaced.
#include <gtest/gtest.h>

#include <string>

#include "core/input_error.h"
#include "io/participant_loader.h"

namespace swingsim::testing {

/// The path the texts are parsed at (messages start with it).
inline const std::string kParticipantPath = "participants/px.yaml";

inline const std::string kParticipantText = R"(name: PX
height_m: 1.80
body_mass_kg: 75
segments:
  thigh: {length_m: 0.410, mass_kg: 3.350, com_from_distal_m: 0.284, inertia_kgm2: 0.0264}
  shank: {length_m: 0.515, mass_kg: 0.785, com_from_distal_m: 0.260, inertia_kgm2: 0.0161}
  foot:  {length_m: 0.240, mass_kg: 1.030, com_from_distal_m: 0.140, inertia_kgm2: 0.0059}
knee_friction_Nm: 10
knee_model: ../models/damping-table-default.yaml
hip_moment:
  profile: biphasic_sine
  flexion_amplitude_Nm: 30
  flexion_duration_s: 0.2
  extension_amplitude_Nm: 15
  extension_duration_s: 0.2
)";

/// The loader's message for `text` parsed at kParticipantPath, or "(no error)".
inline std::string participantError(const std::string& text) {
  try {
    parseParticipant(text, kParticipantPath);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

/// `text` with the first `from` replaced by `to` (a test failure if `from` is not in it).
inline std::string replacedIn(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at == std::string::npos) return text;
  return text.replace(at, from.size(), to);
}

}  // namespace swingsim::testing
