// The calibration study (diagnosis_calibration.h) on a small fixed seed set, holding its
// summary: the hidden effect named, its 95 % interval holding the truth as often as a 95 %
// interval must, its estimate unbiased, and nulls accepting nothing. The seeds are fixed, so
// the outcome is deterministic; the bounds are what a method with the study's rates passes
// except with a small probability, from the binomial distribution (said at each). The full
// table (20 seeds a case): scripts/diagnosis-calibration.sh, docs/diagnosis.md.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "../cli/release_only.h"
#include "../identify/diagnosis_calibration.h"

namespace swingsim {
namespace {

using calibration::CalibrationCase;
using calibration::CaseSummary;

constexpr std::uint64_t kFirstSeed = 1;
constexpr int kSeeds = 6;
// A 95 % interval holds the truth in at least 4 of 6 seeds except with probability
// P(Binomial(6, 0.95) <= 3) = 0.0022.
constexpr int kMinCovered = 4;
// Named in at least 4 of 6 when the study measured it named in 20 of 20 (a rate of 0.95 or
// more misses this with probability <= 0.0022, as above).
constexpr int kMinNamed = 4;
// A null accepts something in at most 1 of 6: the rule's family-wise alpha is 0.01, and
// P(Binomial(6, 0.01) >= 2) = 0.0015.
constexpr int kMaxFalseAcceptances = 1;

CalibrationCase findCase(const std::string& plant, const std::string& effect) {
  for (const auto& c : calibration::calibrationCases())
    if (c.plant == plant && c.effect == effect) return c;
  throw std::logic_error("no calibration case " + plant + "/" + effect);
}

CaseSummary runSummary(const CalibrationCase& c) {
  const CaseSummary s = calibration::summarize(c, calibration::runCase(c, kFirstSeed, kSeeds, 1));
  std::printf("  %s/%s: named %d, other %d, covered %d of %d, bias %.4g, SD %.4g\n", c.plant.c_str(),
              c.effect.empty() ? "null" : c.effect.c_str(), s.named, s.other, s.covered, s.scored, s.bias, s.sd);
  return s;
}

// The case: friction 0.5 N m as sharp as tanh smoothing 0.3 rad/s. With the grid
// ending at 0.5 rad/s the moment came out +14 % (+23 % in the probe) and its interval
// undercovered; the target is a bias within +-10 %.
TEST(DiagnosisCalibration, SharpCoulombFrictionIsNamedCoveredAndWithinTenPercent) {
  SWINGSIM_RELEASE_ONLY();
  const CalibrationCase c = findCase("swing", "knee_coulomb_friction");
  const CaseSummary s = runSummary(c);
  EXPECT_GE(s.named, kMinNamed);
  EXPECT_EQ(s.scored, kSeeds);
  EXPECT_GE(s.covered, kMinCovered);
  EXPECT_LT(std::abs(s.bias), 0.1 * c.truth);
}

// Viscous damping on a knee whose extension resistance is half its flexion resistance (on a
// symmetric linear table it is the knee model scale itself).
TEST(DiagnosisCalibration, ViscousDampingIsNamedAndCovered) {
  SWINGSIM_RELEASE_ONLY();
  const CalibrationCase c = findCase("swing", "knee_viscous_damping");
  const CaseSummary s = runSummary(c);
  EXPECT_GE(s.named, kMinNamed);
  EXPECT_GE(s.covered, kMinCovered);
}

TEST(DiagnosisCalibration, SwingNullsAcceptNothing) {
  SWINGSIM_RELEASE_ONLY();
  const CaseSummary s = runSummary(findCase("swing", ""));
  EXPECT_LE(s.other, kMaxFalseAcceptances);
}

// Issue 54's near misses: a deep-flexion stiffening outside the library with only the fast
// swing held out. Without the record rules a library effect is accepted first in most seeds
// (the case is a near miss: asserted, so the test keeps its teeth); with them, at most one of
// six seeds accepts anything, as a null.
TEST(DiagnosisCalibration, NearMissesOutsideTheLibraryAcceptNothing) {
  SWINGSIM_RELEASE_ONLY();
  for (const auto& c : calibration::calibrationCases()) {
    if (c.effect != "outside:stiffening") continue;
    const CaseSummary s = runSummary(c);
    std::printf("    %s: before the record rules %d of %d accepted a library effect\n", c.size.c_str(), s.beforeOther,
                s.seeds);
    EXPECT_GE(s.beforeOther, kMinNamed) << c.size;
    EXPECT_LE(s.other, kMaxFalseAcceptances) << c.size;
  }
}

// The bench: seal friction 60 N at a tanh width of 7 mm/s (between the width grid's 5 and
// 10 mm/s) on drawn switch constants refitted from scratch.
TEST(DiagnosisCalibration, BenchCoulombFrictionIsNamedCoveredAndUnbiased) {
  SWINGSIM_RELEASE_ONLY();
  const CalibrationCase c = findCase("cylinder", "coulomb_friction");
  const CaseSummary s = runSummary(c);
  EXPECT_GE(s.named, kMinNamed);
  EXPECT_GE(s.covered, kMinCovered);
  EXPECT_LT(std::abs(s.bias), 0.1 * c.truth);
}

// The report's advice for switch_delay: with one training record the latch rate's interval
// held the truth in 15 of 19 seeds; trained on normal and fast, in 19 of 20 (and named in 20
// of 20), so a method with those rates passes these bounds.
TEST(DiagnosisCalibration, SwitchDelayTrainedOnTwoSpeedsIsNamedAndCovered) {
  SWINGSIM_RELEASE_ONLY();
  const std::string twoSpeeds = "trained on normal and fast";
  for (const auto& c : calibration::calibrationCases()) {
    if (c.effect != "switch_delay" || c.size.find(twoSpeeds) == std::string::npos) continue;
    const CaseSummary s = runSummary(c);
    EXPECT_GE(s.named, kMinNamed);
    EXPECT_GE(s.covered, kMinCovered);
    return;
  }
  FAIL() << "no switch_delay case " << twoSpeeds;
}

TEST(DiagnosisCalibration, BenchNullsAcceptNothing) {
  SWINGSIM_RELEASE_ONLY();
  const CaseSummary s = runSummary(findCase("cylinder", ""));
  EXPECT_LE(s.other, kMaxFalseAcceptances);
}

}  // namespace
}  // namespace swingsim
