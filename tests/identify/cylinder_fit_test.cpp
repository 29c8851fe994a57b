#include "identify/cylinder_fit.h"
#include "io/bench_csv.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/input_error.h"
#include "mauch_bench_fixture.h"
#include "numerics/metrics.h"

namespace swingsim {
namespace {

// Noise-free data must give back the generating coefficients (rounding only).
constexpr double kRecoveryTol = 1e-6;
// With noise, each estimate within this many standard errors of the truth: the chance that
// one of 12 normal estimates falls outside 4 SE is 12 * 6.3e-5, under 0.1 %.
constexpr double kStandardErrorBound = 4.0;

using namespace mauch_bench_fixture;

TEST(CylinderFit, NoiseFreeDataRecoverTheGeneratingCoefficients) {
  for (const char* file : {"mauch-4phase.yaml", "mauch-2phase.yaml"}) {
    const auto truth = model(file);
    const auto fit = fitCylinder(truth, {makeBench(truth, 0.987, 1.0, 0.0, 1, "normal")});
    const auto expected = MauchCylinder(truth).getCoefficientVector();
    ASSERT_EQ(fit.regression.rank, static_cast<int>(expected.size()));
    for (std::size_t i = 0; i < expected.size(); ++i) {
      EXPECT_NEAR(fit.regression.coefficients[i], expected[i], kRecoveryTol * std::fabs(expected[i]))
          << file << " coefficient " << i;
    }
    EXPECT_TRUE(fit.warnings.empty());
  }
}

TEST(CylinderFit, NoisyDataRecoverCoefficientsWithinTheirStandardErrors) {
  const auto truth = model("mauch-4phase.yaml");
  const auto data = makeBench(truth, 0.987, 1.0, kNoise, 2014, "normal");
  const auto fit = fitCylinder(truth, {data});
  const auto expected = MauchCylinder(truth).getCoefficientVector();
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const double se = fit.regression.standardErrors[i];
    ASSERT_TRUE(std::isfinite(se) && se > 0);
    EXPECT_LT(std::fabs(fit.regression.coefficients[i] - expected[i]), kStandardErrorBound * se) << "coefficient " << i;
  }
  // The residual is the noise: RMS within 10 % of its standard deviation.
  EXPECT_NEAR(fit.regression.residualRms, kNoise, 0.1 * kNoise);
}

TEST(CylinderFit, TwoPhaseModelIsWorseOnValidationWithLargestErrorsEnteringHyperextension) {
  const auto truth = model("mauch-4phase.yaml");
  const auto normal = makeBench(truth, 0.987, 1.0, kNoise, 1, "normal");
  const std::vector<BenchData> validation = {makeBench(truth, 1.19, 0.9, kNoise, 2, "slow"),
                                             makeBench(truth, 0.96, 1.05, kNoise, 3, "fast")};
  const auto two = fitCylinder(model("mauch-2phase.yaml"), {normal});
  const auto four = fitCylinder(model("mauch-4phase.yaml"), {normal});
  // The fit puts the high damping in the 2-phase model's phase 1 (stance flexion).
  EXPECT_GT(two.params.coefficients[0].c, 5 * two.params.coefficients[1].c);
  for (const auto& d : validation) {
    const auto p2 = predictBench(MauchCylinder(two.params), d);
    const auto p4 = predictBench(MauchCylinder(four.params), d);
    const auto m2 = calcErrorMetrics(d.force, p2.force), m4 = calcErrorMetrics(d.force, p4.force);
    EXPECT_GT(m2.rmse, 2 * m4.rmse) << d.stem;
    EXPECT_LT(m2.r2, m4.r2) << d.stem;
    // Where: in the stance hyperextension episode the extension runs into (truth S8 < 0.5,
    // phase 4), or within 10 samples (28 ms at 361.4 Hz) of it. The paper: "the maximum error
    // occurred in the transition of knee extension to hyperextension" and "the hyperextension
    // mode ... is where the 2-phase model has the largest deviation".
    const auto tr = predictBench(MauchCylinder(truth), d);
    constexpr long kNearSamples = 10;
    bool inEpisode = false;
    for (long j = -kNearSamples; j <= kNearSamples; ++j) {
      const long i = static_cast<long>(m2.maxErrorIndex) + j;
      if (i >= 0 && i < static_cast<long>(d.time.size()) && tr.switches[static_cast<std::size_t>(i)].s8 < 0.5)
        inEpisode = true;
    }
    EXPECT_TRUE(inEpisode) << d.stem << ": largest 2-phase error at t = " << d.time[m2.maxErrorIndex];
    // And the 4-phase model's largest error is much smaller there.
    EXPECT_LT(m4.maxError, 0.25 * m2.maxError) << d.stem;
  }
}

TEST(CylinderFit, ProfilingSwitchesFindsTheGeneratingWidths) {
  auto truth = model("mauch-4phase.yaml");
  const auto start = truth;
  // Truth on grid points of the 9-point, factor-10 log grid (10^0.25 steps).
  truth.switches.positionWidth *= std::pow(10.0, 0.25);
  truth.switches.velocityWidth *= std::pow(10.0, 0.5);
  const auto data = makeBench(truth, 0.987, 1.0, 0.0, 1, "normal");
  CylinderFitOptions options;
  options.fitSwitches = true;
  const auto fit = fitCylinder(start, {data}, options);
  EXPECT_TRUE(fit.switchesFitted);
  EXPECT_NEAR(fit.params.switches.positionWidth, truth.switches.positionWidth, 1e-9 * truth.switches.positionWidth);
  EXPECT_NEAR(fit.params.switches.velocityWidth, truth.switches.velocityWidth, 1e-9 * truth.switches.velocityWidth);
  EXPECT_GT(fit.trainRmseAtStart, 1.0);         // wrong widths cost newtons ...
  EXPECT_LT(fit.regression.residualRms, 1e-6);  // ... the right ones fit exactly
}

// The polish's analytic Jacobian of the projected residual against central differences of
// the residual itself, for both models, at switch constants away from the model files'
// (so nothing is at an optimum where a wrong term could vanish).
TEST(CylinderFit, RefusesFewerSamplesThanCoefficients) {
  const auto truth = model("mauch-4phase.yaml");
  BenchData tiny = makeBench(truth, 0.987, 1.0, 0.0, 1, "tiny");
  tiny.time.resize(5);
  tiny.position.resize(5);
  tiny.velocity.resize(5);
  tiny.force.resize(5);
  try {
    fitCylinder(truth, {tiny});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("fewer samples (5) than coefficients (12)"));
  }
}

}  // namespace
}  // namespace swingsim
