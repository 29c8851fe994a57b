// `kind: knee-tuning` study files (study/tuning_study.h): what loads, and each bad input
// refused with file:line: key.
#include "study/tuning_study.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "core/input_error.h"
#include "core/units.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;

std::string writeTemp(const std::string& name, const std::string& text) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("swingsim_tuning_study_test-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << text;
  return (dir / name).string();
}

// A study with `knobs` and `targets` (YAML text, indented), on P1 and the damping table.
std::string study(const std::string& knobs, const std::string& targets, const std::string& participant = "") {
  return "kind: knee-tuning\nparticipant: " + (participant.empty() ? kRoot + "/participants/p1.yaml" : participant) +
         "\nknee_model: " + kRoot + "/models/damping-table-default.yaml\nknobs:\n" + knobs + "targets:\n" + targets;
}

const std::string kKnobs = "  - key: lowering_m\n    range: [0, 0.05]\n";
const std::string kTargets = "  swing_time_s: {value: sound_limb}\n";

// The message of loading `text`, "" if it loaded.
std::string refusal(const std::string& text) {
  try {
    loadTuningStudy(writeTemp("study.yaml", text));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(TuningStudy, LoadsTheShippedExample) {
  const TuningStudy s = loadTuningStudy(kRoot + "/studies/tune-p1-damping.yaml");
  ASSERT_EQ(s.knobs.size(), 3u);
  EXPECT_EQ(s.knobs[1].key, "knee_effects.model_scale");
  EXPECT_TRUE(s.knobs[1].logScale);
  ASSERT_EQ(s.targets.size(), 3u);
  EXPECT_DOUBLE_EQ(s.targets[0].lower, 0.499);  // P1's sound_limb_swing_time_s
  EXPECT_DOUBLE_EQ(s.targets[1].lower, 60 * kDegToRad);
  EXPECT_TRUE(s.targets[1].hard);
  EXPECT_NE(s.swingTimeSource.find("sound_limb_swing_time_s"), std::string::npos);
}

TEST(TuningStudy, RefusesAKnobThatIsNotANumericKeyOfTheKneeModel) {
  const std::string m = refusal(study("  - key: damping_table.speed_rule\n    range: [0, 1]\n", kTargets));
  EXPECT_TRUE(
      std::regex_search(m, std::regex(R"(study\.yaml:5: knobs\[0\]\.key: expected .*numeric key.*not a number)")))
      << m;
  const std::string list = refusal(study("  - key: damping_table.moment_Nm\n    range: [0, 1]\n", kTargets));
  EXPECT_NE(list.find("knobs[0].key: "), std::string::npos) << list;
  EXPECT_NE(list.find("moment_Nm[0]"), std::string::npos) << list;
}

TEST(TuningStudy, RefusesARangeWhoseMinIsNotBelowItsMax) {
  const std::string m = refusal(study("  - key: lowering_m\n    range: [0.05, 0.05]\n", kTargets));
  EXPECT_TRUE(std::regex_search(
      m, std::regex(R"(study\.yaml:6: knobs\[0\]\.range: expected min < max \(got 0\.05 >= 0\.05\))")))
      << m;
}

TEST(TuningStudy, RefusesARangeTheKneeModelOrTheLegCannotTake) {
  const std::string stop =
      refusal(study("  - key: hyperextension_stop.restitution\n    range: [0.2, 1.5]\n", kTargets));
  EXPECT_NE(stop.find("knobs[0].range: every value of the range must be usable; at 1.5"), std::string::npos) << stop;
  const std::string leg = refusal(study("  - key: lowering_m\n    range: [0, 0.9]\n", kTargets));
  EXPECT_NE(leg.find("knobs[0].range: every value of the range must be usable; at 0.9"), std::string::npos) << leg;
  const std::string log = refusal(study("  - key: lowering_m\n    range: [0, 0.05]\n    log_scale: true\n", kTargets));
  EXPECT_NE(log.find("knobs[0].log_scale: a log-scaled knob needs a range above 0"), std::string::npos) << log;
}

TEST(TuningStudy, AKnobsResolutionIsStatedOrToldByItsUnitElseRefused) {
  const std::string m = refusal(study("  - key: hyperextension_stop.restitution\n    range: [0.2, 0.9]\n", kTargets));
  EXPECT_NE(m.find("knobs[0].resolution: the unit of hyperextension_stop.restitution cannot be told from its key"),
            std::string::npos)
      << m;
  const std::string wide = refusal(study("  - key: lowering_m\n    range: [0, 0.05]\n    resolution: 0.1\n", kTargets));
  EXPECT_NE(wide.find("knobs[0].resolution: expected a step no larger than the range (0.05) (got 0.1)"),
            std::string::npos)
      << wide;
  const TuningStudy stated = loadTuningStudy(writeTemp(
      "study.yaml", study("  - key: hyperextension_stop.restitution\n    range: [0.2, 0.9]\n    resolution: 0.05\n"
                          "  - key: lowering_m\n    range: [0, 0.05]\n",
                          kTargets)));
  EXPECT_DOUBLE_EQ(stated.knobs[0].resolution, 0.05);
  EXPECT_DOUBLE_EQ(stated.knobs[1].resolution, 0.001);  // 1 mm, by the unit
}

TEST(TuningStudy, RefusesAnUnknownTargetAndAHardLimitWithAWeight) {
  const std::string m = refusal(study(kKnobs, "  stance_time_s: {value: 0.5}\n"));
  EXPECT_TRUE(std::regex_search(m, std::regex(R"(study\.yaml:8: targets\.stance_time_s: unknown key)"))) << m;
  const std::string w = refusal(study(kKnobs, "  peak_knee_flexion_deg: {min: 50, max: 70, hard: true, weight: 2}\n"));
  EXPECT_NE(w.find("targets.peak_knee_flexion_deg.weight: a hard limit has no weight"), std::string::npos) << w;
  const std::string win = refusal(study(kKnobs, "  peak_knee_flexion_deg: {min: 70, max: 50}\n"));
  EXPECT_NE(win.find("targets.peak_knee_flexion_deg.max: expected min < max (got 70 >= 50)"), std::string::npos) << win;
}

TEST(TuningStudy, RefusesSoundLimbWhenTheParticipantHasNoSoundLimbSwingTime) {
  // P1 without its sound-limb key, its knee model named by an absolute path.
  std::ifstream in(kRoot + "/participants/p1.yaml");
  std::string text, line;
  while (std::getline(in, line)) {
    if (line.rfind("sound_limb_swing_time_s", 0) == 0) continue;
    if (line.rfind("knee_model:", 0) == 0) line = "knee_model: " + kRoot + "/models/damping-table-default.yaml";
    text += line + "\n";
  }
  const std::string participant = writeTemp("no-sound-limb.yaml", text);
  const std::string m = refusal(study(kKnobs, kTargets, participant));
  EXPECT_TRUE(std::regex_search(
      m,
      std::regex(
          R"(study\.yaml:8: targets\.swing_time_s\.value: sound_limb needs the participant's sound_limb_swing_time_s, which .*no-sound-limb\.yaml does not give)")))
      << m;
  EXPECT_EQ(refusal(study(kKnobs, "  swing_time_s: {value: 0.5}\n", participant)), "");  // a number needs no key
}

TEST(TuningStudy, RefusesAKnobGivenTwice) {
  const std::string m = refusal(study(kKnobs + kKnobs, kTargets));
  EXPECT_NE(m.find("knobs[1].key: this knob appears twice (got lowering_m)"), std::string::npos) << m;
}

// Issue 57: a fixed lowering beside a lowering knob was dropped without a word.
TEST(TuningStudy, RefusesAFixedLoweringBesideALoweringKnob) {
  const std::string m = refusal(study(kKnobs, kTargets) + "lowering_m: 0.02\n");
  EXPECT_NE(m.find("knobs[0].key: a lowering knob or a fixed lowering_m, not both"), std::string::npos) << m;
}

// `uncertainty: {samples, seed}` asks for the chance of meeting the hard limits (as a sweep
// study's uncertainty map): read, and a bad count or an unknown key refused at its line.
TEST(TuningStudy, UncertaintyAsksForTheChanceOfMeetingTheLimits) {
  const TuningStudy plain = loadTuningStudy(writeTemp("study.yaml", study(kKnobs, kTargets)));
  EXPECT_EQ(plain.chance.samples, 0);
  const TuningStudy asked =
      loadTuningStudy(writeTemp("study.yaml", study(kKnobs, kTargets) + "uncertainty: {samples: 50, seed: 3}\n"));
  EXPECT_EQ(asked.chance.samples, 50);
  EXPECT_EQ(asked.chance.seed, 3u);
  const std::string zero = refusal(study(kKnobs, kTargets) + "uncertainty: {samples: 0}\n");
  EXPECT_TRUE(std::regex_search(
      zero, std::regex(R"(study\.yaml:9: uncertainty\.samples: expected a whole number of samples from 1)")))
      << zero;
  const std::string typo = refusal(study(kKnobs, kTargets) + "uncertainty: {sample: 50}\n");
  EXPECT_NE(typo.find("uncertainty"), std::string::npos) << typo;
  EXPECT_NE(typo.find("sample"), std::string::npos) << typo;
}

}  // namespace
}  // namespace swingsim
