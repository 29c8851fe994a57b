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
  EXPECT_TRUE(study.hidden.extensionAssistSpring);
  EXPECT_EQ(study.hidden.assistStiffness, 0.8);

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
  EXPECT_TRUE(back.hidden.extensionAssistSpring);
  EXPECT_FALSE(back.hidden.kneeCoulombFriction);
  EXPECT_EQ(back.hidden.assistStiffness, 0.8);
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
  // The smoothing rate's default is 1 rad/s (57.3 deg/s in the file).
  EXPECT_EQ(study.hidden.coulombSmoothingRate, 1.0);
  EXPECT_EQ(study.hidden.toeOffKneeRate, -45 * kDegToRad);
  std::vector<std::string> names;
  const SwingModelParams truth = makeHiddenTruth(study.hidden, names);
  EXPECT_EQ(names, (std::vector<std::string>{"knee_coulomb_friction", "toe_off_velocity", "hip_moment_scale"}));
  EXPECT_EQ(truth.effects.knee.coulombMoment, 3.0);
  EXPECT_EQ(truth.effects.hipMomentScale, 1.2);
  EXPECT_EQ(truth.effects.toeOffHipRate, 90 * kDegToRad);
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
    EXPECT_EQ(std::string(e.what()), "studies/empty.yaml:6: conditions: expected at least one condition (got an empty list)");
  }
}

// Generator inputs outside their plausible range (core/plausible_ranges.h) are refused at
// load: absurd noise once gave rc 0 and files that crashed `fit`.
TEST(SwingKinematicsStudy, NoiseAndRatesOutsideTheirPlausibleRangeAreRefused) {
  const auto errorOf = [](const std::string& noise, const std::string& rate) {
    const std::string text = "kind: swing-kinematics\nparticipant: ../participants/p1.yaml\n"
                             "model: ../models/damping-table-default.yaml\nnoise_deg: " + noise +
                             "\noutput_dir: out\nconditions: [{name: normal}]\nhidden_effects:\n"
                             "  toe_off_velocity: {hip_rate_deg_s: 90, knee_rate_deg_s: " + rate + "}\n";
    try {
      parse(text, "studies/inline.yaml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(errorOf("0.5", "-45"), "");
  EXPECT_EQ(errorOf("1e300", "-45").rfind("studies/inline.yaml:4: noise_deg: expected an angle noise in [0, 10] deg "
                                          "(motion capture angles are good to about 1 deg)", 0), 0u)
      << errorOf("1e300", "-45");
  EXPECT_EQ(errorOf("0.5", "1e9").rfind("studies/inline.yaml:8: hidden_effects.toe_off_velocity.knee_rate_deg_s: expected "
                                        "a knee rate in [-3000, 3000] deg/s", 0), 0u)
      << errorOf("0.5", "1e9");
}

}  // namespace
}  // namespace swingsim
