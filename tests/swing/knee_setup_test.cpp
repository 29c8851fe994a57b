// The knee law and setup of one swing (swing/knee_setup.h): the participant's friction Tc
// is added to the knee model's law only when it is above zero, and a setup names the knee
// file actually used.
#include "swing/knee_setup.h"

#include <gtest/gtest.h>

#include "io/knee_model_loader.h"
#include "io/participant_loader.h"

namespace swingsim {
namespace {

TEST(KneeSetup, FrictionIsAddedOnlyWhenTheParticipantHasIt) {
  Participant p = loadParticipant("participants/p1.yaml");
  const KneeModel model = loadKneeModel(p.kneeModelPath);
  ASSERT_GT(p.kneeFriction, 0.0);
  const KneeLawSum withFriction = makeKneeLaw(p, model);
  ASSERT_EQ(withFriction.size(), model.law.size() + 1);
  EXPECT_EQ(withFriction.part(withFriction.size() - 1).name(), "knee friction");
  p.kneeFriction = 0;
  EXPECT_EQ(makeKneeLaw(p, model).size(), model.law.size());
}

TEST(KneeSetup, ASetupNamesTheKneeFileUsedAndKeepsLoweringAndMass) {
  const Participant p = loadParticipant("participants/p1.yaml");
  KneeModel other = loadKneeModel(p.kneeModelPath);
  other.path = "models/elsewhere.yaml";
  AddedMass added;
  added.mass = 0.5;
  added.distanceBelowKnee = 0.2;
  const SwingSetup setup = makeSwingSetup(p, other, 0.05, added);
  EXPECT_EQ(setup.participant.kneeModelPath, "models/elsewhere.yaml") << "an override is what a failure names";
  EXPECT_EQ(setup.lowering, 0.05);
  EXPECT_EQ(setup.added.mass, 0.5);
  ASSERT_NE(setup.knee, nullptr);
  EXPECT_EQ(setup.knee->name(), makeKneeLaw(p, other).name());
}

}  // namespace
}  // namespace swingsim
