#include "identify/cylinder_effects.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "io/knee_model_loader.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;

MauchCylinderParams twoPhase() { return loadMauchCylinder(kRoot + "/models/mauch-2phase.yaml"); }

// Every cylinder effect of the table has exactly one record, in the table's order, reporting
// one value per descriptor parameter and one regression column per fitted parameter.
TEST(CylinderEffectRecords, OneRecordPerCylinderEffectMatchingItsDescriptor) {
  std::size_t next = 0;
  const auto& records = cylinderEffectRecords();
  MauchCylinderParams p = twoPhase();
  for (const auto& d : effectTable()) {
    if (d.plant != PlantKind::kCylinder) continue;
    SCOPED_TRACE(d.name);
    ASSERT_LT(next, records.size()) << "no record";
    const CylinderEffectRecord& r = records[next++];
    EXPECT_EQ(r.id(), d.id) << "records out of the table's order";
    EXPECT_EQ(r.columns, d.fittedParameters);
    EXPECT_EQ(r.values(p).size(), d.parameters.size());
  }
  EXPECT_EQ(next, records.size()) << "a record of an effect that is not a cylinder effect";
}

TEST(CylinderEffectRecords, RefusesAnotherPlantsEffect) {
  EXPECT_THROW(findCylinderEffectRecord(EffectId::kKneeViscousDamping), std::invalid_argument);
}

// Added at the grid value, the model has it; removed, it does not (switch_delay: a slow latch,
// then Chien's fast one).
TEST(CylinderEffectRecords, AddAndRemoveSwitchTheEffect) {
  for (const auto& r : cylinderEffectRecords()) {
    SCOPED_TRACE(describeEffect(r.id()).name);
    MauchCylinderParams p = twoPhase();
    ASSERT_FALSE(r.has(p));
    const auto& grid = describeEffect(r.id()).grid;
    r.add(p, grid.empty() ? 0.0 : grid.back());
    EXPECT_TRUE(r.has(p));
    if (!grid.empty()) {
      EXPECT_EQ(r.values(p).back(), grid.back()) << "the grid value is reported last";
    }
    r.remove(p);
    EXPECT_FALSE(r.has(p));
  }
}

// The columns of every effect are where MauchCylinder puts its coefficients: with all effects
// on and distinct values, each effect's columns of the coefficient vector hold its fitted values.
TEST(CylinderEffectRecords, ColumnsAreTheCylinderRegressorsColumns) {
  MauchCylinderParams p = twoPhase();
  for (const auto& r : cylinderEffectRecords()) r.add(p, 0.01);
  auto& e = p.effects;
  e.coulombForce = 11;
  e.orificeCoefficient = 22;
  e.pistonMass = 33;
  e.positionDamping = 44;
  e.hyperextension = {55, 66, 77};
  const std::vector<double> b = MauchCylinder(p).getCoefficientVector();
  for (const auto& r : cylinderEffectRecords()) {
    SCOPED_TRACE(describeEffect(r.id()).name);
    const std::vector<int> cols = cylinderEffectColumns(p, r.id());
    ASSERT_EQ(cols.size(), static_cast<std::size_t>(r.columns));
    const std::vector<double> values = r.values(p);
    for (std::size_t i = 0; i < cols.size(); ++i) EXPECT_EQ(b[static_cast<std::size_t>(cols[i])], values[i]);
  }
  // An effect the model does not have has no columns.
  EXPECT_TRUE(cylinderEffectColumns(twoPhase(), EffectId::kInertia).empty());
}

TEST(CylinderEffectRecords, ApplicabilityAndSignRules) {
  const MauchCylinderParams four = loadMauchCylinder(kRoot + "/models/mauch-4phase.yaml");
  const auto& hyper = findCylinderEffectRecord(EffectId::kHyperextensionPhase);
  EXPECT_EQ(hyper.notApplicable(four), "the 4-phase model already has a hyperextension phase");
  EXPECT_EQ(hyper.notApplicable(twoPhase()), "");
  // The 2-phase model with a hyperextension phase nests in Chien's 4-phase model.
  MauchCylinderParams merged = twoPhase();
  hyper.add(merged, 0);
  const auto split = hyper.nestingModel(merged);
  ASSERT_TRUE(split.has_value());
  EXPECT_EQ(split->phases, 4);
  EXPECT_FALSE(split->effects.hyperextensionPhase);
  EXPECT_FALSE(hyper.nestingModel(four).has_value());

  std::string note;
  MauchCylinderParams p = twoPhase();
  p.effects.coulombForce = -1;
  EXPECT_FALSE(findCylinderEffectRecord(EffectId::kCoulombFriction).isPhysical(p, {}, note));
  EXPECT_NE(note.find("-1 N"), std::string::npos) << note;
  // A position damping that makes c + cx x negative at the far end of the stroke.
  BenchData stroke;
  stroke.position = {0.0, 0.02};
  p.effects.positionDamping = -1e9;
  EXPECT_FALSE(findCylinderEffectRecord(EffectId::kPositionDependentDamping).isPhysical(p, {stroke}, note));
  p.effects.positionDamping = 0;
  EXPECT_TRUE(findCylinderEffectRecord(EffectId::kPositionDependentDamping).isPhysical(p, {stroke}, note)) << note;
}

}  // namespace
}  // namespace swingsim
