#include "study/sweep_study.h"

#include <gtest/gtest.h>

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;

// Round trip: every sweep study of the repository, and one with every optional key, load ->
// write -> load to the same study, and writing again gives the same text.
TEST(SweepStudyFormat, LoadWriteLoadGivesTheSameStudy) {
  std::vector<SweepStudy> studies;
  for (const char* f : {"/studies/burkett2004.yaml", "/studies/burkett2004-proportional-com.yaml", "/studies/burkett2004-mauch.yaml"})
    studies.push_back(loadSweepStudy(kRoot + f));
  SweepStudy custom = studies.front();
  custom.description = "every optional key";
  custom.addedMasses = {0.0, 0.5};
  custom.addedMassDistances = {0.1, 0.2};
  custom.swing.accuracy = 1e-6;
  custom.outputDir = "out/custom";
  custom.loweringStep = 0.02;
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
  }
}

}  // namespace
}  // namespace swingsim
