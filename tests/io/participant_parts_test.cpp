// A participant whose shank and foot are named catalogue parts: the segments are the parts'
// masses, the file round-trips, and a mass written twice or a part of the wrong kind is
// refused at its line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/input_error.h"
#include "io/participant_loader.h"
#include "io/parts_catalogue_loader.h"
#include "model/prosthesis_parts.h"
#include "participant_text.h"

namespace swingsim {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::StartsWith;

// The shared participant with its shank and foot named as parts: the segments keep only
// their lengths (prosthesis_parts on line 4, the shank on line 7).
const std::string kWithParts = [] {
  using testing::replacedIn;
  std::string t = replacedIn(testing::kParticipantText, "segments:\n",
                             "prosthesis_parts: {knee: osl-knee, pylon: osl-tibial-pylon, foot: proteor-kinterra-26}\n"
                             "segments:\n");
  t = replacedIn(t, "  shank: {length_m: 0.515, mass_kg: 0.785, com_from_distal_m: 0.260, inertia_kgm2: 0.0161}",
                 "  shank: {length_m: 0.515}");
  return replacedIn(t, "  foot:  {length_m: 0.240, mass_kg: 1.030, com_from_distal_m: 0.140, inertia_kgm2: 0.0059}",
                    "  foot:  {length_m: 0.180}");
}();

std::string errorFor(const std::string& text) { return testing::participantError(text); }
std::string replaced(const std::string& from, const std::string& to) {
  return testing::replacedIn(kWithParts, from, to);
}

TEST(ParticipantParts, SegmentsAreTheCatalogueParts) {
  const Participant p = parseParticipant(kWithParts, "participants/px.yaml");
  const PartsCatalogue c = loadPartsCatalogue(defaultPartsCataloguePath());
  const ProsthesisPart& knee = *c.find("osl-knee");
  const ProsthesisPart& pylon = *c.find("osl-tibial-pylon");
  const double span = 0.515 - knee.length;
  EXPECT_NEAR(p.shank.mass, knee.mass + pylon.mass * span / pylon.length, 1e-12);
  EXPECT_DOUBLE_EQ(p.shank.length, 0.515);
  EXPECT_DOUBLE_EQ(p.foot.mass, c.find("proteor-kinterra-26")->mass);
  EXPECT_DOUBLE_EQ(p.thigh.mass, 3.350);  // not a part: as written
  // The knee unit keeps its height when the axis is lowered.
  EXPECT_DOUBLE_EQ(p.minShankLength, knee.length);
  ASSERT_TRUE(p.parts.has_value());
  EXPECT_EQ(p.parts->knee, "osl-knee");
}

TEST(ParticipantParts, WrittenFileNamesThePartsAndLoadsBackTheSame) {
  const Participant p = parseParticipant(kWithParts, "participants/px.yaml");
  const std::string text = formatParticipantYaml(p, "participants");
  EXPECT_THAT(text, HasSubstr("prosthesis_parts"));
  EXPECT_THAT(text, HasSubstr("osl-knee"));
  const Participant back = parseParticipant(text, "participants/px.yaml");
  EXPECT_EQ(formatParticipantYaml(back, "participants"), text);
  EXPECT_DOUBLE_EQ(back.shank.mass, p.shank.mass);
  EXPECT_DOUBLE_EQ(back.foot.inertia, p.foot.inertia);
}

TEST(ParticipantParts, BadChoicesNameTheirLine) {
  EXPECT_THAT(
      errorFor(replaced("shank: {length_m: 0.515}", "shank: {length_m: 0.515, mass_kg: 1.2}")),
      AllOf(StartsWith("participants/px.yaml:7:"), HasSubstr("mass_kg"), HasSubstr("come from prosthesis_parts")));
  EXPECT_THAT(errorFor(replaced("knee: osl-knee", "knee: osl-foot")),
              AllOf(StartsWith("participants/px.yaml:4:"), HasSubstr("expected a knee"), HasSubstr("(it is a foot)")));
  EXPECT_THAT(errorFor(replaced("knee: osl-knee", "knee: c-leg")),
              AllOf(HasSubstr("osl-knee"), HasSubstr("ottobock-3r15"), HasSubstr("'c-leg'")));
  EXPECT_THAT(errorFor(replaced("shank: {length_m: 0.515}", "shank: {length_m: 0.15}")),
              AllOf(HasSubstr("prosthesis_parts"), HasSubstr("do not fit in the shank")));
  EXPECT_THAT(errorFor(replaced("{knee: osl-knee, pylon: osl-tibial-pylon, foot: proteor-kinterra-26}", "{}")),
              HasSubstr("expected at least one of knee, pylon, ankle, foot"));
}

}  // namespace
}  // namespace swingsim
