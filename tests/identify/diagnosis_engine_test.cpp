#include "identify/diagnosis_engine.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <vector>

namespace swingsim {
namespace {

// A plant whose model is a straight line y = a + b x with a physical bound b >= bLower: the
// engine's intervals of its base parameter b can be checked against the closed form of a
// linear model (numerics/profile_likelihood_test.cpp).
struct LineModel : PlantModel {};

class LinePlant final : public DiagnosisPlant {
 public:
  LinePlant(double trueSlope, double bLower) : bLower_(bLower) {
    std::mt19937_64 rng(9);
    std::normal_distribution<double> noise(0.0, 0.5);
    for (int i = 0; i < 40; ++i) {
      x_.push_back(0.1 * i);
      y_.push_back(1.0 + trueSlope * x_.back() + noise(rng));
    }
    for (std::size_t i = 0; i < x_.size(); ++i) {
      xbar_ += x_[i] / x_.size();
      ybar_ += y_[i] / y_.size();
    }
    for (std::size_t i = 0; i < x_.size(); ++i) {
      sxx_ += (x_[i] - xbar_) * (x_[i] - xbar_);
      sxy_ += (x_[i] - xbar_) * (y_[i] - ybar_);
    }
  }
  double freeSlope() const { return sxy_ / sxx_; }
  double fittedSlope() const { return std::max(freeSlope(), bLower_); }
  std::vector<double> residualAt(double b) const {  // the intercept refitted
    std::vector<double> r;
    for (std::size_t i = 0; i < x_.size(); ++i) r.push_back(y_[i] - ybar_ - b * (x_[i] - xbar_));
    return r;
  }
  double rssAt(double b) const {
    double s = 0;
    for (double r : residualAt(b)) s += r * r;
    return s;
  }
  double sxx() const { return sxx_; }
  double n() const { return static_cast<double>(x_.size()); }

  PlantKind kind() const override { return PlantKind::kCylinder; }
  PlantModelPtr baseModel() const override { return std::make_shared<LineModel>(); }
  PlantFit fit(const PlantModel&) const override {
    PlantFit f;
    f.model = baseModel();
    const double b = fittedSlope();
    f.likelihoodResidual = {residualAt(b)};
    f.rss = rssAt(b);
    f.samples = x_.size();
    const double se = std::sqrt(rssAt(freeSlope()) / (n() - 2) / sxx_);
    f.baseParameters.push_back({"slope", b, se, bLower_, std::numeric_limits<double>::infinity()});
    return f;
  }
  std::optional<double> calcHeldParameterRss(const PlantModel&, const std::string& name, double v) const override {
    if (name != "slope") return std::nullopt;
    return rssAt(v);
  }
  std::string checkApplicable(const PlantModel&, EffectId) const override { return "not in this test"; }
  PlantModelPtr addEffect(const PlantModel&, EffectId, double) const override { return baseModel(); }
  PlantModelPtr combine(const PlantModel&, const PlantModel&, EffectId) const override { return baseModel(); }
  std::vector<double> effectValues(const PlantModel&, EffectId) const override { return {}; }
  bool checkPhysical(const PlantModel&, EffectId, std::string&) const override { return true; }
  std::vector<std::string> phaseNames(const PlantModel&) const override { return {"all"}; }
  Comparison compare(const PlantModel&) const override { return {}; }
  std::vector<std::string> validationStems() const override { return {}; }
  std::vector<NoiseEstimate> estimateRecordNoise() const override { return {}; }

 private:
  std::vector<double> x_, y_;
  double xbar_ = 0, ybar_ = 0, sxx_ = 0, sxy_ = 0, bLower_;
};

// Steps from se / 4, doubling, then 8 halvings: the last bracket is at most 2 se wide for an
// end within ~4 se, so the end is within 2 se / 512 of the exact one.
constexpr double kProfileTolerance = 0.01;  // times the standard error

// The slope held by its bound b >= 1 (free estimate about 0.8): the engine gives the
// profile-likelihood interval [1, upper] with upper from the closed form, not a Wald
// interval around 1 that crosses the bound, and says so in the note.
TEST(DiagnosisEngine, ABaseParameterOnItsBoundGetsAOneSidedProfileInterval) {
  const LinePlant plant(0.8, 1.0);
  ASSERT_LT(plant.freeSlope(), 1.0);
  const BaselineComparison b = compareBaseline(plant, 5);
  ASSERT_EQ(b.parameters.size(), 1u);
  const EffectParameter& p = b.parameters[0];
  const double nEff = calcEffectiveSampleSize(b.fit.likelihoodResidual), c = calcChiSquaredQuantile(0.95, 1);
  const double rssBest = plant.rssAt(1.0);
  const double upper =
      plant.freeSlope() + std::sqrt((rssBest * std::exp(c / nEff) - plant.rssAt(plant.freeSlope())) / plant.sxx());
  const double se = b.fit.baseParameters[0].standardError * std::sqrt(plant.n() / nEff);
  EXPECT_DOUBLE_EQ(p.value, 1.0);
  EXPECT_DOUBLE_EQ(p.lower, 1.0);
  EXPECT_NEAR(p.upper, upper, kProfileTolerance * se);
  EXPECT_NE(p.intervalNote.find("profile likelihood"), std::string::npos) << p.intervalNote;
  EXPECT_NE(p.intervalNote.find("one-sided: the physical bound 1 cuts it"), std::string::npos) << p.intervalNote;
}

// Far from its bound the slope keeps the Wald interval value +- 1.96 se (inflated), no note.
TEST(DiagnosisEngine, ABaseParameterFarFromItsBoundKeepsTheWaldInterval) {
  const LinePlant plant(0.8, -10.0);
  const BaselineComparison b = compareBaseline(plant, 5);
  ASSERT_EQ(b.parameters.size(), 1u);
  const EffectParameter& p = b.parameters[0];
  const double nEff = calcEffectiveSampleSize(b.fit.likelihoodResidual);
  const double se = b.fit.baseParameters[0].standardError * std::sqrt(plant.n() / std::max(1.0, nEff));
  EXPECT_TRUE(p.intervalNote.empty()) << p.intervalNote;
  EXPECT_NEAR(p.upper - p.value, calcNormalQuantile(0.975) * se, 1e-12);
  EXPECT_NEAR(p.value - p.lower, calcNormalQuantile(0.975) * se, 1e-12);
}

// A plant whose fitted model leaves pure white noise (sigma 1) on a training record of
// `samples` samples and a held-out error at the noise: the data are explained exactly when
// the whiteness test can say the residual is white.
class WhiteNoisePlant final : public DiagnosisPlant {
 public:
  explicit WhiteNoisePlant(int samples) {
    std::mt19937_64 rng(21);
    std::normal_distribution<double> noise(0.0, 1.0);
    for (int i = 0; i < samples; ++i) residual_.push_back(noise(rng));
  }
  PlantKind kind() const override { return PlantKind::kCylinder; }
  PlantModelPtr baseModel() const override { return std::make_shared<LineModel>(); }
  PlantFit fit(const PlantModel&) const override {
    PlantFit f;
    f.model = baseModel();
    f.likelihoodResidual = {residual_};
    f.trainResidual = {residual_};
    f.trainPhase = {std::vector<int>(residual_.size(), 0)};
    for (double r : residual_) f.rss += r * r;
    f.samples = residual_.size();
    f.trainRmse = std::sqrt(f.rss / static_cast<double>(f.samples));
    f.validationRmse = {1.0};
    return f;
  }
  std::string checkApplicable(const PlantModel&, EffectId) const override { return "not in this test"; }
  PlantModelPtr addEffect(const PlantModel&, EffectId, double) const override { return baseModel(); }
  PlantModelPtr combine(const PlantModel&, const PlantModel&, EffectId) const override { return baseModel(); }
  std::vector<double> effectValues(const PlantModel&, EffectId) const override { return {}; }
  bool checkPhysical(const PlantModel&, EffectId, std::string&) const override { return true; }
  std::vector<std::string> phaseNames(const PlantModel&) const override { return {"all"}; }
  Comparison compare(const PlantModel&) const override { return {}; }
  std::vector<std::string> validationStems() const override { return {"held"}; }
  std::vector<NoiseEstimate> estimateRecordNoise() const override { return {{1.0, 100}, {1.0, 100}}; }

 private:
  std::vector<double> residual_;
};

// White noise on 200 samples is explained; on 8 samples the whiteness test cannot be
// computed (too few samples for 2 lags), which is "cannot tell": never explained.
TEST(DiagnosisEngine, AWhitenessTestThatCannotBeComputedNeverExplainsTheData) {
  const Diagnosis enough = runDiagnosis(WhiteNoisePlant(200), EffectSelectionSettings{});
  EXPECT_TRUE(enough.finalWhiteness.computed);
  EXPECT_TRUE(enough.explained) << enough.verdict;
  const Diagnosis tooShort = runDiagnosis(WhiteNoisePlant(8), EffectSelectionSettings{});
  EXPECT_FALSE(tooShort.finalWhiteness.computed);
  EXPECT_FALSE(tooShort.finalResidualWhite);
  EXPECT_FALSE(tooShort.explained);
  EXPECT_EQ(tooShort.verdict.rfind("NOT explained", 0), 0u) << tooShort.verdict;
  EXPECT_NE(tooShort.verdict.find("whether the final residual is white cannot be told"), std::string::npos)
      << tooShort.verdict;
}

}  // namespace
}  // namespace swingsim
