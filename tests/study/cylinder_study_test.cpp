#include "study/cylinder_study.h"

#include <gtest/gtest.h>

#include <string>

#include "core/input_error.h"
#include "io/yaml_reader.h"

namespace swingsim {
namespace {

CylinderBenchStudy parseBench(const std::string& text, const std::string& path) {
  YamlMap yaml = YamlMap::loadString(text, path);
  CylinderBenchStudy s = readCylinderBenchStudy(yaml);
  yaml.finish();
  return s;
}

CylinderFitStudy parseFit(const std::string& text, const std::string& path) {
  YamlMap yaml = YamlMap::loadString(text, path);
  CylinderFitStudy s = readCylinderFitStudy(yaml);
  yaml.finish();
  return s;
}

CylinderBenchStudy loadBench(const std::string& path) {
  YamlMap yaml = YamlMap::loadFile(path);
  CylinderBenchStudy s = readCylinderBenchStudy(yaml);
  yaml.finish();
  return s;
}

void expectSameBench(const CylinderBenchStudy& a, const CylinderBenchStudy& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(a.modelPath, b.modelPath);
  EXPECT_EQ(a.kneeAnglesPath, b.kneeAnglesPath);
  EXPECT_EQ(a.strideFirstFrame, b.strideFirstFrame);
  EXPECT_EQ(a.strideLastFrame, b.strideLastFrame);
  EXPECT_EQ(a.profile.sampleRate, b.profile.sampleRate);
  EXPECT_EQ(a.profile.cycles, b.profile.cycles);
  EXPECT_EQ(a.profile.terminalSwingMinimum, b.profile.terminalSwingMinimum);
  EXPECT_EQ(a.profile.hyperextension, b.profile.hyperextension);
  EXPECT_EQ(a.profile.holdSamples, b.profile.holdSamples);
  EXPECT_EQ(a.noise, b.noise);
  EXPECT_EQ(a.seed, b.seed);
  EXPECT_EQ(a.outputDir, b.outputDir);
  ASSERT_EQ(a.conditions.size(), b.conditions.size());
  for (std::size_t i = 0; i < a.conditions.size(); ++i) {
    EXPECT_EQ(a.conditions[i].name, b.conditions[i].name);
    EXPECT_EQ(a.conditions[i].strideTime, b.conditions[i].strideTime);
    EXPECT_EQ(a.conditions[i].amplitudeScale, b.conditions[i].amplitudeScale);
  }
  EXPECT_EQ(a.hiddenLatchTimeConstant, b.hiddenLatchTimeConstant);
  EXPECT_EQ(a.hiddenEffects.orificeQuadratic, b.hiddenEffects.orificeQuadratic);
  EXPECT_EQ(a.hiddenEffects.orificeCoefficient, b.hiddenEffects.orificeCoefficient);
  EXPECT_EQ(a.hiddenEffects.coulombFriction, b.hiddenEffects.coulombFriction);
  EXPECT_EQ(a.hiddenEffects.coulombForce, b.hiddenEffects.coulombForce);
}

TEST(CylinderStudy, BenchStudiesRoundTripThroughTheWriter) {
  // The shipped studies (one with a hidden effect), written beside themselves and read back.
  for (const char* path : {"studies/mauch2014-bench.yaml", "studies/diagnose-demo-cylinder-bench.yaml"}) {
    SCOPED_TRACE(path);
    const CylinderBenchStudy study = loadBench(path);
    const std::string text = formatCylinderBenchStudyYaml(study, "studies");
    expectSameBench(parseBench(text, "studies/written.yaml"), study);
  }
}

TEST(CylinderStudy, HiddenSwitchDelayAndFrictionRoundTrip) {
  const std::string text = R"(kind: cylinder-bench
model: ../models/mauch-4phase.yaml
knee_angles: data/winter-natural-cadence.csv
output_dir: out
conditions:
  - {name: normal, stride_s: 0.987}
hidden_effects:
  switch_delay: {time_constant_s: 0.1}
  coulomb_friction: {force_N: 40, width_m_per_s: 0.002}
)";
  const CylinderBenchStudy study = parseBench(text, "studies/inline.yaml");
  EXPECT_EQ(study.name, "inline");  // the file stem when no name is given
  EXPECT_EQ(study.hiddenLatchTimeConstant, 0.1);
  EXPECT_TRUE(study.hiddenEffects.coulombFriction);
  EXPECT_EQ(study.hiddenEffects.coulombWidth, 0.002);
  const CylinderBenchStudy back = parseBench(formatCylinderBenchStudyYaml(study, "studies"), "studies/inline.yaml");
  expectSameBench(back, study);
  EXPECT_EQ(back.hiddenEffects.coulombWidth, 0.002);
}

TEST(CylinderStudy, FitStudyRoundTrips) {
  YamlMap yaml = YamlMap::loadFile("studies/mauch2014.yaml");
  const CylinderFitStudy study = readCylinderFitStudy(yaml);
  yaml.finish();
  ASSERT_EQ(study.models.size(), 2u);
  const CylinderFitStudy back = parseFit(formatCylinderFitStudyYaml(study, "studies"), "studies/written.yaml");
  EXPECT_EQ(back.name, study.name);
  EXPECT_EQ(back.models, study.models);
  EXPECT_EQ(back.train, study.train);
  EXPECT_EQ(back.validate, study.validate);
  EXPECT_EQ(back.fitSwitches, study.fitSwitches);
  EXPECT_EQ(back.plotSeconds, study.plotSeconds);
}

TEST(CylinderStudy, RepeatedConditionNameIsRefused) {
  const std::string text = R"(kind: cylinder-bench
model: m.yaml
knee_angles: k.csv
output_dir: out
conditions:
  - {name: normal, stride_s: 0.987}
  - {name: normal, stride_s: 1.0}
)";
  try {
    parseBench(text, "dup.yaml");
    FAIL() << "a repeated condition name was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "dup.yaml:7: conditions[1].name: condition name appears twice (got normal)");
  }
}

}  // namespace
}  // namespace swingsim
