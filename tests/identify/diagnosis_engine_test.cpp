#include "identify/diagnosis_engine.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <vector>

#include "two_candidate_plant.h"

namespace swingsim {
namespace {

// A plant whose model is a straight line y = a + b x with physical bounds bLower <= b <= bUpper: the
// engine's intervals of its base parameter b can be checked against the closed form of a
// linear model (numerics/profile_likelihood_test.cpp).
struct LineModel : PlantModel {};

class LinePlant final : public DiagnosisPlant {
 public:
  LinePlant(double trueSlope, double bLower, double bUpper = std::numeric_limits<double>::infinity(),
            double noiseSd = 0.5)
      : bLower_(bLower), bUpper_(bUpper) {
    std::mt19937_64 rng(9);
    std::normal_distribution<double> noise(0.0, noiseSd);
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
  double fittedSlope() const { return std::clamp(freeSlope(), bLower_, bUpper_); }
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
    f.baseParameters.push_back({"slope", b, se, bLower_, bUpper_});
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
  double xbar_ = 0, ybar_ = 0, sxx_ = 0, sxy_ = 0, bLower_, bUpper_;
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
  EXPECT_NE(p.intervalNote.find("one-sided: cut by its lower bound 1"), std::string::npos) << p.intervalNote;
}

// The slope held by its upper bound b <= 1 (free estimate about 1.2): the note names the
// upper bound and its value, never the lower one.
TEST(DiagnosisEngine, AProfileIntervalCutByTheUpperBoundSaysWhichBound) {
  const LinePlant plant(1.2, 0.05, 1.0);
  ASSERT_GT(plant.freeSlope(), 1.0);
  const BaselineComparison b = compareBaseline(plant, 5);
  ASSERT_EQ(b.parameters.size(), 1u);
  const EffectParameter& p = b.parameters[0];
  EXPECT_DOUBLE_EQ(p.value, 1.0);
  EXPECT_DOUBLE_EQ(p.upper, 1.0);
  EXPECT_GT(p.lower, 0.05);
  EXPECT_NE(p.intervalNote.find("one-sided: cut by its upper bound 1"), std::string::npos) << p.intervalNote;
  EXPECT_EQ(p.intervalNote.find("lower bound"), std::string::npos) << p.intervalNote;
  EXPECT_EQ(p.intervalNote.find("0.05"), std::string::npos) << p.intervalNote;
}

// Noise so large that no slope in [0.9, 1] is excluded: the note names both bounds with their
// values (not "the bound 0.9 cuts it on both sides").
TEST(DiagnosisEngine, AProfileIntervalCutByBothBoundsNamesBoth) {
  const LinePlant plant(1.2, 0.9, 1.0, 20.0);
  const BaselineComparison b = compareBaseline(plant, 5);
  ASSERT_EQ(b.parameters.size(), 1u);
  const EffectParameter& p = b.parameters[0];
  EXPECT_DOUBLE_EQ(p.lower, 0.9);
  EXPECT_DOUBLE_EQ(p.upper, 1.0);
  EXPECT_NE(p.intervalNote.find("cut by its lower bound 0.9 and its upper bound 1"), std::string::npos)
      << p.intervalNote;
  EXPECT_EQ(p.intervalNote.find("both sides"), std::string::npos) << p.intervalNote;
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

std::size_t countOf(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + what.size())) ++n;
  return n;
}

// The candidate whose fit moves no residual gets no interval and the words "no information
// in these records"; it is never accepted nor the closest, although its likelihood ratio is
// the larger. The verdict names one closest candidate, once, with its definition, and the
// power advice is for that one.
TEST(DiagnosisEngine, ACandidateWithoutInformationHasNoIntervalAndIsNeverTheClosest) {
  EffectSelectionSettings settings;
  settings.candidates = {"inertia", "orifice_quadratic"};
  const Diagnosis dg = runDiagnosis(TwoCandidatePlant(), settings);
  ASSERT_EQ(dg.steps.size(), 1u);
  const auto& candidates = dg.steps[0].candidates;
  ASSERT_EQ(candidates.size(), 2u);
  const CandidateScore& inertia = candidates[0];
  const CandidateScore& orifice = candidates[1];
  ASSERT_EQ(orifice.effect, "orifice_quadratic");
  ASSERT_GT(orifice.likelihoodRatio, inertia.likelihoodRatio);
  EXPECT_TRUE(inertia.informative);
  EXPECT_FALSE(orifice.informative);
  EXPECT_FALSE(orifice.accepted);
  ASSERT_EQ(orifice.parameters.size(), 1u);
  EXPECT_TRUE(std::isnan(orifice.parameters[0].lower));
  EXPECT_TRUE(std::isnan(orifice.parameters[0].upper));
  EXPECT_EQ(orifice.parameters[0].intervalNote, "no information in these records");
  EXPECT_EQ(findClosestCandidate(dg.steps[0]), &inertia);
  ASSERT_TRUE(dg.power.has_value());
  EXPECT_EQ(dg.power->effect, "inertia");
  // Issue 54: its held-out error stays at 2.0, so no number of swings is advised for it.
  EXPECT_FALSE(dg.power->lowersHeldOut);
  EXPECT_NE(dg.verdict.find("The closest does not lower the held-out error"), std::string::npos) << dg.verdict;
  EXPECT_EQ(dg.verdict.find("more swings like these ("), std::string::npos) << dg.verdict;

  const std::string& v = dg.verdict;
  EXPECT_NE(v.find("no information in these records: orifice_quadratic"), std::string::npos) << v;
  EXPECT_NE(v.find("The closest (largest likelihood ratio on the training records) is inertia"), std::string::npos)
      << v;
  EXPECT_EQ(countOf(v, "orifice_quadratic"), 1u) << v;          // only in the list, never with an interval
  EXPECT_EQ(countOf(v, "inertia"), 2u) << v;                    // in the list tried, and once as the closest
  EXPECT_EQ(countOf(v, "the closest, "), 0u) << v;              // the power advice names no other one
  EXPECT_EQ(countOf(v, "(largest likelihood ratio"), 1u) << v;  // defined once
}

// A step with only candidates without information has no closest one and no power advice.
TEST(DiagnosisEngine, NoClosestCandidateWhenNoneCarriesInformation) {
  EffectSelectionSettings settings;
  settings.candidates = {"orifice_quadratic"};
  const Diagnosis dg = runDiagnosis(TwoCandidatePlant(), settings);
  ASSERT_EQ(dg.steps.size(), 1u);
  EXPECT_EQ(findClosestCandidate(dg.steps[0]), nullptr);
  EXPECT_FALSE(dg.power.has_value());
  EXPECT_EQ(dg.verdict.find("closest"), std::string::npos) << dg.verdict;
  EXPECT_NE(dg.verdict.find("Tried on top of the final model: none with information; no information in these records: "
                            "orifice_quadratic."),
            std::string::npos)
      << dg.verdict;
}

}  // namespace
}  // namespace swingsim
