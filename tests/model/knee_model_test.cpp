// A knee model's law (model/knee_model.h): the resisting law, the added effects when the file
// has them (the resisting law scaled first), and the hyperextension stop last.
#include "model/knee_model.h"

#include <gtest/gtest.h>

#include <string>

#include "io/knee_model_loader.h"

namespace swingsim {
namespace {

constexpr double kRoundOff = 1e-12;

// The shipped damping table as its file gives it (a default spec has no table).
KneeModelSpec dampingTable() { return loadKneeModel("models/damping-table-default.yaml").spec; }

TEST(KneeModel, LawIsTheResistingLawThenTheStop) {
  const KneeLawSum law = makeKneeModelLaw(dampingTable());
  ASSERT_EQ(law.size(), 2u);
  EXPECT_EQ(law.part(1).name(), "hyperextension stop");
  const KneeModelSpec mauch = loadKneeModel("models/mauch-2phase.yaml").spec;
  const KneeLawSum cylinder = makeKneeModelLaw(mauch);
  ASSERT_EQ(cylinder.size(), 2u);
  EXPECT_NE(cylinder.part(0).name(), law.part(0).name()) << "the cylinder, not the damping table";
  EXPECT_EQ(cylinder.numStates(), cylinder.part(0).numStates()) << "the cylinder's latch states, nothing else";
}

TEST(KneeModel, AddedEffectsComeBeforeTheStopWithTheResistingLawScaled) {
  KneeModelSpec spec = dampingTable();
  spec.hasKneeEffects = true;
  spec.kneeEffects.viscousDamping = 0.2;
  spec.kneeEffects.modelScale = 1.5;
  const KneeLawSum plain = makeKneeModelLaw(dampingTable());
  const KneeLawSum law = makeKneeModelLaw(spec);
  ASSERT_EQ(law.size(), 3u);
  EXPECT_EQ(law.part(1).name(), "added knee effects");
  EXPECT_EQ(law.part(2).name(), "hyperextension stop");
  EXPECT_EQ(law.part(0).name(), plain.part(0).name()) << "scaled, still named as the model";
  for (const KneeKinematics k : {KneeKinematics{0.6, 4.0}, KneeKinematics{1.0, -2.0}}) {
    EXPECT_NEAR(law.calcPartMoment(0, k, nullptr), 1.5 * plain.calcPartMoment(0, k, nullptr), kRoundOff);
    EXPECT_NEAR(law.calcPartMoment(1, k, nullptr), -0.2 * k.flexionRate, kRoundOff);
  }
  spec.kneeEffects.modelScale = 1.0;
  const KneeLawSum unscaled = makeKneeModelLaw(spec);
  EXPECT_NEAR(unscaled.calcPartMoment(0, {0.6, 4.0}, nullptr), plain.calcPartMoment(0, {0.6, 4.0}, nullptr), 0.0);
}

}  // namespace
}  // namespace swingsim
