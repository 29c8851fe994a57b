#include "identify/effect_table.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace swingsim {
namespace {

TEST(EffectTable, EveryIdHasOneDescriptorAndNamesAreUniquePerPlant) {
  std::set<std::pair<PlantKind, std::string>> names;
  for (const auto& e : effectTable()) {
    EXPECT_EQ(&describeEffect(e.id), &e) << e.name << ": its id finds another row";
    EXPECT_TRUE(names.insert({e.plant, e.name}).second) << e.name << " appears twice";
  }
  EXPECT_EQ(effectTable().size(), static_cast<std::size_t>(EffectId::kThighTargetFlexion) + 1);
}

TEST(EffectTable, DescriptorsAreConsistent) {
  for (const auto& e : effectTable()) {
    SCOPED_TRACE(e.name);
    EXPECT_FALSE(e.sentence.empty());
    EXPECT_FALSE(e.mechanism.empty());
    EXPECT_FALSE(e.separatedBy.empty());
    // The reported parameters: the fitted ones, then one for the grid if there is one.
    EXPECT_EQ(e.parameters.size(), static_cast<std::size_t>(e.fittedParameters) + (e.grid.empty() ? 0 : 1));
    EXPECT_EQ(e.degreesOfFreedom(), static_cast<int>(e.parameters.size()));
    for (double g : e.grid) EXPECT_GT(g, 0.0);
    // Only the swing's effects live in the participant; the sweep's are shared by all.
    if (e.participantLevel) {
      EXPECT_EQ(e.plant, PlantKind::kSwing);
    }
    if (e.plant == PlantKind::kSweep) {
      EXPECT_FALSE(e.participantLevel);
    }
  }
}

TEST(EffectTable, FindsByPlantAndName) {
  const EffectDescriptor* c = findEffect(PlantKind::kCylinder, "coulomb_friction");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->id, EffectId::kCoulombFriction);
  // The swing's friction has its own name; the cylinder's is not the swing's.
  EXPECT_EQ(findEffect(PlantKind::kSwing, "coulomb_friction"), nullptr);
  ASSERT_NE(findEffect(PlantKind::kSwing, "knee_coulomb_friction"), nullptr);
  EXPECT_EQ(findEffect(PlantKind::kSwing, "no_such_effect"), nullptr);
}

TEST(EffectTable, NamesPerPlantInTableOrder) {
  const auto swing = effectNames(PlantKind::kSwing);
  ASSERT_EQ(swing.size(), 8u);
  EXPECT_EQ(swing.front(), "knee_coulomb_friction");
  EXPECT_EQ(swing.back(), "socket_compliance");
  const auto cylinder = effectNames(PlantKind::kCylinder);
  ASSERT_EQ(cylinder.size(), 6u);
  EXPECT_EQ(cylinder.front(), "coulomb_friction");
  EXPECT_EQ(plantName(PlantKind::kCylinder), "cylinder");
  EXPECT_EQ(plantName(PlantKind::kSwing), "swing");
  const auto sweep = effectNames(PlantKind::kSweep);
  ASSERT_EQ(sweep.size(), 10u);
  EXPECT_EQ(sweep.front(), "hip_effort_adaptation");
  EXPECT_EQ(sweep.back(), "thigh_target_flexion");
  EXPECT_EQ(plantName(PlantKind::kSweep), "sweep");
}

}  // namespace
}  // namespace swingsim
