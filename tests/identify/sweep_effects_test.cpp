// The sweep plant's effect records (identify/sweep_effects.h): one law per sweep effect of
// the effect table, each inside its physical range; a relative value multiplies the
// participant's own, an absolute one replaces it; the hip tempo acts per lowering.
#include "identify/sweep_effects.h"

#include <gtest/gtest.h>

#include <cmath>

#include "study/sweep_study.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim {
namespace {

SweepVariant nominalP1() {
  const SweepStudy study = loadSweepStudy("studies/burkett2004.yaml");
  return makeNominalVariant(study, study.participants[0]);
}

TEST(SweepEffects, EverySweepEffectOfTheTableHasOneLawWithARange) {
  for (const std::string& name : effectNames(PlantKind::kSweep)) {
    const EffectDescriptor* d = findEffect(PlantKind::kSweep, name);
    ASSERT_NE(d, nullptr) << name;
    const SweepEffectLaw& law = findSweepEffectLaw(d->id);
    EXPECT_EQ(law.id(), d->id) << name;
    EXPECT_LE(law.lower, law.upper) << name;
    EXPECT_FALSE(law.rangeSource.empty()) << name;
    if (!law.assumption.empty()) {
      EXPECT_NO_THROW(findSweepAssumption(law.assumption)) << name;
    }
  }
  EXPECT_THROW(findSweepEffectLaw(EffectId::kKneeViscousDamping), std::logic_error);
  EXPECT_THROW(findSweepAssumption("no_such_assumption"), std::logic_error);
}

TEST(SweepEffects, ARelativeValueScalesTheParticipantsOwnAndAnAbsoluteOneReplacesIt) {
  const SweepVariant v = nominalP1();
  ASSERT_GT(v.participant.kneeFriction, 0);
  SweepModelParams params;
  params.effects = {{EffectId::kKneeFrictionScale, 2.0}, {EffectId::kHipExtensionRatio, 0.8}};
  const SweepVariant changed = applySweepEffects(v, params);
  EXPECT_DOUBLE_EQ(changed.participant.kneeFriction, 2.0 * v.participant.kneeFriction);
  const SweepAssumption& ratio = findSweepAssumption(findSweepEffectLaw(EffectId::kHipExtensionRatio).assumption);
  EXPECT_DOUBLE_EQ(ratio.read(changed), 0.8);
  EXPECT_NE(ratio.read(v), 0.8);
}

TEST(SweepEffects, TheHipTempoScalesTheTimeScaleInProportionToTheLowering) {
  const SweepVariant v = nominalP1();
  SweepModelParams params;
  EXPECT_TRUE(std::isnan(params.value(EffectId::kHipTempoLowering)));
  const double base = calcSweepSwingParticipant(v, params, 0.1).hipMoment.timeScale;
  params.effects = {{EffectId::kHipTempoLowering, 0.25}};
  EXPECT_TRUE(params.has(EffectId::kHipTempoLowering));
  EXPECT_DOUBLE_EQ(params.value(EffectId::kHipTempoLowering), 0.25);
  EXPECT_DOUBLE_EQ(calcSweepSwingParticipant(v, params, 0.1).hipMoment.timeScale, base * 1.25);
  EXPECT_DOUBLE_EQ(calcSweepSwingParticipant(v, params, 0.0).hipMoment.timeScale,
                   calcSweepSwingParticipant(v, SweepModelParams{}, 0.0).hipMoment.timeScale);
  // Not an input change: the variant itself keeps its time scale.
  EXPECT_DOUBLE_EQ(applySweepEffects(v, params).participant.hipMoment.timeScale, v.participant.hipMoment.timeScale);
}

}  // namespace
}  // namespace swingsim
