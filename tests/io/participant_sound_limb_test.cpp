// The participant key sound_limb_swing_time_s (the sweep's symmetry target): read in
// seconds, written back, and a value that is not a swing time refused with file:line: key.
#include "io/participant_loader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/input_error.h"
#include "participant_text.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

const std::string& kParticipant = testing::kParticipantText;
constexpr int kKeyLine = 16;  // the appended key's line in the text above

std::string errorFor(const std::string& value) {
  return testing::participantError(kParticipant + "sound_limb_swing_time_s: " + value + "\n");
}

TEST(ParticipantSoundLimb, ReadInSecondsAndAbsentWhenNotGiven) {
  EXPECT_FALSE(parseParticipant(kParticipant, "participants/px.yaml").soundLimbSwingTime.has_value());
  const Participant p = parseParticipant(kParticipant + "sound_limb_swing_time_s: 0.42\n", "participants/px.yaml");
  ASSERT_TRUE(p.soundLimbSwingTime.has_value());
  EXPECT_DOUBLE_EQ(*p.soundLimbSwingTime, 0.42);
}

TEST(ParticipantSoundLimb, NotASwingTimeIsRefusedWithFileLineKeyAndValue) {
  const std::string where = "participants/px.yaml:" + std::to_string(kKeyLine) + ": sound_limb_swing_time_s: ";
  for (const std::string value : {"-1", "0", "fast"}) {
    const std::string message = errorFor(value);
    EXPECT_THAT(message, HasSubstr(where)) << value;
    EXPECT_THAT(message, HasSubstr(value)) << value;
  }
  EXPECT_THAT(errorFor("-1"), HasSubstr("above 0"));
  EXPECT_THAT(errorFor("0"), HasSubstr("above 0"));
}

TEST(ParticipantSoundLimb, BundledBurkettRunnersCarryTable4AnatomicalAtZeroLowering) {
  // Burkett 2004 Table 4, measured anatomical swing time at 0 m (s).
  const std::vector<std::pair<std::string, double>> expected = {{"participants/p1.yaml", 0.499},
                                                                {"participants/p2.yaml", 0.332},
                                                                {"participants/p3.yaml", 0.478},
                                                                {"participants/p4.yaml", 0.396}};
  for (const auto& [file, seconds] : expected) {
    const Participant p = loadParticipant(std::string(SWINGSIM_SOURCE_DIR) + "/" + file);
    ASSERT_TRUE(p.soundLimbSwingTime.has_value()) << file;
    EXPECT_DOUBLE_EQ(*p.soundLimbSwingTime, seconds) << file;
  }
}

}  // namespace
}  // namespace swingsim
