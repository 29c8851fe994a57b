#include "study/diagnosis_study.h"

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "io/yaml_reader.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;

DiagnosisStudy parse(const std::string& text, const std::string& path) {
  YamlMap yaml = YamlMap::loadString(text, path);
  DiagnosisStudy s = readDiagnosisStudy(yaml);
  yaml.finish();
  return s;
}

// Round trip: both demo studies and one with every optional key load -> write -> load to
// the same study, and writing again gives the same text.
TEST(DiagnosisStudyFormat, LoadWriteLoadGivesTheSameStudy) {
  std::vector<DiagnosisStudy> studies = {loadDiagnosisStudy(kRoot + "/studies/diagnose-demo-cylinder.yaml"),
                                         loadDiagnosisStudy(kRoot + "/studies/diagnose-demo-swing.yaml")};
  DiagnosisStudy custom = studies.front();
  custom.description = "every optional key";
  custom.settings.candidates = {"inertia", "switch_delay"};
  custom.settings.alpha = 0.05;
  custom.settings.maxEffects = 2;
  custom.settings.measurementNoise = 25;
  custom.settings.explainedNoiseRatio = 1.5;
  custom.fitSwitches = true;
  custom.plotSeconds = 1.25;
  studies.push_back(custom);
  const std::string dir = kRoot + "/studies";
  for (const DiagnosisStudy& s : studies) {
    const std::string text = formatDiagnosisStudyYaml(s, dir);
    const DiagnosisStudy back = parse(text, dir + "/roundtrip.yaml");
    EXPECT_EQ(formatDiagnosisStudyYaml(back, dir), text) << s.name;
    EXPECT_EQ(back.plant, s.plant);
    EXPECT_EQ(back.name, s.name);
    EXPECT_EQ(back.train, s.train);
    EXPECT_EQ(back.validate, s.validate);
    EXPECT_EQ(back.baseModelPath, s.baseModelPath);
    EXPECT_EQ(back.participantPath, s.participantPath);
    EXPECT_EQ(back.settings.candidates, s.settings.candidates);
    EXPECT_EQ(back.settings.alpha, s.settings.alpha);
    EXPECT_EQ(back.settings.maxEffects, s.settings.maxEffects);
    EXPECT_EQ(back.settings.measurementNoise, s.settings.measurementNoise);
    EXPECT_EQ(back.settings.explainedNoiseRatio, s.settings.explainedNoiseRatio);
    EXPECT_EQ(back.fitSwitches, s.fitSwitches);
    EXPECT_EQ(back.plotSeconds, s.plotSeconds);
  }
}

TEST(DiagnosisStudyFormat, UnknownCandidateNamesThePlantsEffects) {
  const std::string text = "kind: swing-diagnosis\nparticipant: ../participants/p1.yaml\n"
                           "base_model: ../models/damping-table-default.yaml\ntrain: [a.csv]\nvalidate: [b.csv]\n"
                           "candidates: [coulomb_friction]\n";
  try {
    parse(text, kRoot + "/studies/bad.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.yaml:6: candidates: unknown swing effect (known: knee_coulomb_friction"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace swingsim
