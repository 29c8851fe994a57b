// What a user's effect is on either plant (identify/user_effect.h).
#include "identify/user_effect.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace swingsim {
namespace {

UserEffect damper() { return {"test_user_damper", "-c * knee_rate_rad_s", {{"c", "N m s/rad", 0.0, 20.0, 2.0}}}; }

TEST(UserEffect, ItsStartLawCarriesTheStartValuesAndUnits) {
  const KneeExpressionParams law = damper().startLaw();
  EXPECT_EQ(law.name, "test_user_damper");
  ASSERT_EQ(law.parameters.size(), 1u);
  EXPECT_EQ(law.parameters[0].unit, "N m s/rad");
  EXPECT_EQ(law.parameters[0].value, 2.0);
}

TEST(UserEffect, ChecksTheNameAndTheBoundsForItsPlant) {
  EXPECT_NO_THROW(checkUserEffect(damper(), PlantKind::kSwing));
  UserEffect e = damper();
  e.name = "knee_viscous_damping";
  EXPECT_THROW(checkUserEffect(e, PlantKind::kSwing), std::invalid_argument);
  EXPECT_NO_THROW(checkUserEffect(e, PlantKind::kCylinder));  // not a cylinder effect's name
  e = damper();
  e.parameters[0].min = 30;
  EXPECT_THROW(checkUserEffect(e, PlantKind::kSwing), std::invalid_argument);
  e = damper();
  e.parameters[0].start = -1;
  EXPECT_THROW(checkUserEffect(e, PlantKind::kSwing), std::invalid_argument);
  e = damper();
  e.parameters.clear();
  EXPECT_THROW(checkUserEffect(e, PlantKind::kSwing), std::invalid_argument);
}

TEST(UserEffect, ItsDescriptorAndBoundsComeFromTheStudy) {
  const EffectDescriptor d = describeUserEffect(damper(), PlantKind::kCylinder, "thing (N)");
  EXPECT_EQ(d.plant, PlantKind::kCylinder);
  EXPECT_EQ(d.sentence, "a user's thing (N): -c * knee_rate_rad_s");
  EXPECT_EQ(d.fittedParameters, 1);
  EXPECT_EQ(d.parameters, std::vector<std::string>{"c (N m s/rad)"});
  const BoundedParameter b = userEffectBound(damper(), 0);
  EXPECT_EQ(b.start, 2.0);
  EXPECT_EQ(b.lower, 0.0);
  EXPECT_EQ(b.upper, 20.0);
  EXPECT_DOUBLE_EQ(b.typical, 2.0);  // a tenth of the largest of |start|, |min|, |max|
  EXPECT_THROW(userEffectBound(damper(), 1), std::out_of_range);
}

TEST(UserEffect, TheRegistryKeepsOneRecordPerId) {
  UserRecordRegistry<int> r;
  const auto id = static_cast<EffectId>(kFirstUserEffectId + 1000);
  EXPECT_EQ(r.find(id), nullptr);
  r.add(id, [] { return 1; });
  r.add(id, [] { return 2; });  // already there: kept
  ASSERT_NE(r.find(id), nullptr);
  EXPECT_EQ(*r.find(id), 1);
}

}  // namespace
}  // namespace swingsim
