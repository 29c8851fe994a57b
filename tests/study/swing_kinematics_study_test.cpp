#include "study/swing_kinematics_study.h"

#include <gtest/gtest.h>

#include <string>

#include "core/input_error.h"
#include "core/units.h"
#include "io/yaml_reader.h"

namespace swingsim {
namespace {

SwingKinematicsStudy parse(const std::string& text, const std::string& path) {
  YamlMap yaml = YamlMap::loadString(text, path);
  return readSwingKinematicsStudy(yaml);
}

TEST(SwingKinematicsStudy, ShippedStudyRoundTripsThroughTheWriter) {
  YamlMap yaml = YamlMap::loadFile("studies/diagnose-demo-swing-data.yaml");
  const SwingKinematicsStudy study = readSwingKinematicsStudy(yaml);
  EXPECT_EQ(study.noiseDeg, 0.5);
  EXPECT_EQ(study.seed, 707u);
  ASSERT_EQ(study.conditions.size(), 3u);
  ASSERT_TRUE(study.hasHiddenEffects);
  EXPECT_TRUE(study.hidden.has("extension_assist_spring"));
  EXPECT_EQ(study.hidden.value("extension_assist_spring", "stiffness_Nm_per_rad"), 0.8);

  const SwingKinematicsStudy back = parse(formatSwingKinematicsStudyYaml(study, "studies"), "studies/written.yaml");
  EXPECT_EQ(back.participantPath.substr(back.participantPath.rfind('/')), "/p1.yaml");
  EXPECT_EQ(back.base.participant.name, study.base.participant.name);
  EXPECT_EQ(back.noiseDeg, study.noiseDeg);
  EXPECT_EQ(back.seed, study.seed);
  EXPECT_EQ(back.sampleInterval, study.sampleInterval);
  ASSERT_EQ(back.conditions.size(), study.conditions.size());
  for (std::size_t i = 0; i < back.conditions.size(); ++i) {
    EXPECT_EQ(back.conditions[i].name, study.conditions[i].name);
    EXPECT_EQ(back.conditions[i].timeScale, study.conditions[i].timeScale);
    EXPECT_EQ(back.conditions[i].amplitudeScale, study.conditions[i].amplitudeScale);
  }
  EXPECT_TRUE(back.hidden.has("extension_assist_spring"));
  EXPECT_FALSE(back.hidden.has("knee_coulomb_friction"));
  EXPECT_EQ(back.hidden.value("extension_assist_spring", "stiffness_Nm_per_rad"), 0.8);
}

TEST(SwingKinematicsStudy, HiddenEffectsBuildTheTruthInFormatOrder) {
  const std::string text = R"(kind: swing-kinematics
participant: ../participants/p1.yaml
model: ../models/damping-table-default.yaml
noise_deg: 0
output_dir: out
conditions: [{name: normal}]
hidden_effects:
  hip_moment_scale: {scale: 1.2}
  knee_coulomb_friction: {moment_Nm: 3}
  toe_off_velocity: {hip_rate_deg_s: 90, knee_rate_deg_s: -45}
)";
  const SwingKinematicsStudy study = parse(text, "studies/inline.yaml");
  // The smoothing rate, absent, takes the grid's middle value: 1 rad/s (57.3 deg/s in the file).
  EXPECT_DOUBLE_EQ(study.hidden.value("knee_coulomb_friction", "smoothing_deg_s"), 1.0 * kRadToDeg);
  EXPECT_EQ(study.hidden.value("toe_off_velocity", "knee_rate_deg_s"), -45);
  std::vector<std::string> names;
  const SwingModelParams truth = makeHiddenTruth(study.hidden, names);
  EXPECT_EQ(names, (std::vector<std::string>{"knee_coulomb_friction", "toe_off_velocity", "hip_moment_scale"}));
  EXPECT_EQ(truth.effects.knee.coulombMoment, 3.0);
  EXPECT_EQ(truth.effects.hipMomentScale, 1.2);
  EXPECT_DOUBLE_EQ(truth.effects.toeOffHipRate, 90 * kDegToRad);
  EXPECT_DOUBLE_EQ(truth.effects.knee.coulombSmoothingRate, 1.0);
}

TEST(SwingKinematicsStudy, EmptyConditionsAreRefused) {
  const std::string text = R"(kind: swing-kinematics
participant: ../participants/p1.yaml
model: ../models/damping-table-default.yaml
noise_deg: 0
output_dir: out
conditions: []
)";
  try {
    parse(text, "studies/empty.yaml");
    FAIL() << "an empty condition list was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "studies/empty.yaml:6: conditions: expected at least one condition (got an empty list)");
  }
}

// Generator inputs outside their plausible range (core/plausible_ranges.h) are refused at
// load: absurd noise once gave rc 0 and files that crashed `fit`. A hidden effect's values
// are checked against its record's physical bounds (a toe-off rate within 20 rad/s).
TEST(SwingKinematicsStudy, NoiseAndRatesOutsideTheirPlausibleRangeAreRefused) {
  const auto errorOf = [](const std::string& noise, const std::string& rate) {
    const std::string text =
        "kind: swing-kinematics\nparticipant: ../participants/p1.yaml\n"
        "model: ../models/damping-table-default.yaml\nnoise_deg: " +
        noise +
        "\noutput_dir: out\nconditions: [{name: normal}]\nhidden_effects:\n"
        "  toe_off_velocity: {hip_rate_deg_s: 90, knee_rate_deg_s: " +
        rate + "}\n";
    try {
      parse(text, "studies/inline.yaml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(errorOf("0.5", "-45"), "");
  EXPECT_EQ(errorOf("1e300", "-45")
                .rfind("studies/inline.yaml:4: noise_deg: expected an angle noise in [0, 10] deg "
                       "(motion capture angles are good to about 1 deg)",
                       0),
            0u)
      << errorOf("1e300", "-45");
  EXPECT_EQ(errorOf("0.5", "1e9")
                .rfind("studies/inline.yaml:8: hidden_effects.toe_off_velocity.knee_rate_deg_s: expected "
                       "a value within the effect's physical bounds [-1146, 1146]",
                       0),
            0u)
      << errorOf("0.5", "1e9");
}

}  // namespace
}  // namespace swingsim
