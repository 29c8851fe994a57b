#include "identify/swing_model.h"

#include <gtest/gtest.h>

#include <cmath>

#include "identify/synthetic_swing.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;

const SwingBase& base() {
  static const SwingBase b = [] {
    SwingBase s;
    s.participant = loadParticipant(kRoot + "/participants/p1.yaml");
    s.knee = loadKneeModel(kRoot + "/models/damping-table-default.yaml");
    return s;
  }();
  return b;
}

const SwingRecord& normalSwing() {
  static const SwingRecord r = makeSyntheticSwing(base(), {}, {"normal", 1.0, 1.0}, 0.0, 1);
  return r;
}

// Only a moving hip takes the record's pelvis along.
TEST(SwingModel, ThighKinematicsTakeThePelvisOnlyForAMovingHip) {
  SwingRecord r;
  r.time = {0.0, 0.1};
  r.hipFlexion = {0.2, 0.3};
  r.pelvisX = {0.0, 0.01};
  EXPECT_EQ(thighKinematicsOf(r, true).pelvisX, r.pelvisX);
  EXPECT_TRUE(thighKinematicsOf(r, false).pelvisX.empty());
  EXPECT_EQ(thighKinematicsOf(r, false).hipFlexion, r.hipFlexion);
  // The hip-moment drive never moves the hip.
  EXPECT_FALSE(hipPathOf(base(), thighKinematicsOf(r, true)).has_value());
}

// The knee law: the model's resisting parts scaled, one part more for added knee effects.
TEST(SwingModel, KneeLawScalesTheModelAndAddsTheKneeEffects) {
  SwingModelParams plain;
  const KneeLawSum reference = makeSwingKneeLaw(base(), plain);
  SwingModelParams damped = addSwingEffect(plain, EffectId::kKneeViscousDamping, 0);
  EXPECT_EQ(makeSwingKneeLaw(base(), damped).size(), reference.size()) << "a zero damper adds no part";
  damped.effects.knee.viscousDamping = 2.0;  // N m s/rad
  const KneeLawSum law = makeSwingKneeLaw(base(), damped);
  ASSERT_EQ(law.size(), reference.size() + 1);
  // Mid-swing (no stop, no Tc): the added damper's -c rate on top of the model's moment.
  const KneeKinematics knee{0.8, 3.0};
  std::vector<double> z(static_cast<std::size_t>(std::max(1, law.numStates())), 0.0);
  law.initialStates(z.data());
  EXPECT_NEAR(law.calcMoment(knee, z.data()) - reference.calcMoment(knee, z.data()), -2.0 * 3.0, 1e-9);
}

// The effect size: zero for an effect at its neutral value, positive when it acts.
TEST(SwingModel, EffectRmsIsZeroForANeutralEffect) {
  SwingModelParams truth = addSwingEffect({}, EffectId::kShankMassScale, 0);
  EXPECT_EQ(calcSwingEffectRms(base(), truth, EffectId::kShankMassScale, normalSwing()), 0.0);
  truth.effects.shankMassScale = 1.5;
  EXPECT_GT(calcSwingEffectRms(base(), truth, EffectId::kShankMassScale, normalSwing()), 0.1);  // deg
}

}  // namespace
}  // namespace swingsim
