#include "identify/swing_plant.h"
#include "io/knee_model_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "../cli/release_only.h"
#include "core/input_error.h"
#include "identify/synthetic_swing.h"
#include "io/participant_loader.h"
#include "report/diagnosis_report.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;
constexpr double kNoise = 0.5;  // deg on hip and knee: marker-based angles (studies/diagnose-demo-swing-data.yaml)
// The diagnosis's claim: hidden effects of at least 3 noise RMS must be found...
constexpr double kMinEffectToNoise = 3.0;
// ...and the final validation RMSE must come within 15 % of the noise floor.
constexpr double kNoiseFloorTolerance = 1.15;
constexpr int kNullSeeds = 20;
constexpr int kMaxFalseAcceptances = 1;
// As in the cylinder tests: the blind draw checks the 99.9 % interval (same standard error).
constexpr double kCheckedIntervalWidening = 3.2905 / 1.9600;

const SwingBase& base() {
  static const SwingBase b = [] {
    SwingBase s;
    s.participant = loadParticipant(kRoot + "/participants/p1.yaml");
    s.knee = loadKneeModel(kRoot + "/models/damping-table-default.yaml");
    return s;
  }();
  return b;
}

struct Data {
  std::vector<SwingRecord> train, validate;
};

EffectId effectId(const std::string& name) { return findEffect(PlantKind::kSwing, name)->id; }

Diagnosis diagnose(const Data& d, const EffectSelectionSettings& settings = {}) {
  return runDiagnosis(SwingPlant(base(), d.train, d.validate), settings);
}

// Three walking speeds: train on normal, validate on slow and fast.
Data makeData(const SwingModelParams& truth, std::uint64_t seed) {
  Data d;
  d.validate.push_back(makeSyntheticSwing(base(), truth, {"slow", 1.12, 0.85}, kNoise, seed));
  d.train.push_back(makeSyntheticSwing(base(), truth, {"normal", 1.0, 1.0}, kNoise, seed + 1));
  d.validate.push_back(makeSyntheticSwing(base(), truth, {"fast", 0.9, 1.15}, kNoise, seed + 2));
  return d;
}

struct Hidden {
  std::string effect;
  SwingModelParams truth;
  std::vector<std::pair<std::string, double>> parameters;  // name -> truth
};

Hidden hidden(const std::string& effect, double size) {
  Hidden h{effect, addSwingEffect({}, effectId(effect), 1.0), {}};
  auto& e = h.truth.effects;
  if (effect == "knee_coulomb_friction") {
    e.knee.coulombMoment = 1.0 * size;
    h.parameters = {{"moment_Nm", e.knee.coulombMoment}};
  } else if (effect == "knee_viscous_damping") {
    e.knee.viscousDamping = 0.15 * size;
    h.parameters = {{"damping_Nm_s_per_rad", e.knee.viscousDamping}};
  } else if (effect == "extension_assist_spring") {
    e.knee.assistStiffness = 0.6 * size;
    h.parameters = {{"stiffness_Nm_per_rad", e.knee.assistStiffness}};
  } else if (effect == "toe_off_velocity") {
    e.toeOffHipRate = 1.0 * size;
    e.toeOffKneeRate = 2.5 * size;
    h.parameters = {{"hip_rate_deg_s", e.toeOffHipRate * kRadToDeg}, {"knee_rate_deg_s", e.toeOffKneeRate * kRadToDeg}};
  } else if (effect == "hip_moment_scale") {
    e.hipMomentScale = 1.0 + 0.1 * size;
    h.parameters = {{"scale", e.hipMomentScale}};
  } else if (effect == "socket_compliance") {
    // A loose socket (docs/socket.md): far softer and less damped than MyoSuite's 350 and 175.
    e.socket.rotationStiffness = 120.0 / size;
    e.socket.rotationDamping = 6.0 / size;
    h.parameters = {{"rotation_stiffness_Nm_per_rad", e.socket.rotationStiffness},
                    {"rotation_damping_Nm_s_per_rad", e.socket.rotationDamping}};
  } else if (effect == "below_knee_mass_scale") {
    e.belowKneeMassScale = 1.0 + 0.3 * size;
    h.parameters = {{"scale", e.belowKneeMassScale}};
  } else {
    e.shankMassScale = 1.0 + 0.5 * size;
    h.parameters = {{"scale", e.shankMassScale}};
  }
  return h;
}

void printDiagnosis(const Diagnosis& dg) {
  for (std::size_t s = 0; s < dg.steps.size(); ++s) {
    std::vector<const EffectScore*> scores;
    for (const auto& c : dg.steps[s].candidates) scores.push_back(&c);
    std::printf("step %zu (train %.3f deg)\n%s", s + 1, dg.steps[s].currentTrainRmse,
                formatCandidateRanking(scores, "deg", 2).c_str());
  }
  for (const auto& c : dg.acceptedScores) std::printf("%s", formatAcceptedEffect(c, "").c_str());
}

// First accepted effect is the hidden one (or its ambiguity group holds it), its parameters
// lie in their intervals (widened by `widen`), and validation RMSE is at the noise floor.
void expectRecovered(const Hidden& h, const Diagnosis& dg, double widen) {
  ASSERT_FALSE(dg.steps.empty());
  const auto& first = dg.steps.front();
  ASSERT_GE(first.chosen, 0) << "nothing accepted for hidden " << h.effect;
  EXPECT_TRUE(std::find(first.group.begin(), first.group.end(), h.effect) != first.group.end())
      << "hidden " << h.effect << ", first accepted " << first.group.front();
  const auto& c = dg.acceptedScores.front();
  if (c.effect == h.effect) {
    for (const auto& [name, truth] : h.parameters) {
      const auto p = std::find_if(c.parameters.begin(), c.parameters.end(),
                                  [&](const EffectParameter& q) { return q.name == name; });
      ASSERT_NE(p, c.parameters.end()) << name;
      const double half = 0.5 * (p->upper - p->lower) * widen, mid = 0.5 * (p->upper + p->lower);
      EXPECT_LE(std::abs(truth - mid), half) << h.effect << " " << name << " truth " << truth << " fitted " << p->value
                                             << " CI " << p->lower << " .. " << p->upper;
    }
  }
  const auto& last = dg.steps.back();
  for (double v : last.currentValidationRmse.empty() ? c.validationRmse : last.currentValidationRmse)
    EXPECT_LE(v, kNoiseFloorTolerance * kNoise) << h.effect;
}

TEST(SwingDiagnosis, EveryHiddenEffectIsFoundWithItsParameterAndTheErrorFallsToTheNoise) {
  SWINGSIM_RELEASE_ONLY();  // 50-180 s under the sanitizers
  for (const auto& name : effectNames(PlantKind::kSwing)) {
    const Hidden h = hidden(name, 1.0);
    const Data d = makeData(h.truth, 101);
    const double size = calcSwingEffectRms(base(), h.truth, effectId(h.effect), d.train.front());
    ASSERT_GE(size, kMinEffectToNoise * kNoise) << h.effect << ": the test's effect is too small";
    const Diagnosis dg = diagnose(d);
    std::printf("  %-24s size %.2f deg RMS: accepted %s\n", h.effect.c_str(), size,
                dg.accepted.empty() ? "none" : dg.accepted.front().c_str());
    expectRecovered(h, dg, 1.0);
  }
}

TEST(SwingDiagnosis, UnderTheThighDriveTheSocketIsNotACandidateAndAParticipantsSocketIsWarnedOf) {
  const Data d = makeData({}, 7);
  SwingBase thighDriven = base();
  thighDriven.drive = SwingDrive::kThighKinematics;
  const SwingPlant rigid(thighDriven, d.train, {});
  EXPECT_NE(rigid.checkApplicable(*rigid.baseModel(), EffectId::kSocketCompliance).find("markers sit on the socket"),
            std::string::npos);
  EXPECT_TRUE(rigid.warnings().empty());
  thighDriven.participant.socket = SocketCompliance{};
  const SwingPlant withSocket(thighDriven, d.train, {});
  ASSERT_EQ(withSocket.warnings().size(), 1u);
  EXPECT_NE(withSocket.warnings().front().find("counted twice"), std::string::npos);
  // Driven by the hip moment, the socket is a candidate.
  const SwingPlant hipDriven(base(), d.train, {});
  EXPECT_EQ(hipDriven.checkApplicable(*hipDriven.baseModel(), EffectId::kSocketCompliance), "");
}

TEST(SwingDiagnosis, NullDataAcceptNothingInAtLeastNineteenOfTwentySeeds) {
  SWINGSIM_RELEASE_ONLY();  // 50-180 s under the sanitizers
  int falseAcceptances = 0, falseAlarms = 0;
  for (int seed = 0; seed < kNullSeeds; ++seed) {
    const Data d = makeData({}, 5000 + 10 * static_cast<std::uint64_t>(seed));
    EffectSelectionSettings s;
    s.maxEffects = 1;  // a first acceptance is already the failure being counted
    const Diagnosis dg = diagnose(d, s);
    EXPECT_NEAR(dg.pooledNoise.sigma, kNoise, 0.15 * kNoise) << "null seed " << seed;
    if (!dg.explained) {  // a false alarm of the whiteness test at alpha, as in the cylinder test
      ++falseAlarms;
      std::printf("  null seed %d: %s\n", seed, dg.verdict.c_str());
    }
    if (!dg.accepted.empty()) {
      ++falseAcceptances;
      std::printf("  null seed %d: falsely accepted %s\n", seed, dg.accepted.front().c_str());
    }
    // Nothing hidden: the knee model scale is 1 within its interval.
    ASSERT_EQ(dg.baselineParameters.size(), 1u);
    EXPECT_EQ(dg.baselineParameters.front().name, "knee_model_scale");
    EXPECT_LE(dg.baselineParameters.front().lower, 1.0 + 1e-3);
    EXPECT_GE(dg.baselineParameters.front().upper, 1.0 - 1e-3);
  }
  std::printf("  null: %d false acceptances in %d seeds\n", falseAcceptances, kNullSeeds);
  EXPECT_LE(falseAcceptances, kMaxFalseAcceptances);
  EXPECT_LE(falseAlarms, kMaxFalseAcceptances);
}

// Effect, size (1 to 2 x the test sizes, >= 3 x noise) and seed drawn from a fixed master
// seed (printed on failure); SWINGSIM_BLIND_SEED draws others. Thresholds: the defaults.
TEST(SwingDiagnosis, BlindDrawIsRecovered) {
  constexpr std::uint64_t kMasterSeed = 20261123;
  const char* env = std::getenv("SWINGSIM_BLIND_SEED");
  const std::uint64_t master = env ? std::strtoull(env, nullptr, 10) : kMasterSeed;
  SCOPED_TRACE("SWINGSIM_BLIND_SEED=" + std::to_string(master));
  std::mt19937_64 rng(master);
  const auto lib = effectNames(PlantKind::kSwing);
  const std::string effect = lib[std::uniform_int_distribution<std::size_t>(0, lib.size() - 1)(rng)];
  const double size = std::uniform_real_distribution<double>(1.0, 2.0)(rng);
  const std::uint64_t seed = std::uniform_int_distribution<std::uint64_t>(1, 1000000)(rng);
  std::printf("  blind: %s x %.3g, seed %llu (master %llu)\n", effect.c_str(), size,
              static_cast<unsigned long long>(seed), static_cast<unsigned long long>(master));
  const Hidden h = hidden(effect, size);
  const Data d = makeData(h.truth, seed);
  ASSERT_GE(calcSwingEffectRms(base(), h.truth, effectId(effect), d.train.front()), kMinEffectToNoise * kNoise);
  expectRecovered(h, diagnose(d), kCheckedIntervalWidening);
}

// Confound: whole-range Coulomb friction with a wide smoothing (5 rad/s, the top of the
// grid) against viscous damping, on swings at ONE speed. Their knee sensitivities are
// nearly collinear (checked below); both explain the residual, neither adds anything on top
// of the other, and the report must say so with what data would separate them.
TEST(SwingDiagnosis, CoulombWithWideSmoothingAndViscousDampingAtOneSpeedAreReportedAmbiguous) {
  Hidden h = hidden("knee_coulomb_friction", 0.4);
  h.truth.effects.knee.coulombSmoothingRate = 5.0;
  Data d;
  d.train.push_back(makeSyntheticSwing(base(), h.truth, {"normal", 1.0, 1.0}, kNoise, 40));
  d.validate.push_back(makeSyntheticSwing(base(), h.truth, {"normal2", 1.0, 1.0}, kNoise, 41));
  // Correlation of the two knee sensitivities at the base model, along the training swing.
  const auto& r = d.train.front();
  const double hip0 = base().participant.initial.hipFlexion, knee0 = base().participant.initial.kneeFlexion;
  const auto ref = predictSwing(base(), {}, r, hip0, knee0, 1e-10);
  SwingModelParams a = addSwingEffect({}, EffectId::kKneeCoulombFriction, 5.0),
                   b = addSwingEffect({}, EffectId::kKneeViscousDamping, 0);
  a.effects.knee.coulombMoment = 0.01;
  b.effects.knee.viscousDamping = 0.01;
  const auto pa = predictSwing(base(), a, r, hip0, knee0, 1e-10), pb = predictSwing(base(), b, r, hip0, knee0, 1e-10);
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < r.time.size(); ++i) {
    const double da = pa.kneeFlexion[i] - ref.kneeFlexion[i], db = pb.kneeFlexion[i] - ref.kneeFlexion[i];
    sab += da * db;
    saa += da * da;
    sbb += db * db;
  }
  const double correlation = sab / std::sqrt(saa * sbb);
  std::printf("  knee sensitivity correlation, Coulomb (5 rad/s) vs viscous: %.4f\n", correlation);
  EXPECT_GT(correlation, 0.95);

  EffectSelectionSettings s;
  s.candidates = {"knee_coulomb_friction", "knee_viscous_damping"};
  s.maxEffects = 1;
  const Diagnosis dg = diagnose(d, s);
  printDiagnosis(dg);
  ASSERT_EQ(dg.ambiguous.size(), 1u);
  const auto& g = dg.ambiguous.front();
  EXPECT_TRUE(std::find(g.begin(), g.end(), "knee_coulomb_friction") != g.end());
  EXPECT_TRUE(std::find(g.begin(), g.end(), "knee_viscous_damping") != g.end());
  ASSERT_EQ(dg.ambiguityAdvice.size(), 1u);
  EXPECT_NE(dg.ambiguityAdvice.front().find("several speeds"), std::string::npos) << dg.ambiguityAdvice.front();
}

TEST(SwingDiagnosis, AddedKneeEffectsLoadFromAKneeModelYaml) {
  const KneeModel m = parseKneeModel(R"(kind: damping_table
damping_table: {flexion_deg: [0, 70], moment_Nm: [1, 1], speed_rule: constant}
knee_effects:
  coulomb_friction: {moment_Nm: 2, smoothing_deg_s: 57.29577951308232}
  viscous_damping: {damping_Nm_s_per_rad: 0.5}
  extension_assist_spring: {stiffness_Nm_per_rad: 3}
)",
                                     "inline.yaml");
  ASSERT_EQ(m.law.size(), 3u);  // table, added effects, stop
  const KneeKinematics k{0.5, 2.0};
  EXPECT_NEAR(m.law.calcPartMoment(1, k, nullptr), -2 * std::tanh(2.0) - 0.5 * 2.0 - 3 * 0.5, 1e-12);
  EXPECT_THROW(parseKneeModel("kind: damping_table\ndamping_table: {flexion_deg: [0, 70], moment_Nm: [1, 1]}\n"
                              "knee_effects: {viscous_damping: {damping_Nm_s_per_rad: -1}}\n",
                              "bad.yaml"),
               InputError);
}

TEST(SwingDiagnosis, UnknownCandidateAndMissingValidationAreInputErrors) {
  const Data d = makeData({}, 7);
  EffectSelectionSettings s;
  s.candidates = {"knee_teleportation"};
  EXPECT_THROW(diagnose(d, s), InputError);
  EXPECT_THROW(runDiagnosis(SwingPlant(base(), d.train, {}), {}), InputError);
}

}  // namespace
}  // namespace swingsim
