// The knee moments the swing diagnosis adds (knee/knee_added_effects.h), by hand: the sum of
// friction, damping and assist spring with the KneeLaw sign convention, passivity, stored
// energy, validation; and the scaled law.
#include "knee/knee_added_effects.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "knee/joint_stop.h"

namespace swingsim {
namespace {

constexpr double kRoundOff = 1e-12;

KneeAddedEffectsParams allThree() {
  KneeAddedEffectsParams p;
  p.coulombMoment = 2;
  p.coulombSmoothingRate = 0.5;
  p.viscousDamping = 0.3;
  p.assistStiffness = 4;
  return p;
}

TEST(KneeAddedEffects, MomentIsFrictionPlusDampingPlusSpringAllResisting) {
  const KneeAddedEffects law(allThree());
  const KneeKinematics flexing{0.5, 3.0};
  EXPECT_NEAR(law.calcMoment(flexing, nullptr), -2 * std::tanh(3.0 / 0.5) - 0.3 * 3.0 - 4 * 0.5, kRoundOff);
  EXPECT_NEAR(law.calcMoment({0.0, 0.0}, nullptr), 0.0, kRoundOff) << "nothing at rest at full extension";
  // Far above the smoothing rate the friction is the full Coulomb moment, against the motion.
  EXPECT_NEAR(law.calcMoment({0.0, -50.0}, nullptr), 2 + 0.3 * 50, 1e-9);
  EXPECT_TRUE(law.isPassive());
  EXPECT_NEAR(law.calcStoredEnergy({0.5, 1.0}, nullptr), 0.5 * 4 * 0.25, kRoundOff);
  EXPECT_EQ(law.name(), "added knee effects");
  EXPECT_NEAR(law.clone()->calcMoment(flexing, nullptr), law.calcMoment(flexing, nullptr), 0.0);
}

TEST(KneeAddedEffects, NegativeTermsAreNotPassiveAndBadValuesAreRefused) {
  KneeAddedEffectsParams p = allThree();
  p.viscousDamping = -0.1;
  EXPECT_FALSE(KneeAddedEffects(p).isPassive()) << "a fit may step through zero; such a law gives energy";
  p = allThree();
  p.coulombSmoothingRate = 0;
  EXPECT_THROW(KneeAddedEffects{p}, std::invalid_argument);
  p = allThree();
  p.assistStiffness = std::numeric_limits<double>::infinity();
  EXPECT_THROW(KneeAddedEffects{p}, std::invalid_argument);
  EXPECT_FALSE(KneeAddedEffectsParams{}.any());
  EXPECT_TRUE(allThree().any());
}

TEST(ScaledKneeLaw, ScalesTheMomentAndTheStoredEnergyKeepsTheName) {
  const JointStop stop(JointStopParams{});
  const ScaledKneeLaw half(stop, 0.5);
  const KneeKinematics in{-0.02, -1.0};
  EXPECT_NEAR(half.calcMoment(in, nullptr), 0.5 * stop.calcMoment(in, nullptr), kRoundOff);
  EXPECT_NEAR(half.calcStoredEnergy(in, nullptr), 0.5 * stop.calcStoredEnergy(in, nullptr), kRoundOff);
  EXPECT_EQ(half.name(), "hyperextension stop");
  EXPECT_TRUE(half.isPassive());
  EXPECT_FALSE(ScaledKneeLaw(stop, -1).isPassive());
  EXPECT_THROW(ScaledKneeLaw(stop, std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
