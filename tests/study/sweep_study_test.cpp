#include "study/sweep_study.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/input_error.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;

// Round trip: every sweep study of the repository, and one with every optional key, load ->
// write -> load to the same study, and writing again gives the same text.
TEST(SweepStudyFormat, LoadWriteLoadGivesTheSameStudy) {
  std::vector<SweepStudy> studies;
  for (const char* f :
       {"/studies/burkett2004.yaml", "/studies/burkett2004-proportional-com.yaml", "/studies/burkett2004-mauch.yaml"})
    studies.push_back(loadSweepStudy(kRoot + f));
  SweepStudy custom = studies.front();
  custom.description = "every optional key";
  custom.addedMasses = {0.0, 0.5};
  custom.addedMassDistances = {0.1, 0.2};
  custom.swing.accuracy = 1e-6;
  custom.outputDir = "out/custom";
  custom.loweringStep = 0.02;
  custom.uncertaintySamples = 40;
  custom.uncertaintySeed = 123;
  studies.push_back(custom);
  const std::string dir = kRoot + "/studies";
  for (const SweepStudy& s : studies) {
    const std::string text = formatSweepStudyYaml(s, dir);
    const SweepStudy back = parseSweepStudy(text, dir + "/roundtrip.yaml");
    EXPECT_EQ(formatSweepStudyYaml(back, dir), text) << s.name;
    ASSERT_EQ(back.participants.size(), s.participants.size());
    for (std::size_t i = 0; i < s.participants.size(); ++i) {
      EXPECT_EQ(back.participants[i].name, s.participants[i].name);
      EXPECT_EQ(back.participants[i].comRule, s.participants[i].comRule);
    }
    EXPECT_EQ(back.kneeModelOverride, s.kneeModelOverride);
    EXPECT_EQ(back.loweringStep, s.loweringStep);
    EXPECT_EQ(back.loweringMax, s.loweringMax);
    EXPECT_EQ(back.addedMasses, s.addedMasses);
    EXPECT_EQ(back.addedMassDistances, s.addedMassDistances);
    EXPECT_EQ(back.swing.integrator, s.swing.integrator);
    EXPECT_EQ(back.swing.accuracy, s.swing.accuracy);
    EXPECT_EQ(back.outputDir, s.outputDir);
    EXPECT_EQ(back.kneeModels.size(), s.kneeModels.size());
    EXPECT_EQ(back.uncertaintySamples, s.uncertaintySamples);
    EXPECT_EQ(back.uncertaintySeed, s.uncertaintySeed);
  }
}

// `uncertainty: {samples: N, seed: S}` (docs/uncertainty.md): read, defaults, and strict keys.
std::string studyWithUncertainty(const std::string& map) {
  return "kind: knee-axis-sweep\nname: u\nparticipants: [../participants/p1.yaml]\nuncertainty: " + map + "\n";
}

TEST(SweepStudyFormat, UncertaintyMapIsRead) {
  const std::string path = kRoot + "/studies/uncertainty-test.yaml";
  const SweepStudy s = parseSweepStudy(studyWithUncertainty("{samples: 25, seed: 9}"), path);
  EXPECT_EQ(s.uncertaintySamples, 25);
  EXPECT_EQ(s.uncertaintySeed, 9);
  const SweepStudy unseeded = parseSweepStudy(studyWithUncertainty("{samples: 3}"), path);
  EXPECT_EQ(unseeded.uncertaintySeed, 1);
  const SweepStudy none =
      parseSweepStudy("kind: knee-axis-sweep\nname: u\nparticipants: [../participants/p1.yaml]\n", path);
  EXPECT_EQ(none.uncertaintySamples, 0);
}

TEST(SweepStudyFormat, UncertaintyMapRejectsBadKeysAndValues) {
  using ::testing::HasSubstr;
  const std::string path = kRoot + "/studies/uncertainty-test.yaml";
  struct Case {
    std::string map, message;
  };
  const Case cases[] = {
      {"{samples: 10, sed: 3}", "sed: unknown key"},
      {"{samples: 10, seeds: 3}", "seeds: unknown key"},
      {"{seed: 3}", "samples"},
      {"{samples: 0}", "samples: expected a whole number of samples from 1 to 100000"},
      {"{samples: -5}", "samples: expected a whole number of samples from 1 to 100000"},
      {"{samples: 2.5}", "samples: expected an integer"},
      {"{samples: many}", "samples"},
      {"{samples: 10, seed: -1}", "seed: expected an integer in [0, 1000000000]"},
      {"{samples: 10, seed: 1000000001}", "seed: expected an integer in [0, 1000000000]"},
      {"{samples: 10, seed: 2.5}", "seed: expected an integer in [0, 1000000000]"},
      {"200", "uncertainty"},
  };
  for (const Case& c : cases) {
    try {
      parseSweepStudy(studyWithUncertainty(c.map), path);
      ADD_FAILURE() << c.map << " was accepted";
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr(c.message)) << c.map;
      EXPECT_THAT(e.what(), HasSubstr("uncertainty-test.yaml:4")) << c.map << ": no file:line";
    }
  }
}

}  // namespace
}  // namespace swingsim
