#include "identify/swing_effects.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "core/units.h"

namespace swingsim {
namespace {

// Every swing effect of the table has exactly one record, in the table's order, with one slot
// per fitted parameter and a grid accessor exactly when the descriptor has a grid.
TEST(SwingEffectRecords, OneRecordPerSwingEffectMatchingItsDescriptor) {
  std::size_t next = 0;
  const auto& records = swingEffectRecords();
  for (const auto& d : effectTable()) {
    if (d.plant != PlantKind::kSwing) continue;
    SCOPED_TRACE(d.name);
    ASSERT_LT(next, records.size()) << "no record";
    const SwingEffectRecord& r = records[next++];
    EXPECT_EQ(r.id(), d.id) << "records out of the table's order";
    EXPECT_EQ(r.slots.size(), static_cast<std::size_t>(d.fittedParameters));
    EXPECT_EQ(r.gridValue != nullptr, !d.grid.empty());
    EXPECT_NE(r.isPhysical, nullptr);
    // Participant-level effects act on the leg, not through the knee law.
    if (d.participantLevel) {
      EXPECT_TRUE(r.applyToParticipant != nullptr) << "a participant-level effect that does nothing";
    }
    for (const auto& slot : r.slots) {
      EXPECT_LE(slot.bounds.lower, slot.bounds.start);
      EXPECT_GE(slot.bounds.upper, slot.bounds.start);
    }
  }
  EXPECT_EQ(next, records.size()) << "a record of an effect that is not a swing effect";
}

TEST(SwingEffectRecords, RefusesAnotherPlantsEffect) {
  EXPECT_THROW(findSwingEffectRecord(EffectId::kCoulombFriction), std::invalid_argument);
  EXPECT_THROW(addSwingEffectTo({}, EffectId::kStopStiffness, 0), std::invalid_argument);
}

// Switched on at the start values (0 for a moment, 1 for a scale) with the grid value set;
// removed: absent and back at the start values.
TEST(SwingEffectRecords, AddAndRemoveSetTheStartValues) {
  SwingEffects e;
  e.knee.coulombMoment = 7;
  e = addSwingEffectTo(e, EffectId::kKneeCoulombFriction, 2.0);
  EXPECT_TRUE(e.has(EffectId::kKneeCoulombFriction));
  EXPECT_FALSE(e.has(EffectId::kKneeViscousDamping));
  EXPECT_EQ(e.knee.coulombMoment, 0.0);
  EXPECT_EQ(e.knee.coulombSmoothingRate, 2.0);
  e.knee.coulombMoment = 3;
  e = addSwingEffectTo(e, EffectId::kHipMomentScale, 0);
  e.hipMomentScale = 1.3;
  EXPECT_EQ(e.present.size(), 2u);

  const SwingEffects without = removeSwingEffect(e, EffectId::kKneeCoulombFriction);
  EXPECT_FALSE(without.has(EffectId::kKneeCoulombFriction));
  EXPECT_TRUE(without.has(EffectId::kHipMomentScale));
  EXPECT_EQ(without.knee.coulombMoment, 0.0);  // the knee law must not see it
  EXPECT_EQ(without.hipMomentScale, 1.3);
}

TEST(SwingEffectRecords, CopyTakesTheFittedAndGridValues) {
  SwingEffects from = addSwingEffectTo({}, EffectId::kKneeCoulombFriction, 5.0);
  from.knee.coulombMoment = 2.5;
  from.knee.viscousDamping = 9;  // not this effect's: left behind
  const SwingEffects to = copySwingEffect({}, from, EffectId::kKneeCoulombFriction);
  EXPECT_TRUE(to.has(EffectId::kKneeCoulombFriction));
  EXPECT_EQ(to.knee.coulombMoment, 2.5);
  EXPECT_EQ(to.knee.coulombSmoothingRate, 5.0);
  EXPECT_EQ(to.knee.viscousDamping, 0.0);
}

// Reported values: the fitted ones in report units, then the grid value in its report unit.
TEST(SwingEffectRecords, ValuesAreInReportUnits) {
  SwingEffects e = addSwingEffectTo({}, EffectId::kKneeCoulombFriction, 2.0);
  e.knee.coulombMoment = 4;
  e = addSwingEffectTo(e, EffectId::kToeOffVelocity, 0);
  e.toeOffHipRate = 1.0;
  e.toeOffKneeRate = -2.0;
  EXPECT_EQ(swingEffectValues(e, EffectId::kKneeCoulombFriction), (std::vector<double>{4.0, 2.0 * kRadToDeg}));
  EXPECT_EQ(swingEffectValues(e, EffectId::kToeOffVelocity), (std::vector<double>{kRadToDeg, -2.0 * kRadToDeg}));
}

TEST(SwingEffectRecords, SignRulesRefuseTheWrongSign) {
  std::string note;
  SwingEffects e;
  e.knee.viscousDamping = -0.1;
  EXPECT_FALSE(findSwingEffectRecord(EffectId::kKneeViscousDamping).isPhysical(e, note));
  EXPECT_NE(note.find("-0.1 N m s/rad"), std::string::npos) << note;
  e.knee.viscousDamping = 0.1;
  EXPECT_TRUE(findSwingEffectRecord(EffectId::kKneeViscousDamping).isPhysical(e, note));
  e.toeOffKneeRate = -1.0;  // the foot cannot extend the knee
  EXPECT_FALSE(findSwingEffectRecord(EffectId::kToeOffVelocity).isPhysical(e, note));
  e.belowKneeMassScale = 0;
  EXPECT_FALSE(findSwingEffectRecord(EffectId::kBelowKneeMassScale).isPhysical(e, note));
}

// Only present effects act on the leg; shank and below-knee scales multiply together.
TEST(SwingEffectRecords, ParticipantEffectsActOnlyWhenPresent) {
  Participant base;
  base.shank.mass = 3;
  base.foot.mass = 1;
  base.hipMoment.flexionAmplitude = 10;
  SwingEffects e;
  e.shankMassScale = 2;
  e.hipMomentScale = 3;
  EXPECT_EQ(applyParticipantEffects(base, e).shank.mass, 3.0) << "an absent effect acted";
  e.setPresent(EffectId::kShankMassScale, true);
  e.setPresent(EffectId::kBelowKneeMassScale, true);
  e.belowKneeMassScale = 1.5;
  const Participant p = applyParticipantEffects(base, e);
  EXPECT_EQ(p.shank.mass, 3.0 * 2 * 1.5);
  EXPECT_EQ(p.foot.mass, 1.5);
  EXPECT_EQ(p.hipMoment.flexionAmplitude, 10.0);
  e.setPresent(EffectId::kHipMomentScale, true);
  EXPECT_EQ(applyParticipantEffects(base, e).hipMoment.flexionAmplitude, 30.0);
  EXPECT_EQ(applyHipDriveEffects(e, {1.0, -2.0}), (std::vector<double>{3.0, -6.0}));
}

}  // namespace
}  // namespace swingsim
