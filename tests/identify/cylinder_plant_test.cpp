#include "identify/cylinder_plant.h"
#include "io/bench_csv.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>

#include "core/input_error.h"
#include "identify/synthetic_bench.h"
#include "io/knee_model_loader.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;
constexpr double kNoise = 25.0;  // N, load-cell noise of studies/mauch2014-bench.yaml
// The diagnosis's claim: hidden effects of at least 3 noise RMS must be found...
constexpr double kMinEffectToNoise = 3.0;
// ...and the final validation RMSE must come within 15 % of the noise floor.
constexpr double kNoiseFloorTolerance = 1.15;
// Null test: at most this many false acceptances over kNullSeeds seeds.
constexpr int kNullSeeds = 20;
constexpr int kMaxFalseAcceptances = 1;
// Parameters are reported with 95 % intervals, which miss the truth in 1 of 20 honest draws;
// the blind test draws at random on every run, so the check uses the 99.9 % interval with
// the same standard error (z 3.29 / 1.96) and fails by chance in < 0.1 % per parameter.
// Grid parameters (profile-likelihood intervals over the fixed grid) are checked as reported.
constexpr double kCheckedIntervalWidening = 3.2905 / 1.9600;

struct Data {
  std::vector<BenchData> train, validate;
};

EffectId effectId(const std::string& name) { return findEffect(PlantKind::kCylinder, name)->id; }

Diagnosis diagnose(const MauchCylinderParams& base, const Data& d, const EffectSelectionSettings& settings = {}) {
  return runDiagnosis(CylinderPlant(base, d.train, d.validate), settings);
}

const KneeAngleStride& stride() {
  static const KneeAngleStride s = readKneeAngleStride(kRoot + "/studies/data/winter-natural-cadence.csv", 28, 97);
  return s;
}

MauchCylinderParams model(const std::string& file) { return loadMauchCylinder(kRoot + "/models/" + file); }

// The three speeds of studies/mauch2014-bench.yaml: train on normal, validate on slow and fast.
Data makeData(const MauchCylinderParams& truth, std::uint64_t seed) {
  auto profile = [](double strideTime, double scale) {
    BenchProfileParams p;
    p.strideTime = strideTime;
    p.amplitudeScale = scale;
    return p;
  };
  Data d;
  d.validate.push_back(makeSyntheticBench(truth, stride(), profile(1.19, 0.9), kNoise, seed, "slow"));
  d.train.push_back(makeSyntheticBench(truth, stride(), profile(0.987, 1.0), kNoise, seed + 1, "normal"));
  d.validate.push_back(makeSyntheticBench(truth, stride(), profile(0.96, 1.05), kNoise, seed + 2, "fast"));
  return d;
}

// A hidden effect of the truth: its name, the model it is added to, the base model the
// diagnosis starts from, and the parameter values to recover (name -> truth).
struct Hidden {
  std::string effect;
  MauchCylinderParams truth;
  MauchCylinderParams base;
  std::vector<std::pair<std::string, double>> parameters;
};

Hidden makeHidden(const std::string& effect, double scale) {
  Hidden h{effect, model("mauch-4phase.yaml"), model("mauch-4phase.yaml"), {}};
  auto& e = h.truth.effects;
  if (effect == "coulomb_friction") {
    e.coulombFriction = true;
    e.coulombForce = 100 * scale;
    e.coulombWidth = 0.01;  // on the profiling grid
    h.parameters = {{"force_N", e.coulombForce}, {"width_m_per_s", e.coulombWidth}};
  } else if (effect == "orifice_quadratic") {
    e.orificeQuadratic = true;
    e.orificeCoefficient = 8000 * scale;
    h.parameters = {{"coefficient_Ns2_per_m2", e.orificeCoefficient}};
  } else if (effect == "inertia") {
    e.inertia = true;
    e.pistonMass = 60 * scale;
    h.parameters = {{"mass_kg", e.pistonMass}};
  } else if (effect == "position_dependent_damping") {
    e.positionDependentDamping = true;
    e.positionDamping = 1e5 * scale;
    h.parameters = {{"coefficient_Ns_per_m2", e.positionDamping}};
  } else if (effect == "hyperextension_phase") {
    // Chien's 4th phase hidden from a 2-phase model: Table 1's phase 4.
    h.truth = model("mauch-2phase.yaml");
    h.base = h.truth;
    h.truth.effects.hyperextensionPhase = true;
    h.truth.effects.hyperextension = {-488.12 * scale, 563313 * scale, 14672.2 * scale};
    h.parameters = {{"f_N", -488.12 * scale}, {"k_N_per_m", 563313 * scale}, {"c_Ns_per_m", 14672.2 * scale}};
  } else if (effect == "switch_delay") {
    const double tau = 0.05 * scale;  // scale 1 or 2 keeps it on the profiling grid
    h.truth.switches.latchRate = 1.0 / tau;
    h.parameters = {{"time_constant_s", tau}};
  }
  return h;
}

// Runs the diagnosis and checks its three claims for a hidden effect: named first, its
// parameters inside their intervals, and the validation error down to the noise floor.
void expectRecovered(const Hidden& h, std::uint64_t seed) {
  const Data d = makeData(h.truth, seed);
  const double size = calcCylinderEffectRms(h.truth, effectId(h.effect), d.train.front());
  ASSERT_GE(size, kMinEffectToNoise * kNoise) << h.effect << ": the test's effect is too small to demand recovery";
  const Diagnosis dg = diagnose(h.base, d);
  ASSERT_FALSE(dg.steps.empty());
  const auto& first = dg.steps.front();
  ASSERT_GE(first.chosen, 0) << h.effect << " (" << size << " N RMS): nothing accepted";
  EXPECT_NE(std::find(first.group.begin(), first.group.end(), h.effect), first.group.end())
      << h.effect << ": first accepted " << first.candidates[static_cast<std::size_t>(first.chosen)].effect;
  // The hidden effect's own score in the first step: its parameters inside their 95 % CIs.
  for (const auto& c : first.candidates) {
    if (c.effect != h.effect) continue;
    for (const auto& [name, truth] : h.parameters) {
      const auto p = std::find_if(c.parameters.begin(), c.parameters.end(),
                                  [&](const EffectParameter& q) { return q.name == name; });
      ASSERT_NE(p, c.parameters.end()) << name;
      const bool grid = name == "width_m_per_s" || name == "time_constant_s";
      const double w = grid ? 1.0 : kCheckedIntervalWidening;
      const double lower = p->value - w * (p->value - p->lower), upper = p->value + w * (p->upper - p->value);
      EXPECT_LE(lower, truth) << h.effect << " " << name << " = " << p->value << " [" << p->lower << ", " << p->upper
                              << "]";
      EXPECT_GE(upper, truth) << h.effect << " " << name << " = " << p->value << " [" << p->lower << ", " << p->upper
                              << "]";
    }
  }
  const Comparison after = CylinderPlant(h.base, d.train, d.validate).compare(*dg.final.model);
  for (const auto& r : after.records)
    EXPECT_LE(r.overall.rmse, kNoiseFloorTolerance * kNoise) << h.effect << " " << r.stem;
  std::printf("  %-27s size %6.1f N RMS: accepted", h.effect.c_str(), size);
  for (const auto& a : dg.accepted) std::printf(" %s", a.c_str());
  std::printf("; validation RMSE");
  for (const auto& r : after.records)
    if (!r.training) std::printf(" %s %.1f N", r.stem.c_str(), r.overall.rmse);
  std::printf("\n");
}

TEST(CylinderDiagnosis, EveryHiddenEffectIsFoundWithItsParameterAndTheErrorFallsToTheNoise) {
  for (const auto& name : effectNames(PlantKind::kCylinder)) expectRecovered(makeHidden(name, 1.0), 101);
}

TEST(CylinderDiagnosis, NullDataWithoutAHiddenEffectGiveAtMostOneFalseAcceptance) {
  const auto truth = model("mauch-4phase.yaml");
  int falseAcceptances = 0, falseAlarms = 0;
  for (int s = 0; s < kNullSeeds; ++s) {
    const Data d = makeData(truth, 5000 + 10 * static_cast<std::uint64_t>(s));
    const Diagnosis dg = diagnose(truth, d);
    // Nothing hidden: what remains is the noise, estimated from the data (25 N).
    EXPECT_NEAR(dg.pooledNoise.sigma, kNoise, 0.15 * kNoise) << "null seed " << s;
    // A verdict of "not explained" on null data is a false alarm of the whiteness test at
    // alpha (1 %): counted against the same bound as false acceptances.
    if (!dg.explained) {
      ++falseAlarms;
      std::printf("  null seed %d: %s\n", s, dg.verdict.c_str());
    }
    if (!dg.accepted.empty()) {
      ++falseAcceptances;
      std::printf("  null seed %d: falsely accepted %s\n", s, dg.accepted.front().c_str());
    }
  }
  std::printf("  null: %d false acceptance(s) in %d seeds\n", falseAcceptances, kNullSeeds);
  EXPECT_LE(falseAcceptances, kMaxFalseAcceptances);
  EXPECT_LE(falseAlarms, kMaxFalseAcceptances);
}

// Effect, size (3 to 6 noise RMS) and noise seed drawn from a fixed master seed (printed on
// failure); SWINGSIM_BLIND_SEED draws others. Thresholds: the EffectSelectionSettings defaults.
TEST(CylinderDiagnosis, BlindDrawIsRecovered) {
  constexpr std::uint64_t kMasterSeed = 20261123;
  std::uint64_t master = kMasterSeed;
  if (const char* env = std::getenv("SWINGSIM_BLIND_SEED")) master = std::strtoull(env, nullptr, 10);
  SCOPED_TRACE("blind test master seed " + std::to_string(master) +
               " (replay: SWINGSIM_BLIND_SEED=" + std::to_string(master) + ")");
  std::mt19937_64 rng(master);
  const auto lib = effectNames(PlantKind::kCylinder);
  constexpr int kDraws = 2;
  for (int k = 0; k < kDraws; ++k) {
    const std::string effect = lib[rng() % lib.size()];
    const std::uint64_t seed = rng() % 1000000;
    // Scale the effect to a random 3..6 x noise RMS (fixed-point iteration: the added
    // hyperextension phase's size is not proportional to its coefficients); switch_delay:
    // a time constant on the grid whose size is above 3 x noise.
    const double target = kNoise * (kMinEffectToNoise + 3.0 * std::uniform_real_distribution<double>(0, 1)(rng));
    double scale = 1.0;
    const BenchData probe = makeData(makeHidden(effect, 1.0).truth, seed).train.front();
    for (int it = 0; it < 8 && effect != "switch_delay"; ++it)
      scale *= target / calcCylinderEffectRms(makeHidden(effect, scale).truth, effectId(effect), probe);
    if (effect == "switch_delay") scale = (rng() % 2) ? 1.0 : 2.0;
    std::printf("  blind draw %d: %s x %.3g, seed %llu\n", k, effect.c_str(), scale,
                static_cast<unsigned long long>(seed));
    expectRecovered(makeHidden(effect, scale), seed);
  }
}

TEST(CylinderDiagnosis, ResidualStructureOutsideTheLibraryIsReportedNotClaimed) {
  // Truth: the latch releases on a different hyperextension threshold than the model's
  // (xhy 1.5 mm): an effect the library has no name for. Candidates limited to those that
  // cannot represent it.
  auto truth = model("mauch-4phase.yaml");
  truth.switches.hyperextensionPosition = 0.0015;
  const Data d = makeData(truth, 77);
  EffectSelectionSettings s;
  s.candidates = {"inertia", "orifice_quadratic"};
  const Diagnosis dg = diagnose(model("mauch-4phase.yaml"), d, s);
  EXPECT_TRUE(dg.accepted.empty());
  EXPECT_FALSE(dg.finalResidualWhite);
  EXPECT_NE(dg.structureNote.find("largest share of squared force error"), std::string::npos) << dg.structureNote;
  // The verdict says so in words: not explained, where it remains, what was tried.
  EXPECT_FALSE(dg.explained);
  EXPECT_EQ(dg.verdict.rfind("NOT explained", 0), 0u) << dg.verdict;
  EXPECT_NE(dg.verdict.find("Tried on top of the final model: inertia, orifice_quadratic"), std::string::npos)
      << dg.verdict;
}

TEST(CylinderDiagnosis, AugmentedModelRoundTripsThroughTheModelYamlAndActsAsAKneeLaw) {
  Hidden h = makeHidden("orifice_quadratic", 1.0);
  h.truth.effects.coulombFriction = true;
  h.truth.effects.coulombForce = 12.5;
  h.truth.effects.positionDamping = 3e4;
  h.truth.effects.positionDependentDamping = true;
  KneeModelSpec spec = loadKneeModel(kRoot + "/models/mauch-4phase.yaml").spec;
  spec.name = "roundtrip";
  MauchKnee& mauch = std::get<MauchKnee>(spec.kind);
  mauch.cylinder = h.truth;
  mauch.hasCylinderEffects = true;
  MauchDialSetting setting{mauch.flexionDial, mauch.extensionDial, {}};
  for (int i = 0; i < h.truth.phases; ++i)
    setting.rows.push_back({i + 1, h.truth.coefficients[static_cast<std::size_t>(i)]});
  mauch.settings = {setting};
  const std::string yaml = formatKneeModelYaml(spec);
  const KneeModel km = parseKneeModel(yaml, "roundtrip.yaml");
  ASSERT_EQ(km.law.size(), 2u);  // cylinder, then the hyperextension stop
  const auto* cyl = dynamic_cast<const MauchCylinder*>(&km.law.part(0));
  ASSERT_NE(cyl, nullptr);
  EXPECT_EQ(cyl->getCoefficientVector(), MauchCylinder(h.truth).getCoefficientVector());
  // As a knee law: moment = -F dx/dtheta with the added terms in F (inertia excepted).
  const KneeKinematics knee{0.5, 3.0};
  const double z = 1.0;
  const double x = cyl->geometry().calcPistonPosition(knee.flexion);
  const double arm = cyl->geometry().calcMomentArm(knee.flexion);
  EXPECT_DOUBLE_EQ(cyl->calcMoment(knee, &z), -MauchCylinder(h.truth).calcForce(x, arm * knee.flexionRate, z) * arm);
}

TEST(CylinderDiagnosis, UnknownCandidateAndMissingValidationAreInputErrors) {
  const auto truth = model("mauch-4phase.yaml");
  const Data d = makeData(truth, 3);
  EffectSelectionSettings s;
  s.candidates = {"magic_damping"};
  EXPECT_THROW(diagnose(truth, d, s), InputError);
  EXPECT_THROW(runDiagnosis(CylinderPlant(truth, d.train, {}), {}), InputError);
}

}  // namespace
}  // namespace swingsim

namespace swingsim {
namespace {

// The cylinder plant names every fitted constant (an added effect's as "effect.constant")
// and gives their correlation, so the engine's confound rule applies to the cylinder too.
TEST(CylinderPlantFit, NamesEveryConstantAndGivesTheirCorrelation) {
  const MauchCylinderParams base = model("mauch-4phase.yaml");
  MauchCylinderParams truth = base;
  truth = addCylinderEffect(truth, EffectId::kOrificeQuadratic, 0.0);
  truth.effects.orificeCoefficient = 8000;
  const Data d = makeData(truth, 41);
  const CylinderPlant plant(base, d.train, d.validate);
  const PlantFit fit = plant.fit(*plant.addEffect(CylinderModel(base), EffectId::kOrificeQuadratic, 0.0));
  const auto n = static_cast<Eigen::Index>(fit.parameterNames.size());
  ASSERT_EQ(n, static_cast<Eigen::Index>(3 * base.phases + 1));
  ASSERT_EQ(fit.correlation.rows(), n);
  int effectParameters = 0;
  for (const auto& name : fit.parameterNames) {
    if (name.find('.') == std::string::npos) continue;
    EXPECT_EQ(name.rfind("orifice_quadratic.", 0), 0u) << name;
    ++effectParameters;
  }
  EXPECT_EQ(effectParameters, 1);
  for (Eigen::Index i = 0; i < n; ++i) {
    EXPECT_NEAR(fit.correlation(i, i), 1.0, 1e-9);
    for (Eigen::Index j = 0; j < n; ++j) {
      EXPECT_NEAR(fit.correlation(i, j), fit.correlation(j, i), 1e-9);
      EXPECT_LE(std::abs(fit.correlation(i, j)), 1.0 + 1e-9);
    }
  }
}

}  // namespace
}  // namespace swingsim

namespace swingsim {
namespace {

// After switch_delay is accepted the refit frees the latch rate with the switch constants
// (fit_switches off for the baseline), reports them as base parameters and can hold each one
// for its profile likelihood.
TEST(CylinderPlantRefit, SwitchDelayRefitFreesTheLatchRateAndCanHoldEachSwitchConstant) {
  const MauchCylinderParams base = model("mauch-4phase.yaml");
  MauchCylinderParams truth = base;
  truth.switches.latchRate = 1.0 / 0.03;  // s: between the grid's 20 and 50 ms
  const Data d = makeData(truth, 61);
  const CylinderPlant plant(base, d.train, d.validate);
  const PlantFit candidate = plant.fit(*plant.addEffect(CylinderModel(base), EffectId::kSwitchDelay, 0.02));
  EXPECT_FALSE(plant.calcHeldParameterRss(*candidate.model, "latch_rate_per_s", 40.0)) << "its switches are held";
  const PlantFit refit = plant.refitAccepted(candidate, EffectId::kSwitchDelay);
  EXPECT_LE(refit.rss, candidate.rss);
  std::vector<std::string> names;
  for (const auto& p : refit.baseParameters) names.push_back(p.name);
  EXPECT_EQ(names, (std::vector<std::string>{"velocity_width_m_per_s", "position_width_m", "hyperextension_position_m",
                                             "latch_rate_per_s"}));
  const double k = cylinderParams(*refit.model).switches.latchRate;
  EXPECT_NE(k, 1.0 / 0.02) << "the latch rate is fitted, not left at the candidate's grid value";
  // Held at its own value the RSS is the refit's; held away from it, larger.
  const auto atFit = plant.calcHeldParameterRss(*refit.model, "latch_rate_per_s", k);
  ASSERT_TRUE(atFit);
  EXPECT_NEAR(*atFit, refit.rss, 1e-3 * refit.rss);
  const auto away = plant.calcHeldParameterRss(*refit.model, "latch_rate_per_s", 3.0 * k);
  ASSERT_TRUE(away);
  EXPECT_GT(*away, refit.rss);
  EXPECT_FALSE(plant.calcHeldParameterRss(*refit.model, "phase 1 f_N", 0.0));
  // Later candidates keep the freed constants free.
  const PlantFit next = plant.fit(*plant.addEffect(*refit.model, EffectId::kInertia, 0.0));
  EXPECT_EQ(next.baseParameters.size(), 4u);
}

// The linear effects' candidate fit is already joint: the refit keeps it.
TEST(CylinderPlantRefit, LinearEffectKeepsItsCandidateFit) {
  const MauchCylinderParams base = model("mauch-4phase.yaml");
  const Data d = makeData(base, 62);
  const CylinderPlant plant(base, d.train, d.validate);
  const PlantFit candidate = plant.fit(*plant.addEffect(CylinderModel(base), EffectId::kOrificeQuadratic, 0.0));
  const PlantFit refit = plant.refitAccepted(candidate, EffectId::kOrificeQuadratic);
  EXPECT_EQ(refit.model, candidate.model);
  EXPECT_TRUE(refit.baseParameters.empty());
}

}  // namespace
}  // namespace swingsim
