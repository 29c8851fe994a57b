// report.md of a diagnosis carries the warnings about the data, as stderr, the JSON and
// Python do: a user reading only the report sees them.
#include "report/diagnosis_markdown.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace swingsim {
namespace {

using ::testing::HasSubstr;

TEST(DiagnosisMarkdown, WarningsAreASectionOfTheReport) {
  EXPECT_EQ(formatWarningsSection({}), "");
  const std::string md = formatWarningsSection(
      {"right1: the hip angle hip_flexion_r of walk.mot is read without the pelvis tilt: set motion_columns: "
       "pelvis_tilt: pelvis_tilt",
       "right2: events from the kinematics, not the force (fallback_to_kinematics): grf.mot: ..."});
  EXPECT_THAT(md, HasSubstr("## Warnings\n"));
  EXPECT_THAT(md, HasSubstr("\n- right1: the hip angle hip_flexion_r of walk.mot is read without the pelvis tilt"));
  EXPECT_THAT(md, HasSubstr("\n- right2: events from the kinematics, not the force"));
}

}  // namespace
}  // namespace swingsim
