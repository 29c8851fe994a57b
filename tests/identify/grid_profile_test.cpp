// The profiled grid parameter of a candidate (candidate_score.cpp): between grid values the
// profile's best is refined, and where the profile's 95 % region reaches an end of the grid the
// interval is one-sided (open towards the end it reaches), never the grid's edges as a 95 %
// interval. A plant whose training RSS is a known function of the grid value checks both.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

#include "identify/candidate_score.h"

namespace swingsim {
namespace {

struct GridModel : PlantModel {
  bool withEffect = false, fitted = false;
  double width = 0;  // m/s, the Coulomb tanh width (the grid parameter)
};

// 200 training samples; the base model leaves RSS 400; with coulomb_friction at width w the
// RSS is 200 (1 + curvature ln(w / bestWidth)^2): a parabola in ln w, so one parabolic step
// from three grid values finds bestWidth exactly.
class GridPlant final : public DiagnosisPlant {
 public:
  GridPlant(double bestWidth, double curvature) : bestWidth_(bestWidth), curvature_(curvature) {}
  PlantKind kind() const override { return PlantKind::kCylinder; }
  PlantModelPtr baseModel() const override { return std::make_shared<GridModel>(); }
  PlantFit fit(const PlantModel& model) const override {
    auto m = std::make_shared<GridModel>(dynamic_cast<const GridModel&>(model));
    m->fitted = true;
    const double l = m->withEffect ? std::log(m->width / bestWidth_) : 0;
    const double rss = m->withEffect ? 200.0 * (1.0 + curvature_ * l * l) : 400.0;
    PlantFit f;
    f.model = m;
    // Alternating +-a: white, so n_eff = n and the LR is n ln(RSS ratio).
    std::vector<double> r;
    for (int i = 0; i < 200; ++i) r.push_back((i % 2 ? 1.0 : -1.0) * std::sqrt(rss / 200.0));
    f.likelihoodResidual = {r};
    f.trainResidual = {r};
    f.trainPhase = {std::vector<int>(r.size(), 0)};
    f.rss = rss;
    f.samples = r.size();
    f.trainRmse = std::sqrt(rss / 200.0);
    f.validationRmse = {1.0};
    if (m->withEffect) {
      f.effectErrors.push_back({EffectId::kCoulombFriction, {0.1}});
      f.effectBounds.push_back({EffectId::kCoulombFriction, {{0.0, 1000.0}}});
    }
    return f;
  }
  std::string checkApplicable(const PlantModel&, EffectId) const override { return ""; }
  PlantModelPtr addEffect(const PlantModel& model, EffectId, double gridValue) const override {
    auto m = std::make_shared<GridModel>(dynamic_cast<const GridModel&>(model));
    m->withEffect = true;
    m->fitted = false;
    m->width = gridValue;
    return m;
  }
  PlantModelPtr combine(const PlantModel& a, const PlantModel&, EffectId id) const override {
    return addEffect(a, id, 0.01);
  }
  std::vector<double> effectValues(const PlantModel& model, EffectId id) const override {
    const auto& m = dynamic_cast<const GridModel&>(model);
    if (id == EffectId::kComRuleProportional) return {m.width};  // its one "grid" value
    return {m.fitted ? 50.0 : 0.0, m.width};                     // force_N, width_m_per_s
  }
  bool checkPhysical(const PlantModel&, EffectId, std::string&) const override { return true; }
  std::vector<std::string> phaseNames(const PlantModel&) const override { return {"all"}; }
  Comparison compare(const PlantModel&) const override { return {}; }
  std::vector<std::string> validationStems() const override { return {"held"}; }
  std::vector<NoiseEstimate> estimateRecordNoise() const override { return {{1.0, 200}, {1.0, 200}}; }

 private:
  double bestWidth_, curvature_;
};

CandidateScore scoreCoulomb(const GridPlant& plant) {
  const PlantFit current = plant.fit(*plant.baseModel());
  return scoreCandidate(plant, current, EffectId::kCoulombFriction, EffectSelectionSettings{}, nullptr);
}

// The truth between the grid's 5 and 10 mm/s: the reported width is the refined best, not the
// nearest grid value, and its interval is two-sided inside the grid.
TEST(GridProfile, TheBestBetweenGridValuesIsRefined) {
  const CandidateScore c = scoreCoulomb(GridPlant(0.007, 1.0));
  ASSERT_EQ(c.parameters.size(), 2u);
  const EffectParameter& width = c.parameters[1];
  EXPECT_NEAR(width.value, 0.007, 1e-9);
  EXPECT_TRUE(width.intervalNote.empty()) << width.intervalNote;
  // The region is narrower than the grid's spacing: its ends are where the profile crosses
  // chi^2_1(0.95), between the best and its neighbours 5 and 10 mm/s, not those grid values.
  EXPECT_GT(width.lower, 0.005);
  EXPECT_LT(width.lower, 0.007);
  EXPECT_GT(width.upper, 0.007);
  EXPECT_LT(width.upper, 0.01);
}

// The truth sharper than the grid's sharpest value (2 mm/s): the best sits at the grid's end,
// the interval reaches down to the physical bound 0 and says so; the grid's end is no limit.
TEST(GridProfile, ABestAtTheGridsEndHasAOneSidedInterval) {
  const CandidateScore c = scoreCoulomb(GridPlant(0.0005, 1.0));
  const EffectParameter& width = c.parameters[1];
  EXPECT_DOUBLE_EQ(width.value, 0.002);
  EXPECT_EQ(width.lower, 0.0);
  EXPECT_GT(width.upper, 0.002);
  EXPECT_LT(width.upper, 0.005);
  EXPECT_NE(width.intervalNote.find("one-sided"), std::string::npos) << width.intervalNote;
  EXPECT_NE(width.intervalNote.find("open below"), std::string::npos) << width.intervalNote;
}

// A profile so flat that every grid value is inside its 95 % region: open both ways.
TEST(GridProfile, AFlatProfileIsOpenBothWays) {
  const CandidateScore c = scoreCoulomb(GridPlant(0.007, 1e-5));
  const EffectParameter& width = c.parameters[1];
  EXPECT_EQ(width.lower, 0.0);
  EXPECT_EQ(width.upper, std::numeric_limits<double>::infinity());
  EXPECT_NE(width.intervalNote.find("open both ways"), std::string::npos) << width.intervalNote;
}

// A one-value grid is a switch (com_rule_proportional: on), not a profile: its value, no
// one-sided interval.
TEST(GridProfile, AOneValueGridIsItsValue) {
  const GridPlant plant(0.007, 1.0);
  const PlantFit current = plant.fit(*plant.baseModel());
  const CandidateScore c =
      scoreCandidate(plant, current, EffectId::kComRuleProportional, EffectSelectionSettings{}, nullptr);
  ASSERT_EQ(c.parameters.size(), 1u);
  EXPECT_EQ(c.parameters[0].value, 1.0);
  EXPECT_EQ(c.parameters[0].lower, 1.0);
  EXPECT_EQ(c.parameters[0].upper, 1.0);
  EXPECT_TRUE(c.parameters[0].intervalNote.empty()) << c.parameters[0].intervalNote;
}

}  // namespace
}  // namespace swingsim
