// The knee model file's `kind: impedance_state_machine` (the microprocessor knee): the
// shipped model loads with the Open Source Leg's values in SI, writes and reads back the
// same, and bad values are refused with file:line: key: expected (got ...).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "core/input_error.h"
#include "core/units.h"
#include "io/knee_model_loader.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

// Line numbers below count from 1 at "kind:".
const char* kValid = R"(kind: impedance_state_machine
impedance_state_machine:
  mode: powered
  torque_limit_Nm: 60
  states:
    - name: swing_flexion
      stiffness_Nm_per_rad: 39.749
      damping_Nm_s_per_rad: 0.063
      equilibrium_deg: 60
      transition:
        to: swing_extension
        when_flexion: above
        flexion_deg: 50
        when_rate: below
        rate_deg_s: 3
    - name: swing_extension
      stiffness_Nm_per_rad: 15.899
      damping_Nm_s_per_rad: 3.816
      equilibrium_deg: 5
)";

std::string errorOf(const std::string& text) {
  try {
    parseKneeModel(text, "mp.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

const ImpedanceStateMachine& lawOf(const KneeModel& m) {
  return dynamic_cast<const ImpedanceStateMachine&>(m.law.part(0));
}

TEST(ImpedanceKneeModel, ShippedModelLoadsInSI) {
  const KneeModel m = loadKneeModel(std::string(SWINGSIM_SOURCE_DIR) + "/models/microprocessor-knee-osl.yaml");
  EXPECT_STREQ(m.spec.kindKey(), "impedance_state_machine");
  const ImpedanceStateMachineParams& p = lawOf(m).params();
  ASSERT_EQ(p.states.size(), 3u);
  EXPECT_EQ(p.mode, ImpedanceMode::kPowered);
  EXPECT_DOUBLE_EQ(p.states[0].stiffness, 39.749);  // N m/rad, as the OSL file
  EXPECT_DOUBLE_EQ(p.states[0].equilibrium, 60 * kDegToRad);
  EXPECT_DOUBLE_EQ(p.states[0].transition.rate, 3 * kDegToRad);
  EXPECT_EQ(p.states[1].transition.flexionSide, ThresholdSide::kBelow);
  EXPECT_DOUBLE_EQ(p.states[2].damping, 3.180);
  EXPECT_EQ(m.law.part(m.law.size() - 1).name(), "hyperextension stop");
}

TEST(ImpedanceKneeModel, WrittenModelReadsBackTheSame) {
  const KneeModel m = loadKneeModel(std::string(SWINGSIM_SOURCE_DIR) + "/models/microprocessor-knee-osl.yaml");
  const KneeModel back = parseKneeModel(formatKneeModelYaml(m.spec), "back.yaml");
  const ImpedanceStateMachineParams &a = lawOf(m).params(), &b = lawOf(back).params();
  ASSERT_EQ(a.states.size(), b.states.size());
  EXPECT_EQ(a.mode, b.mode);
  EXPECT_DOUBLE_EQ(a.torqueLimit, b.torqueLimit);
  EXPECT_DOUBLE_EQ(a.latchTime, b.latchTime);
  for (std::size_t i = 0; i < a.states.size(); ++i) {
    EXPECT_EQ(a.states[i].name, b.states[i].name);
    EXPECT_NEAR(a.states[i].stiffness, b.states[i].stiffness, 1e-12);
    EXPECT_NEAR(a.states[i].damping, b.states[i].damping, 1e-12);
    EXPECT_NEAR(a.states[i].equilibrium, b.states[i].equilibrium, 1e-12);
    EXPECT_EQ(a.states[i].hasTransition, b.states[i].hasTransition);
    EXPECT_EQ(a.states[i].transition.to, b.states[i].transition.to);
    EXPECT_EQ(a.states[i].transition.flexionSide, b.states[i].transition.flexionSide);
    EXPECT_EQ(a.states[i].transition.rateSide, b.states[i].transition.rateSide);
    EXPECT_NEAR(a.states[i].transition.flexion, b.states[i].transition.flexion, 1e-12);
    EXPECT_NEAR(a.states[i].transition.rate, b.states[i].transition.rate, 1e-12);
  }
}

TEST(ImpedanceKneeModel, ValidTextLoads) { EXPECT_EQ(errorOf(kValid), ""); }

TEST(ImpedanceKneeModel, NegativeDampingIsRefused) {
  EXPECT_THAT(
      errorOf(replaced(kValid, "damping_Nm_s_per_rad: 3.816", "damping_Nm_s_per_rad: -1")),
      HasSubstr("mp.yaml:18: impedance_state_machine.states[1].damping_Nm_s_per_rad: expected a damping in [0, "));
  EXPECT_THAT(errorOf(replaced(kValid, "damping_Nm_s_per_rad: 3.816", "damping_Nm_s_per_rad: -1")),
              HasSubstr("(got -1)"));
}

TEST(ImpedanceKneeModel, UnknownModeIsRefused) {
  EXPECT_THAT(errorOf(replaced(kValid, "mode: powered", "mode: turbo")),
              HasSubstr("mp.yaml:3: impedance_state_machine.mode:"));
  EXPECT_THAT(errorOf(replaced(kValid, "mode: powered", "mode: turbo")), HasSubstr("turbo"));
}

TEST(ImpedanceKneeModel, TransitionToAnUnknownStateIsRefused) {
  EXPECT_THAT(
      errorOf(replaced(kValid, "to: swing_extension", "to: late_swing")),
      HasSubstr("mp.yaml:11: impedance_state_machine.states[0].transition.to: expected the next state in the list, "
                "swing_extension (got late_swing)"));
}

TEST(ImpedanceKneeModel, TorqueLimitMustBePositive) {
  for (const char* bad : {"0", "-5"})
    EXPECT_THAT(errorOf(replaced(kValid, "torque_limit_Nm: 60", std::string("torque_limit_Nm: ") + bad)),
                HasSubstr(std::string("mp.yaml:4: impedance_state_machine.torque_limit_Nm: must be positive (got ") +
                          bad + ")"));
}

TEST(ImpedanceKneeModel, MissingAndSurplusTransitionsAreRefused) {
  // The last state with a transition: it has nowhere to go.
  const std::string surplus = std::string(kValid) + "      transition: {to: swing_flexion}\n";
  EXPECT_THAT(errorOf(surplus), HasSubstr("mp.yaml:20: impedance_state_machine.states[1].transition.to: expected no "
                                          "transition in the last state"));
  // A threshold side without its threshold.
  EXPECT_THAT(
      errorOf(replaced(kValid, "        flexion_deg: 50\n", "")),
      HasSubstr("mp.yaml:12: impedance_state_machine.states[0].transition.when_flexion: expected its threshold, "
                "flexion_deg, beside it (got no flexion_deg)"));
  // A threshold without its side (issue 57): it was ignored, the state ended at once and P1
  // swung 0.257 s instead of 0.429 s.
  EXPECT_THAT(errorOf(replaced(kValid, "        when_flexion: above\n", "")),
              HasSubstr("impedance_state_machine.states[0].transition.flexion_deg: expected its side beside it, "
                        "when_flexion: above or below (got no side (or when_flexion: any))"));
  EXPECT_THAT(errorOf(replaced(kValid, "when_flexion: above", "when_flexion: any")),
              HasSubstr("transition.flexion_deg: expected its side beside it"));
}

TEST(ImpedanceKneeModel, LatchTimeMustBeFast) {
  EXPECT_THAT(errorOf(replaced(kValid, "torque_limit_Nm: 60\n", "torque_limit_Nm: 60\n  latch_time_s: 0.05\n")),
              HasSubstr("mp.yaml:5: impedance_state_machine.latch_time_s: expected a latch time constant"));
}

}  // namespace
}  // namespace swingsim
