#include "study/swing_listing.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/input_error.h"

namespace swingsim {
namespace {

const std::string kIk = std::string(SWINGSIM_SOURCE_DIR) + "/tests/data/opensim-gait10dof/subject01_walk_IK.mot";

// OpenSim's subject01 walk (0-2.5 s): the left leg swings twice, the right once completely
// (its first swing began before the recording); the events come from the kinematics.
TEST(SwingListing, ListsEachLegsCompleteSwings) {
  SwingListRequest left;
  left.kinematics = kIk;
  left.side = "l";
  const SwingListing l = listLegSwings(left);
  EXPECT_EQ(l.columns.hip, "hip_flexion_l");
  EXPECT_EQ(l.columns.knee, "knee_angle_l");
  ASSERT_EQ(l.list.swings.size(), 2u);
  EXPECT_NEAR(l.list.swings[0].toeOff, 0.793, 0.001);
  EXPECT_NEAR(l.framePeriod, 1.0 / 60, 1e-4);  // 60 Hz
  SwingListRequest right = left;
  right.side = "r";
  // The right knee rises from the file's first frame into a swing whose fastest flexion, and so
  // its toe-off (0.168 s; the force plates: 0.1648 s), lies inside the file: two swings.
  EXPECT_EQ(listLegSwings(right).list.swings.size(), 2u);
}

TEST(SwingListing, JsonNumbersTheSwingsFromOne) {
  SwingListRequest r;
  r.kinematics = kIk;
  r.side = "l";
  const Json j = makeSwingListJson(r, listLegSwings(r));
  EXPECT_EQ(j["side"], "l");
  EXPECT_TRUE(j["grf"].is_null());
  ASSERT_EQ(j["swings"].size(), 2u);
  EXPECT_EQ(j["swings"][1]["swing"], 2);
  EXPECT_EQ(j["swings"][0]["toe_off_source"], "kinematics");
  EXPECT_TRUE(j["swings"][0]["toe_off_force_minus_kinematics_ms"].is_null());
}

TEST(SwingListing, DefaultVerticalForceFollowsOpenSimsExampleFiles) {
  EXPECT_EQ(defaultVerticalForce("r"), "ground_force_vy");
  EXPECT_EQ(defaultVerticalForce("l"), "1_ground_force_vy");
}

}  // namespace
}  // namespace swingsim
