// Knee model knobs (io/knee_model_knobs.h): a key path sets one number of the file and the
// model is reloaded through the loader, for every knee kind.
#include "io/knee_model_knobs.h"

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "core/units.h"
#include "knee/knee_law.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;
const std::string kTable = kRoot + "/models/damping-table-default.yaml";
const std::string kMauch = kRoot + "/models/mauch-4phase.yaml";

TEST(KneeModelKnobs, SetsAListItemANestedKeyAndAKeyTheFileLeftOut) {
  const KneeModelKnobs knobs(kTable);
  EXPECT_DOUBLE_EQ(knobs.fileValue("damping_table.moment_Nm[3]"), 1.3);
  const KneeModel m = knobs.make(
      {"damping_table.moment_Nm[3]", "damping_table.extension_factor", "knee_effects.model_scale"}, {2.5, 0.5, 3.0});
  const DampingTableParams& table = std::get<DampingTableKnee>(m.spec.kind).table;
  EXPECT_DOUBLE_EQ(table.moment[3], 2.5);
  EXPECT_DOUBLE_EQ(table.moment[2], 1.1);  // the others as in the file
  EXPECT_DOUBLE_EQ(table.extensionFactor, 0.5);
  EXPECT_TRUE(m.spec.hasKneeEffects);
  EXPECT_DOUBLE_EQ(m.spec.kneeEffects.modelScale, 3.0);
  EXPECT_EQ(m.path, kTable);
}

TEST(KneeModelKnobs, WorksOnTheMauchCylinderThroughItsListOfSettings) {
  const KneeModelKnobs knobs(kMauch);
  EXPECT_EQ(knobs.checkKey("settings[0].coefficients[1].c_Ns_per_m"), "");
  const KneeModel m = knobs.make({"settings[0].coefficients[1].c_Ns_per_m"}, {1500});
  EXPECT_DOUBLE_EQ(std::get<MauchKnee>(m.spec.kind).cylinder.coefficients[1].c,
                   1500);  // phase 2 of the dial setting in use
}

TEST(KneeModelKnobs, RefusesKeysThatAreNotOneNumber) {
  const KneeModelKnobs knobs(kTable);
  EXPECT_NE(knobs.checkKey("damping_table.moment_Nm").find("holds a list of 8 values"), std::string::npos);
  EXPECT_NE(knobs.checkKey("damping_table").find("holds a map"), std::string::npos);
  EXPECT_NE(knobs.checkKey("damping_table.speed_rule").find("not a number"), std::string::npos);
  EXPECT_NE(knobs.checkKey("damping_table.moment_Nm[8]").find("no item 8"), std::string::npos);
  EXPECT_NE(knobs.checkKey("damping_table.moment_Nm[x]").find("key path"), std::string::npos);
}

TEST(KneeModelKnobs, TheLoaderRefusesAnUnknownKeyAndAnImpossibleValue) {
  const KneeModelKnobs knobs(kTable);
  EXPECT_EQ(knobs.checkKey("damping_table.no_such_key"), "");  // absent: the loader decides
  try {
    knobs.make({"damping_table.no_such_key"}, {1});
    FAIL() << "an unknown key was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_key: unknown key"), std::string::npos) << e.what();
  }
  EXPECT_THROW(knobs.make({"hyperextension_stop.restitution"}, {1.5}), InputError);
  EXPECT_THROW(knobs.make({"damping_table.moment_Nm[0]"}, {-1}), InputError);
}

}  // namespace
}  // namespace swingsim
