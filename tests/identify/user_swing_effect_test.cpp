// A user's effect (identify/user_swing_effect.h): registered as a record of the library's
// kind, and, on swings the independent generator makes (tests/independent/swing_generator.h,
// no code shared with src/) with an effect outside the library, fitted, accepted and given an
// interval by the library's rules.
#include "identify/user_swing_effect.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>

#include "../cli/release_only.h"
#include "diagnosis_calibration.h"
#include "diagnosis_outcome.h"
#include "io/knee_model_loader.h"

namespace swingsim {
namespace {

UserSwingEffect damper(const std::string& name) {
  return {name, "-c * knee_rate_rad_s", {{"c", "N m s/rad", 0.0, 20.0, 0.0}}};
}

TEST(UserSwingEffect, TheSameDefinitionIsOneEffectAndAnotherIsAnother) {
  const EffectId a = registerUserSwingEffect(damper("test_damper_a"));
  EXPECT_TRUE(isUserEffect(a));
  EXPECT_EQ(registerUserSwingEffect(damper("test_damper_a")), a);
  UserSwingEffect wider = damper("test_damper_a");
  wider.parameters[0].max = 40;
  const EffectId b = registerUserSwingEffect(wider);
  EXPECT_NE(b, a);
  // The name finds the one registered last; each id keeps its own record and bounds.
  EXPECT_EQ(findEffect(PlantKind::kSwing, "test_damper_a")->id, b);
  EXPECT_EQ(findSwingEffectRecord(a).slots[0].bounds.upper, 20.0);
  EXPECT_EQ(findSwingEffectRecord(b).slots[0].bounds.upper, 40.0);
  EXPECT_EQ(describeEffect(b).fittedParameters, 1);
  EXPECT_EQ(describeEffect(b).parameters[0], "c (N m s/rad)");
}

TEST(UserSwingEffect, RefusesALibraryNameBadBoundsAndABadExpression) {
  EXPECT_THROW(registerUserSwingEffect(damper("knee_viscous_damping")), std::invalid_argument);
  UserSwingEffect e = damper("test_bad");
  e.parameters[0].start = 30;  // outside [0, 20]
  EXPECT_THROW(registerUserSwingEffect(e), std::invalid_argument);
  e = damper("test_bad");
  e.parameters[0].max = e.parameters[0].min;
  EXPECT_THROW(registerUserSwingEffect(e), std::invalid_argument);
  e = damper("test_bad");
  e.parameters.clear();
  EXPECT_THROW(registerUserSwingEffect(e), std::invalid_argument);
  e = damper("test_bad");
  e.expression = "-c * knee_rte_rad_s";
  EXPECT_THROW(registerUserSwingEffect(e), KneeExpressionError);
}

// Switched on, the expression enters the knee's added effects at its start values; its slot
// is the parameter's value there; switched off, it leaves.
TEST(UserSwingEffect, PresenceMovesTheExpressionInAndOutOfTheKnee) {
  const EffectId id = registerUserSwingEffect(damper("test_presence"));
  SwingEffects e = addSwingEffectTo({}, id, 0);
  ASSERT_EQ(e.knee.expressions.size(), 1u);
  EXPECT_EQ(e.knee.expressions[0].name, "test_presence");
  findSwingEffectRecord(id).slots[0].value(e) = 2.5;
  EXPECT_EQ(e.knee.expressions[0].parameters[0].value, 2.5);
  EXPECT_EQ(swingEffectValues(e, id), std::vector<double>{2.5});
  const SwingEffects copy = copySwingEffect({}, e, id);
  ASSERT_EQ(copy.knee.expressions.size(), 1u);
  EXPECT_EQ(copy.knee.expressions[0].parameters[0].value, 2.5);
  const SwingEffects without = removeSwingEffect(e, id);
  EXPECT_FALSE(without.has(id));
  EXPECT_TRUE(without.knee.expressions.empty());
  EXPECT_EQ(presentSwingEffectRecords(e).size(), 1u);
  EXPECT_TRUE(presentSwingEffectRecords(without).empty());
}

// ---- On independent data -----------------------------------------------------------------

constexpr double kNoiseDeg = calibration::kSwingNoiseDeg;

// The cushion the generator hides (SwingTruth::cushionDamping), as a user would write it.
const char* const kCushionCandidates =
    "candidates:\n"
    "  - knee_coulomb_friction\n  - knee_viscous_damping\n  - extension_assist_spring\n"
    "  - name: my_cushion\n"
    "    knee_moment_Nm: \"-c * knee_rate_rad_s * (knee_rate_rad_s < 0 ? 1 : 0) * (knee_deg < 20 ? 1 : 0)\"\n"
    "    parameters:\n"
    "      c: {unit: N m s/rad, min: 0, max: 20, start: 0}\n";

Diagnosis diagnose(const independent::SwingTruth& truth, std::uint64_t seed, const std::string& tag,
                   const std::string& candidates, const std::string& saveKnee = "") {
  const Diagnosis dg = calibration::diagnoseSwing(truth, truth, seed, "user-" + tag, 1, candidates, saveKnee);
  testing::printOutcome(tag, dg, "deg", kNoiseDeg);
  for (const auto& st : dg.steps)
    for (const auto& c : st.candidates) {
      std::printf("    %s train %.4f (current %.4f) LR %.3g p %.3g %s %s", c.effect.c_str(), c.trainRmse,
                  st.currentTrainRmse, c.likelihoodRatio, c.pAdjusted, c.notApplicable.c_str(),
                  c.informative ? "" : "no-info");
      for (const auto& q : c.parameters)
        std::printf(" %s=%.3g [%.3g, %.3g]", q.name.c_str(), q.value, q.lower, q.upper);
      for (double v : c.validationRmse) std::printf(" v%.3f", v);
      std::printf("\n");
    }
  return dg;
}

// Issue 54: a cushion outside the library leaves the library's diagnosis NOT explained; the
// user's expression of the right form is accepted, its interval holds the truth and the
// held-out error falls to the noise.
TEST(UserSwingEffect, ACushionOutsideTheLibraryIsExplainedByTheUsersExpression) {
  SWINGSIM_RELEASE_ONLY();  // two diagnoses; the sanitized pass runs the null below
  independent::SwingTruth truth;
  truth.cushionDamping = 1.5;  // N m s/rad below 20 deg while extending
  const Diagnosis library =
      diagnose(truth, 91, "cushion-library",
               "candidates: [knee_coulomb_friction, knee_viscous_damping, extension_assist_spring]\n");
  EXPECT_FALSE(library.explained) << library.verdict;
  std::printf("  library: %s\n", library.missingNote.c_str());
  EXPECT_EQ(library.missingNote.rfind("missing moment: +", 0), 0u) << "where it acts leads the remains";
  EXPECT_NE(library.missingNote.find("resisting extension"), std::string::npos) << library.missingNote;

  const std::string saved =
      (std::filesystem::temp_directory_path() / ("user-cushion-" + std::to_string(::getpid()) + ".yaml")).string();
  const Diagnosis dg = diagnose(truth, 91, "cushion-user", kCushionCandidates, saved);
  ASSERT_FALSE(dg.accepted.empty()) << dg.verdict;
  EXPECT_EQ(dg.accepted.front(), "my_cushion");
  ASSERT_EQ(dg.acceptedScores.front().parameters.size(), 1u);
  const EffectParameter& c = dg.acceptedScores.front().parameters[0];
  std::printf("  my_cushion c = %.3f (95 %% CI %.3f .. %.3f), truth %.3f N m s/rad\n", c.value, c.lower, c.upper,
              truth.cushionDamping);
  EXPECT_LE(c.lower, truth.cushionDamping);
  EXPECT_GE(c.upper, truth.cushionDamping);
  EXPECT_LE(testing::worstHeldOut(dg), 1.5 * kNoiseDeg);
  EXPECT_LT(testing::worstHeldOut(dg), testing::worstHeldOut(library));
  // Saved into the knee model's knee_effects, so every command that loads it applies it.
  const KneeModel knee = loadKneeModel(saved);
  std::filesystem::remove(saved);
  ASSERT_EQ(knee.spec.kneeEffects.expressions.size(), 1u);
  const KneeExpressionParams& x = knee.spec.kneeEffects.expressions[0];
  EXPECT_EQ(x.name, "my_cushion");
  ASSERT_EQ(x.parameters.size(), 1u);
  EXPECT_EQ(x.parameters[0].unit, "N m s/rad");
  EXPECT_DOUBLE_EQ(x.parameters[0].value, c.value);
  bool inTheLaw = false;
  for (std::size_t i = 0; i < knee.law.size(); ++i) inTheLaw = inTheLaw || knee.law.part(i).name() == "my_cushion";
  EXPECT_TRUE(inTheLaw);
}

// A null with the user's expression among the candidates accepts nothing.
TEST(UserSwingEffect, ANullAcceptsNeitherTheLibraryNorTheUsersExpression) {
  const Diagnosis dg = diagnose(independent::SwingTruth{}, 93, "null", kCushionCandidates);
  EXPECT_TRUE(dg.accepted.empty()) << dg.accepted.front();
  EXPECT_LT(testing::worstHeldOut(dg), 1.2 * kNoiseDeg);
}

// An expression that is a library effect (-c rate is knee_viscous_damping) fits exactly as the
// library's record does: the two records are of one kind.
TEST(UserSwingEffect, AnExpressionOfALibraryEffectScoresAsTheLibrarys) {
  SWINGSIM_RELEASE_ONLY();
  independent::SwingTruth truth;
  truth.extensionFactor = 0.5;
  truth.extraViscous = 0.15;
  const Diagnosis dg = diagnose(
      truth, 95, "as-library",
      "candidates:\n  - knee_viscous_damping\n  - name: my_damper\n    knee_moment_Nm: \"-c * knee_rate_rad_s\"\n"
      "    parameters: {c: {unit: N m s/rad, min: 0, max: 50, start: 0}}\n");
  ASSERT_FALSE(dg.steps.empty());
  const auto& first = dg.steps.front().candidates;
  ASSERT_EQ(first.size(), 2u);
  EXPECT_NEAR(first[1].trainRmse, first[0].trainRmse, 1e-6 * first[0].trainRmse);
  ASSERT_EQ(first[1].parameters.size(), 1u);
  EXPECT_NEAR(first[1].parameters[0].value, first[0].parameters[0].value, 1e-4);
}

}  // namespace
}  // namespace swingsim
