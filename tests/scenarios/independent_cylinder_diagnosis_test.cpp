// `diagnose` on bench files swingsim did not make (tests/independent/): switch constants
// drawn across their ranges and refitted from scratch (fit_switches), a hidden effect inside
// the library, none, or one outside it. The engine must name the right effect and reach the
// noise on held-out records, accept nothing on a null, and say "not explained" when the
// effect is not in its library.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "../cli/release_only.h"
#include "../identify/diagnosis_outcome.h"
#include "../independent/mauch_bench_generator.h"
#include "identify/cylinder_plant.h"
#include "identify/diagnosis_engine.h"
#include "io/bench_csv.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;

constexpr double kNoise = 15.0;  // N, as in the measurement that set this test up

struct Files {
  std::vector<BenchData> train, validate;
};

Files makeFiles(const independent::MauchTruth& truth, std::uint64_t seed, const std::string& tag) {
  const fs::path dir = fs::temp_directory_path() / ("swingsim-indep-dg-" + tag + "-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  Files out;
  std::uint64_t s = seed;
  for (const auto& g : independent::chienGaits()) {
    const std::string path = (dir / (g.name + ".csv")).string();
    independent::writeCsv(independent::generate(truth, g, kNoise, s++), path);
    (g.name == "normal" ? out.train : out.validate).push_back(readBenchCsv(path, 20));
  }
  fs::remove_all(dir);
  return out;
}

MauchCylinderParams startModel(int phases = 4) {
  MauchCylinderParams p;
  p.phases = phases;
  p.coefficients.assign(static_cast<std::size_t>(phases), {});
  p.initialLatch = 0.0;
  return p;
}

Diagnosis diagnose(const independent::MauchTruth& truth, std::uint64_t seed, const std::string& tag,
                   int basePhases = 4) {
  const Files f = makeFiles(truth, seed, tag);
  const CylinderPlant plant(startModel(basePhases), f.train, f.validate, /*fitSwitches=*/true);
  const Diagnosis dg = runDiagnosis(plant, {});
  testing::printOutcome(tag, dg, "N", kNoise);
  return dg;
}

using testing::worstHeldOut;

TEST(IndependentCylinderDiagnosis, OrificeFlowHiddenIsNamedAndExplained) {
  for (std::uint64_t seed : {11, 12}) {
    auto truth = independent::drawTruth(4, seed);
    truth.orifice = 4000.0;  // N s^2/m^2: about 40-90 N at swing piston speeds
    const Diagnosis dg = diagnose(truth, seed, "orifice-" + std::to_string(seed));
    ASSERT_FALSE(dg.accepted.empty());
    EXPECT_EQ(dg.accepted.front(), "orifice_quadratic");
    EXPECT_LT(worstHeldOut(dg), 1.2 * kNoise);
    EXPECT_TRUE(dg.explained) << dg.verdict;
  }
}

TEST(IndependentCylinderDiagnosis, NullAcceptsNothing) {
  for (std::uint64_t seed : {21, 22}) {
    const Diagnosis dg = diagnose(independent::drawTruth(4, seed), seed, "null-" + std::to_string(seed));
    EXPECT_TRUE(dg.accepted.empty()) << dg.accepted.front();
  }
}

// Oil and air compliance (the force lags its law by 25 ms) is not in the library: whatever the
// engine tries, it must not call the result explained, and must say so in words.
TEST(IndependentCylinderDiagnosis, EffectOutsideTheLibraryIsNotExplained) {
  auto truth = independent::drawTruth(4, 31);
  truth.complianceLag = 0.025;
  const Diagnosis dg = diagnose(truth, 31, "compliance");
  EXPECT_FALSE(dg.explained);
  EXPECT_EQ(dg.verdict.rfind("NOT explained", 0), 0u) << dg.verdict;
}

// After the right effect is accepted, the joint refit reaches the noise (issue 31).
constexpr double kHeldOutToNoise = 1.2;
constexpr int kRefitSeeds = 5;

// A balance-wheel latch about 250 times slower than Chien's k = 1e4 /s (time constant 25 ms,
// between the switch_delay grid's 20 and 50 ms), switch constants drawn across their ranges:
// once switch_delay is accepted, the refit frees the latch rate with the switch constants it
// couples to and must reach the noise. With one training speed, some drawn truths hide the
// latch from the training record (the fit at the true constants is no better there: a deep
// hold completes even a slow latch, and the phase coefficients absorb the rest): nothing may
// then be accepted, but no other effect either.
TEST(IndependentCylinderDiagnosis, SlowLatchReachesTheNoiseAfterTheJointRefit) {
  SWINGSIM_RELEASE_ONLY();
  int recovered = 0, hidden = 0;
  for (std::uint64_t seed = 41; recovered < kRefitSeeds && seed < 56; ++seed) {
    auto truth = independent::drawTruth(4, seed);
    truth.latchRate = 40.0;  // 1/s
    const Diagnosis dg = diagnose(truth, seed, "slow-latch-" + std::to_string(seed));
    if (dg.accepted.empty()) {
      ++hidden;
      continue;
    }
    ++recovered;
    EXPECT_EQ(dg.accepted.front(), "switch_delay") << "seed " << seed;
    std::printf("    seed %llu: worst held-out / noise %.3f\n", static_cast<unsigned long long>(seed),
                worstHeldOut(dg) / kNoise);
    EXPECT_LE(worstHeldOut(dg), kHeldOutToNoise * kNoise) << "seed " << seed;
    EXPECT_TRUE(dg.explained) << dg.verdict;
    // The latch rate is a fitted constant of the final model, with its interval.
    const auto k = std::find_if(dg.finalParameters.begin(), dg.finalParameters.end(),
                                [](const EffectParameter& p) { return p.name == "latch_rate_per_s"; });
    ASSERT_NE(k, dg.finalParameters.end()) << "seed " << seed;
    EXPECT_LE(k->lower, k->value);
    EXPECT_GE(k->upper, k->value);
  }
  std::printf("    slow latch: %d seeds recovered, %d with the latch hidden from the training record\n", recovered,
              hidden);
  EXPECT_EQ(recovered, kRefitSeeds);
}

// Chien's 4-phase truth diagnosed from the 2-phase model: hyperextension_phase is accepted and
// refitted as the 4-phase model it produces (the low-force phase split in two).
TEST(IndependentCylinderDiagnosis, FourPhaseTruthFromATwoPhaseBaseReachesTheNoise) {
  SWINGSIM_RELEASE_ONLY();
  for (std::uint64_t seed = 41; seed < 41 + kRefitSeeds; ++seed) {
    const auto truth = independent::drawTruth(4, seed);
    const Diagnosis dg = diagnose(truth, seed, "four-phase-" + std::to_string(seed), /*basePhases=*/2);
    ASSERT_FALSE(dg.accepted.empty()) << "seed " << seed;
    EXPECT_EQ(dg.accepted.front(), "hyperextension_phase") << "seed " << seed;
    EXPECT_EQ(cylinderParams(*dg.final.model).phases, 4) << "seed " << seed;
    std::printf("    seed %llu: worst held-out / noise %.3f\n", static_cast<unsigned long long>(seed),
                worstHeldOut(dg) / kNoise);
    EXPECT_LE(worstHeldOut(dg), kHeldOutToNoise * kNoise) << "seed " << seed;
    EXPECT_TRUE(dg.explained) << dg.verdict;
  }
}

}  // namespace
}  // namespace swingsim
