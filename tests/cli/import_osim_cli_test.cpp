// `swingsim import-osim`: the file it writes is a participant `simulate` runs as it is; bad
// input writes nothing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "io/participant_loader.h"
#include "io/parts_catalogue_loader.h"
#include "run_swingsim.h"

namespace swingsim::testing {
namespace {

using ::testing::HasSubstr;

const std::string kModel =
    std::string(SWINGSIM_SOURCE_DIR) + "/studies/data/opensim-subject01/gait2354_subject01_simbody.osim";

TEST(ImportOsimCli, WritesAParticipantThatSimulateRuns) {
  const auto dir = freshTempDir("ImportOsimCli", "runs");
  const auto yaml = dir / "subject01.yaml";
  const CliRun imported =
      runSwingsim("import-osim " + kModel + " --side r --name subject01 --shank-mass-kg 1.2 --foot-mass-kg 0.9 --out " +
                  yaml.string());
  ASSERT_EQ(imported.code, 0) << imported.output;
  const std::string text = slurp(yaml);
  EXPECT_THAT(text, HasSubstr("name: subject01"));
  EXPECT_THAT(text, HasSubstr("hip_offset_in_pelvis_m: [-0.0724376, -0.0677245]"));
  EXPECT_THAT(text, HasSubstr("# shank mass: --shank-mass-kg"));
  EXPECT_THAT(text, HasSubstr("taken at full extension, knee angle 0"));
  const CliRun swing = runSwingsim("simulate " + yaml.string() + " --out " + (dir / "out").string());
  ASSERT_EQ(swing.code, 0) << swing.output;
  EXPECT_THAT(swing.output, HasSubstr("swing time"));
}

TEST(ImportOsimCli, PrintsToStdoutWithoutOut) {
  const CliRun run = runSwingsim("import-osim " + kModel + " --side l");
  ASSERT_EQ(run.code, 0) << run.output;
  EXPECT_THAT(run.output, HasSubstr("name: subject01_l"));
  EXPECT_THAT(run.output, HasSubstr("segments:"));
}

TEST(ImportOsimCli, BadSideIsAUsageErrorAndBadModelWritesNothing) {
  const auto dir = freshTempDir("ImportOsimCli", "bad");
  const CliRun side = runSwingsim("import-osim " + kModel + " --side x --out " + (dir / "x.yaml").string());
  EXPECT_EQ(side.code, 2) << side.output;
  EXPECT_THAT(side.output, HasSubstr("--side"));
  const std::string notXml = writeSuiteTempFile("ImportOsimCli", "not-xml.osim", "name: not an osim\n");
  const CliRun bad = runSwingsim("import-osim " + notXml + " --out " + (dir / "p.yaml").string());
  EXPECT_EQ(bad.code, 1) << bad.output;
  EXPECT_THAT(bad.output, HasSubstr("not-xml.osim:"));
  EXPECT_FALSE(std::filesystem::exists(dir / "x.yaml"));
  EXPECT_FALSE(std::filesystem::exists(dir / "p.yaml"));
}

TEST(ImportOsimCli, CataloguePartsGiveTheShankAndFootTheirMasses) {
  const auto dir = freshTempDir("ImportOsimCli", "parts");
  const auto yaml = dir / "subject01-osl.yaml";
  const CliRun imported = runSwingsim("import-osim " + kModel +
                                      " --knee-part osl-knee --pylon-part osl-tibial-pylon --foot-part "
                                      "proteor-kinterra-26 --out " +
                                      yaml.string());
  ASSERT_EQ(imported.code, 0) << imported.output;
  const Participant p = loadParticipant(yaml.string());
  const PartsCatalogue c = loadPartsCatalogue(defaultPartsCataloguePath());
  const ProsthesisPart &knee = *c.find("osl-knee"), &pylon = *c.find("osl-tibial-pylon");
  EXPECT_NEAR(p.shank.mass, knee.mass + pylon.mass * (p.shank.length - knee.length) / pylon.length, 1e-9);
  EXPECT_DOUBLE_EQ(p.foot.mass, c.find("proteor-kinterra-26")->mass);
  EXPECT_THAT(slurp(yaml), HasSubstr("# prosthesis_parts: knee osl-knee, pylon osl-tibial-pylon"));
  const CliRun swing = runSwingsim("simulate " + yaml.string() + " --out " + (dir / "out").string());
  ASSERT_EQ(swing.code, 0) << swing.output;
  EXPECT_THAT(swing.output, HasSubstr("swing time"));
}

TEST(ImportOsimCli, AnUnknownPartOrAMassGivenTwiceWritesNothing) {
  const auto dir = freshTempDir("ImportOsimCli", "bad-parts");
  const CliRun unknown = runSwingsim("import-osim " + kModel + " --knee-part c-leg --out " + (dir / "a.yaml").string());
  EXPECT_EQ(unknown.code, 1) << unknown.output;
  EXPECT_THAT(unknown.output, HasSubstr("--knee-part: expected a knee"));
  EXPECT_THAT(unknown.output, HasSubstr("osl-knee"));
  const CliRun twice = runSwingsim("import-osim " + kModel + " --foot-part osl-foot --foot-mass-kg 0.9 --out " +
                                   (dir / "b.yaml").string());
  EXPECT_EQ(twice.code, 1) << twice.output;
  EXPECT_THAT(twice.output, HasSubstr("both as a mass and as catalogue parts"));
  EXPECT_FALSE(std::filesystem::exists(dir / "a.yaml"));
  EXPECT_FALSE(std::filesystem::exists(dir / "b.yaml"));
}

TEST(PartsCli, ListsTheShippedCatalogueByCategory) {
  const CliRun all = runSwingsim("parts");
  ASSERT_EQ(all.code, 0) << all.output;
  EXPECT_THAT(all.output, HasSubstr("osl-knee"));
  EXPECT_THAT(all.output, HasSubstr("source: MyoHub/myo_sim"));
  const CliRun feet = runSwingsim("parts --category foot");
  ASSERT_EQ(feet.code, 0) << feet.output;
  EXPECT_THAT(feet.output, HasSubstr("proteor-kinterra-26"));
  EXPECT_THAT(feet.output, ::testing::Not(HasSubstr("osl-knee")));
  EXPECT_EQ(runSwingsim("parts --category hand").code, 2);
}

}  // namespace
}  // namespace swingsim::testing
