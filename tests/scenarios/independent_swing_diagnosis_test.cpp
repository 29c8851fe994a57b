// `diagnose` on swings swingsim did not make (tests/independent/swing_generator.h: Kane's
// equations in absolute angles, fixed-step RK4, its own laws), read through a user's files
// (participant YAML, knee model YAML, swing CSVs, study YAML). A hidden knee effect inside the
// library must be named and bring the held-out knee error to the noise; a null must accept
// nothing; an effect outside the library (a biarticular strap) must be reported as not
// explained.
#include <gtest/gtest.h>

#include <random>

#include "../cli/release_only.h"
#include "../identify/diagnosis_calibration.h"
#include "../identify/diagnosis_outcome.h"
#include "io/participant_loader.h"

namespace swingsim {
namespace {

constexpr double kNoiseDeg = calibration::kSwingNoiseDeg;  // as in the swing demo

// `files`: what the user's participant and knee files say (default: the truth itself);
// `every`: the records keep every `every`-th sample (a lower sampling rate).
Diagnosis diagnoseIndependent(const independent::SwingTruth& truth, std::uint64_t seed, const std::string& tag,
                              const independent::SwingTruth* files = nullptr, std::size_t every = 1) {
  const Diagnosis dg = calibration::diagnoseSwing(truth, files ? *files : truth, seed, "indep-" + tag, every);
  testing::printOutcome(tag, dg, "deg", kNoiseDeg);
  return dg;
}

using testing::worstHeldOut;

TEST(IndependentSwingDiagnosis, NullAcceptsNothingAndReachesTheNoise) {
  const Diagnosis dg = diagnoseIndependent(independent::SwingTruth{}, 41, "null");
  EXPECT_TRUE(dg.accepted.empty());
  EXPECT_LT(worstHeldOut(dg), 1.2 * kNoiseDeg);
}

TEST(IndependentSwingDiagnosis, HiddenAssistSpringIsNamedAndExplained) {
  independent::SwingTruth truth;
  truth.assistStiffness = 1.5;  // N m/rad
  const Diagnosis dg = diagnoseIndependent(truth, 51, "assist");
  ASSERT_FALSE(dg.accepted.empty());
  EXPECT_EQ(dg.accepted.front(), "extension_assist_spring");
  EXPECT_LT(worstHeldOut(dg), 1.2 * kNoiseDeg);
  EXPECT_TRUE(dg.explained) << dg.verdict;
  // The record-agreement rule was run on it and held: one stiffness in all three records.
  EXPECT_EQ(dg.acceptedScores.front().agreement.rfind("stiffness_Nm_per_rad agrees between records", 0), 0u)
      << dg.acceptedScores.front().agreement;
}

// A loose socket hidden in swings of the independent generator (its own four-coordinate
// leg by Kane's method, the socket's angle as the lab's thigh): the socket candidate is named,
// its two values land near the truth, and the held-out error falls to the noise.
TEST(IndependentSwingDiagnosis, HiddenLooseSocketIsNamedWithItsSpringAndDamper) {
  SWINGSIM_RELEASE_ONLY();  // the socket leg's refits: 5-7 s in Release
  independent::SwingTruth truth;
  truth.socket.rotationStiffness = 100.0;                           // N m/rad (MyoSuite: 350)
  truth.socket.rotationDamping = 5.0;                               // N m s/rad (MyoSuite: 175)
  const independent::SwingTruth files = independent::SwingTruth{};  // the user's leg is rigid
  // As `diagnose --save-model` would save it: the knee file and the participant beside it.
  const std::string saved = ::testing::TempDir() + "swingsim-socket-knee.yaml";
  const Diagnosis dg = calibration::diagnoseSwing(truth, files, 61, "indep-socket", 1, "", saved);
  testing::printOutcome("socket", dg, "deg", kNoiseDeg);
  ASSERT_FALSE(dg.accepted.empty());
  EXPECT_EQ(dg.accepted.front(), "socket_compliance");
  EXPECT_LT(worstHeldOut(dg), 1.2 * kNoiseDeg);
  const auto& c = dg.acceptedScores.front();
  ASSERT_EQ(c.parameters.size(), 2u);
  const double truths[2] = {truth.socket.rotationStiffness, truth.socket.rotationDamping};
  for (std::size_t i = 0; i < 2; ++i) {
    // Within the 99.9 % interval (the 95 % one widened as the blind draw's check).
    const double half = 0.5 * (c.parameters[i].upper - c.parameters[i].lower) * 3.2905 / 1.96;
    const double mid = 0.5 * (c.parameters[i].upper + c.parameters[i].lower);
    EXPECT_LE(std::abs(truths[i] - mid), half) << c.parameters[i].name << " " << c.parameters[i].value;
  }
  // The saved participant hangs its prosthesis on the diagnosed socket.
  const Participant p = loadParticipant(::testing::TempDir() + "swingsim-socket-knee-participant.yaml");
  ASSERT_TRUE(p.socket.has_value());
  EXPECT_NEAR(p.socket->rotationStiffness, c.parameters[0].value, 1e-6 * c.parameters[0].value);
  EXPECT_NEAR(p.socket->rotationDamping, c.parameters[1].value, 1e-6 * c.parameters[1].value);
  EXPECT_EQ(p.socket->pistonStiffness, SocketCompliance{}.pistonStiffness);
}

// Issue 54, a near miss: a stiffening outside the library (beyond 55 deg) with only the
// fastest swing held out. A whole-range extension_assist_spring lowers the training error and
// the fast swing's held-out error (4.27 -> 3.54 deg, measured), so the rules before the
// record-agreement rule accepted it; refitted on each record alone its stiffness is about 0.3
// (slow), 0.8 (normal) and 1.5 N m/rad (fast): a law of another shape, not accepted.
TEST(IndependentSwingDiagnosis, ANearMissWithOnlyTheFastestHeldOutIsNotAccepted) {
  independent::SwingTruth truth;
  truth.stiffening = 20.0;  // N m/rad beyond 55 deg
  independent::SwingTruth files = truth;
  files.stiffening = 0;
  for (const char* split :
       {"train: [normal.csv, slow.csv]\nvalidate: [fast.csv]\n", "train: [normal.csv]\nvalidate: [fast.csv]\n"}) {
    const Diagnosis dg = calibration::diagnoseSwing(truth, files, 111, "indep-near-miss", 1, "", "", split);
    testing::printOutcome("near-miss", dg, "deg", kNoiseDeg);
    EXPECT_TRUE(dg.accepted.empty()) << split;
    EXPECT_FALSE(dg.explained);
    ASSERT_FALSE(dg.steps.empty());
    bool springRefused = false;
    for (const auto& c : dg.steps.front().candidates)
      if (c.effect == "extension_assist_spring") {
        std::printf("    %s\n", c.agreement.c_str());
        springRefused = c.significant && c.validationImproves && !c.recordsAgree &&
                        c.agreement.find("differs between records") != std::string::npos;
      }
    EXPECT_TRUE(springRefused) << "the near miss passes every other rule and fails agreement: " << split;
  }
}

TEST(IndependentSwingDiagnosis, BiarticularStrapOutsideTheLibraryIsNotExplained) {
  independent::SwingTruth truth;
  truth.strapStiffness = 8.0;  // N m/rad
  truth.strapOffset = 0.2;
  const Diagnosis dg = diagnoseIndependent(truth, 61, "strap");
  EXPECT_FALSE(dg.explained);
  EXPECT_EQ(dg.verdict.rfind("NOT explained", 0), 0u) << dg.verdict;
}

// The strap case recorded at 1/12 of the rate (about 42 Hz, 16 samples in the training
// swing). Before issue 29, 20 Ljung-Box lags were taken on these 16-sample records and the
// final residual read "consistent with white noise" (p = 0.14, measured with the build of
// 4a793fb); the probe saw such a pass, with a held-out error near the noise, turn a
// verdict into "explained". The lags now follow the record (at most one per
// kWhitenessLagDivisor samples) and the verdict stays "NOT explained".
TEST(IndependentSwingDiagnosis, StrapAtALowSamplingRateIsStillNotExplained) {
  independent::SwingTruth truth;
  truth.strapStiffness = 8.0;  // N m/rad
  truth.strapOffset = 0.2;
  constexpr std::size_t kEvery = 12;
  const Diagnosis dg = diagnoseIndependent(truth, 61, "strap-low-rate", nullptr, kEvery);
  ASSERT_FALSE(dg.final.likelihoodResidual.empty());
  const std::size_t samples = dg.final.likelihoodResidual.front().size();
  EXPECT_LE(samples, 20u);
  EXPECT_EQ(dg.finalWhiteness.lags, static_cast<int>(samples) / kWhitenessLagDivisor);
  EXPECT_TRUE(dg.finalWhiteness.computed) << dg.finalWhiteness.note;  // a 10-row record keeps 2 lags
  // Over the lags the record supports the strap's structure shows (p = 0.0005 over 3 lags).
  EXPECT_FALSE(dg.finalResidualWhite) << "p = " << dg.finalWhiteness.pValue;
  EXPECT_FALSE(dg.explained);
  EXPECT_EQ(dg.verdict.rfind("NOT explained", 0), 0u) << dg.verdict;
}

// The prosthesis is 30 % heavier below the knee (shank and foot) than the participant file
// says. The library's below_knee_mass_scale is that effect; hip_moment_scale and
// shank_mass_scale act almost alike on a swing. Whatever is named first, no second one of
// these is stacked on top of it: a confound is reported with the measurement that separates.
TEST(IndependentSwingDiagnosis, HeavierProsthesisIsNamedAndConfoundsAreNotStacked) {
  independent::SwingTruth truth;
  const independent::SwingTruth files = truth;
  for (independent::Segment* s : {&truth.shank, &truth.foot}) {
    s->mass *= 1.3;
    s->inertia *= 1.3;
  }
  const Diagnosis dg = diagnoseIndependent(truth, 71, "heavier", &files);
  ASSERT_FALSE(dg.accepted.empty());
  EXPECT_EQ(dg.accepted.front(), "below_knee_mass_scale");
  int massOrMoment = 0;
  for (const auto& a : dg.accepted)
    massOrMoment += a == "shank_mass_scale" || a == "hip_moment_scale" || a == "below_knee_mass_scale";
  EXPECT_EQ(massOrMoment, 1) << "stacked on a confound";
  EXPECT_LT(worstHeldOut(dg), 1.2 * kNoiseDeg);
}

// Legs and knees drawn across plausible ranges (segment masses x 0.8..1.2, lengths x
// 0.9..1.1, a damping table of 1..4 N m at 150 deg/s), the participant file telling the
// truth: nulls accept nothing, a hidden assist spring (1..3 N m/rad) is named, and both reach
// the noise on held-out swings. A viscous term would be no test here: on a table that is
// linear in speed it is the knee model scale itself.
TEST(IndependentSwingDiagnosis, DrawnLegsAndKnees) {
  for (std::uint64_t seed : {81, 82}) {
    std::mt19937_64 e(seed);
    std::uniform_real_distribution<double> mass(0.8, 1.2), length(0.9, 1.1), table(1.0, 4.0), spring(1.0, 3.0);
    independent::SwingTruth truth;
    for (independent::Segment* s : {&truth.thigh, &truth.shank, &truth.foot}) {
      const double m = mass(e), l = length(e);
      s->mass *= m;
      s->inertia *= m * l * l;
      s->length *= l;
      s->comFromDistal *= l;
    }
    truth.tableMoment = table(e);
    SCOPED_TRACE("seed " + std::to_string(seed) + ", table " + std::to_string(truth.tableMoment) + " N m");
    const Diagnosis null = diagnoseIndependent(truth, seed, "drawn-null-" + std::to_string(seed));
    EXPECT_TRUE(null.accepted.empty());
    EXPECT_LT(worstHeldOut(null), 1.2 * kNoiseDeg);
    truth.assistStiffness = spring(e);
    const Diagnosis hidden = diagnoseIndependent(truth, seed + 100, "drawn-assist-" + std::to_string(seed));
    ASSERT_FALSE(hidden.accepted.empty());
    EXPECT_EQ(hidden.accepted.front(), "extension_assist_spring");
    EXPECT_LT(worstHeldOut(hidden), 1.2 * kNoiseDeg);
  }
}

}  // namespace
}  // namespace swingsim
