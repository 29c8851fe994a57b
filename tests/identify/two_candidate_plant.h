#pragma once
// A test plant for the diagnosis engine and its candidate scoring (diagnosis_engine_test.cpp,
// candidate_score_test.cpp).
#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "identify/diagnosis_engine.h"

namespace swingsim {

// A plant of white noise (sigma 1, 200 samples) left by a base model whose held-out error is
// twice the noise, with two candidates: "inertia" lowers the training RSS a little and has a
// narrow interval inside its range; "orifice_quadratic" lowers it more (larger likelihood
// ratio) but its parameter's interval is a million times its physical range, a Jacobian
// column of round-off: it carries no information in these records.
struct TwoCandidateModel : PlantModel {
  std::vector<EffectId> effects;
  bool fitted = false;
  bool has(EffectId id) const { return std::find(effects.begin(), effects.end(), id) != effects.end(); }
};

class TwoCandidatePlant final : public DiagnosisPlant {
 public:
  TwoCandidatePlant() {
    std::mt19937_64 rng(5);
    std::normal_distribution<double> noise(0.0, 1.0);
    for (int i = 0; i < 200; ++i) residual_.push_back(noise(rng));
  }
  PlantKind kind() const override { return PlantKind::kCylinder; }
  PlantModelPtr baseModel() const override { return std::make_shared<TwoCandidateModel>(); }
  PlantFit fit(const PlantModel& model) const override {
    auto m = std::make_shared<TwoCandidateModel>(dynamic_cast<const TwoCandidateModel&>(model));
    m->fitted = true;
    // Shares of the residual left: LR = n_eff ln(RSS_base / RSS) of about 2 and 4.
    const double left = m->has(EffectId::kInertia) ? 0.995 : m->has(EffectId::kOrificeQuadratic) ? 0.99 : 1.0;
    PlantFit f;
    f.model = m;
    std::vector<double> r;
    for (double v : residual_) r.push_back(left * v);
    f.likelihoodResidual = {r};
    f.trainResidual = {r};
    f.trainPhase = {std::vector<int>(r.size(), 0)};
    for (double v : r) f.rss += v * v;
    f.samples = r.size();
    f.trainRmse = std::sqrt(f.rss / static_cast<double>(f.samples));
    f.validationRmse = {2.0};
    if (m->has(EffectId::kInertia)) {
      f.effectErrors.push_back({EffectId::kInertia, {0.1}});
      f.effectBounds.push_back({EffectId::kInertia, {{0.0, 10.0}}});
    }
    if (m->has(EffectId::kOrificeQuadratic)) {
      f.effectErrors.push_back({EffectId::kOrificeQuadratic, {1e6}});
      f.effectBounds.push_back({EffectId::kOrificeQuadratic, {{0.0, 10.0}}});
    }
    return f;
  }
  std::string checkApplicable(const PlantModel& model, EffectId id) const override {
    return dynamic_cast<const TwoCandidateModel&>(model).has(id) ? "already in the model" : "";
  }
  PlantModelPtr addEffect(const PlantModel& model, EffectId id, double) const override {
    auto m = std::make_shared<TwoCandidateModel>(dynamic_cast<const TwoCandidateModel&>(model));
    m->effects.push_back(id);
    m->fitted = false;
    return m;
  }
  PlantModelPtr combine(const PlantModel& a, const PlantModel&, EffectId id) const override {
    return addEffect(a, id, 0);
  }
  std::vector<double> effectValues(const PlantModel& model, EffectId id) const override {
    const auto& m = dynamic_cast<const TwoCandidateModel&>(model);
    if (!m.fitted) return {0.0};  // neutral
    return {id == EffectId::kInertia ? 1.0 : 0.5};
  }
  bool checkPhysical(const PlantModel&, EffectId, std::string&) const override { return true; }
  std::vector<std::string> phaseNames(const PlantModel&) const override { return {"all"}; }
  Comparison compare(const PlantModel&) const override {
    Comparison c;
    c.quantity = "force";
    c.unit = "N";
    return c;
  }
  std::vector<std::string> validationStems() const override { return {"held"}; }
  std::vector<NoiseEstimate> estimateRecordNoise() const override { return {{1.0, 200}, {1.0, 200}}; }

 private:
  std::vector<double> residual_;
};

}  // namespace swingsim
