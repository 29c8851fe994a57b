// `swingsim export-osim`: the model lands beside simulate's .sto for the same participant and
// lowering, names that .sto's angle columns as its coordinates, and import-osim gives the
// lowered leg back; a bad participant writes nothing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/osim_model.h"
#include "io/participant_loader.h"
#include "model/leg_parameters.h"
#include "run_swingsim.h"

namespace swingsim::testing {
namespace {

using ::testing::HasSubstr;

const std::string kP1 = std::string(SWINGSIM_SOURCE_DIR) + "/participants/p1.yaml";
// import-osim writes numbers in full; its arithmetic adds a few ulps of 1 m.
constexpr double kRoundTrip = 1e-12;

TEST(ExportOsimCli, ModelBesideSimulatesStoPlaysItAndImportsBack) {
  const auto dir = freshTempDir("ExportOsimCli", "p1");
  const CliRun exported = runSwingsim("export-osim " + kP1 + " --lowering 0.02 --out " + dir.string());
  ASSERT_EQ(exported.code, 0) << exported.output;
  const auto osim = dir / "P1-lower020mm.osim";
  ASSERT_TRUE(std::filesystem::exists(osim)) << exported.output;
  EXPECT_THAT(exported.output, HasSubstr(osim.string()));
  const CliRun simulated = runSwingsim("simulate " + kP1 + " --lowering 0.02 --out " + dir.string());
  ASSERT_EQ(simulated.code, 0) << simulated.output;
  const std::string sto = slurp(dir / "P1-lower020mm.sto");
  ASSERT_FALSE(sto.empty());
  EXPECT_THAT(sto, HasSubstr("inDegrees=yes"));
  const std::string columns = sto.substr(sto.find("endheader\n") + 10,
                                         sto.find('\n', sto.find("endheader\n") + 10) - sto.find("endheader\n") - 10);
  const OsimModel model = loadOsimModel(osim.string());
  for (const auto& j : model.joints)
    for (const auto& c : j.coordinates) EXPECT_THAT(columns, HasSubstr("\t" + c.name + "\t")) << columns;
  EXPECT_EQ(model.getJointTo("tibia_r").coordinates.at(0).name, "knee_angle_r");
  // The knee's sign and range, said in the file.
  EXPECT_THAT(slurp(osim), HasSubstr("- = FLEXION"));

  const auto yaml = dir / "back.yaml";
  const CliRun imported = runSwingsim("import-osim " + osim.string() + " --out " + yaml.string());
  ASSERT_EQ(imported.code, 0) << imported.output;
  const Participant p1 = loadParticipant(kP1), back = loadParticipant(yaml.string());
  const LegGeometry g = calcLegGeometry(p1, 0.02), h = calcLegGeometry(back, 0);
  EXPECT_NEAR(h.thighLength, g.thighLength, kRoundTrip);
  EXPECT_NEAR(h.thighCom, g.thighCom, kRoundTrip);
  EXPECT_NEAR(h.thighMass, g.thighMass, kRoundTrip);
  EXPECT_NEAR(h.thighInertia, g.thighInertia, kRoundTrip);
  EXPECT_NEAR(h.shankLength, g.shankLength, kRoundTrip);
  EXPECT_NEAR(h.shankCom, g.shankCom, kRoundTrip);
  EXPECT_NEAR(h.shankMass, g.shankMass, kRoundTrip);
  EXPECT_NEAR(h.shankInertia, g.shankInertia, kRoundTrip);
  EXPECT_NEAR(h.footLength, g.footLength, kRoundTrip);
  EXPECT_NEAR(h.footComForward, g.footComForward, kRoundTrip);
  EXPECT_NEAR(h.footMass, g.footMass, kRoundTrip);
  EXPECT_NEAR(h.footInertia, g.footInertia, kRoundTrip);
  EXPECT_NEAR(back.bodyMass, p1.bodyMass, kRoundTrip);
}

TEST(ExportOsimCli, BadParticipantOrLoweringWritesNothing) {
  const auto dir = freshTempDir("ExportOsimCli", "bad");
  const std::string bad = writeSuiteTempFile("ExportOsimCli", "bad.yaml", "name: X\nheight_m: 1.8\nnot_a_key: 1\n");
  const CliRun run = runSwingsim("export-osim " + bad + " --out " + dir.string());
  EXPECT_EQ(run.code, 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("bad.yaml:"));
  const CliRun missing = runSwingsim("export-osim " + (dir / "none.yaml").string() + " --out " + dir.string());
  EXPECT_EQ(missing.code, 1) << missing.output;
  EXPECT_THAT(missing.output, HasSubstr("none.yaml"));
  const CliRun tooLow = runSwingsim("export-osim " + kP1 + " --lowering 0.6 --out " + dir.string());
  EXPECT_EQ(tooLow.code, 1) << tooLow.output;
  EXPECT_THAT(tooLow.output, HasSubstr("lowering"));
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace swingsim::testing
