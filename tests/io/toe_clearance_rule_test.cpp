// The toe-clearance rule of a participant: walking flags a strike, running does not unless
// the hip's rise is stated, and a stated rise lifts the foot by exactly that much.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "core/input_error.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "swing/knee_setup.h"
#include "swing/swing_simulation.h"

namespace swingsim {
namespace {

std::string p1Text() {
  std::ifstream in(std::string(SWINGSIM_SOURCE_DIR) + "/participants/p1.yaml");
  std::stringstream s;
  s << in.rdbuf();
  return std::regex_replace(s.str(), std::regex("\\.\\./models/"), std::string(SWINGSIM_SOURCE_DIR) + "/models/");
}

Participant withRule(const std::string& rule) {
  std::string text = std::regex_replace(p1Text(), std::regex("toe_clearance:[^\n]*\n  gait: running[^\n]*\n"), rule);
  return parseParticipant(text, "p.yaml");
}

TEST(ToeClearanceRule, TheAlarmHoldsForWalkingOrAStatedHipRise) {
  EXPECT_FALSE(loadParticipant(std::string(SWINGSIM_SOURCE_DIR) + "/participants/p1.yaml").toeClearance.alarmHolds());
  EXPECT_TRUE(withRule("").toeClearance.alarmHolds());  // default: walking
  EXPECT_TRUE(withRule("toe_clearance: {gait: walking}\n").toeClearance.alarmHolds());
  const Participant rise = withRule("toe_clearance: {gait: running, hip_rise_m: 0.05}\n");
  EXPECT_TRUE(rise.toeClearance.alarmHolds());
  EXPECT_DOUBLE_EQ(rise.toeClearance.hipRise, 0.05);
  EXPECT_THROW(withRule("toe_clearance: {gait: flying}\n"), InputError);
  EXPECT_THROW(withRule("toe_clearance: {gait: running, hip_rise_m: 3}\n"), InputError);
}

TEST(ToeClearanceRule, AStatedHipRiseLiftsTheFootByThatMuch) {
  auto clearance = [](const Participant& p) {
    SwingSetup setup =
        makeSwingSetup(p, std::make_shared<const KneeLawSum>(makeKneeLaw(p, loadKneeModel(p.kneeModelPath))));
    return simulateSwing(setup).minToeClearance.value();  // an ended swing has its clearance
  };
  const double standing = clearance(withRule("toe_clearance: {gait: running}\n"));
  const double lifted = clearance(withRule("toe_clearance: {gait: running, hip_rise_m: 0.05}\n"));
  EXPECT_NEAR(lifted - standing, 0.05, 1e-9);
}

}  // namespace
}  // namespace swingsim
