// The report of an accepted effect quotes the calibration study's measured coverage of its
// interval in one line (text and JSON); with nothing accepted there is no such line.
#include "report/diagnosis_coverage.h"

#include <gtest/gtest.h>

#include <string>

#include "report/diagnosis_report.h"

namespace swingsim {
namespace {

Diagnosis acceptedFriction() {
  Diagnosis dg;
  CandidateScore friction;
  friction.id = EffectId::kKneeCoulombFriction;
  friction.effect = "knee_coulomb_friction";
  friction.parameters = {{"moment_Nm", 0.5, 0.4, 0.6, ""}, {"smoothing_deg_s", 17.0, 11.5, 28.6, ""}};
  dg.accepted = {"knee_coulomb_friction"};
  dg.acceptedScores = {friction};
  dg.explained = true;
  return dg;
}

// Every swing and cylinder candidate the study hid has a row; a candidate without one has no line.
TEST(DiagnosisCoverage, EveryMeasuredCandidateHasARow) {
  for (const char* effect :
       {"knee_coulomb_friction", "knee_viscous_damping", "extension_assist_spring", "toe_off_velocity",
        "hip_moment_scale", "shank_mass_scale", "below_knee_mass_scale", "coulomb_friction", "orifice_quadratic",
        "position_dependent_damping", "switch_delay", "hyperextension_phase"}) {
    const auto m = findMeasuredCoverage(effect);
    ASSERT_TRUE(m.has_value()) << effect;
    EXPECT_GE(m->seeds, 20) << effect;
    EXPECT_LE(m->covered, m->scored) << effect;
    EXPECT_LE(m->scored, m->seeds) << effect;
    EXPECT_LE(m->named, m->seeds) << effect;
  }
  EXPECT_FALSE(findMeasuredCoverage("an_effect_never_measured").has_value());
  EXPECT_EQ(formatMeasuredCoverage("an_effect_never_measured"), "");
  // The COM rule switch was measured (20 seeds, named in none): its line says why, no counts.
  EXPECT_NE(formatMeasuredCoverage("com_rule_proportional").find("cannot tell the two COM rules apart"),
            std::string::npos);
}

TEST(DiagnosisCoverage, TheLineAppearsForAnAcceptedEffect) {
  const Diagnosis dg = acceptedFriction();
  const auto m = findMeasuredCoverage("knee_coulomb_friction");
  ASSERT_TRUE(m.has_value());
  const std::string text = formatDiagnosisText(dg, Comparison{}, Comparison{});
  const std::string expected = "held the truth in " + std::to_string(m->covered) + " of " + std::to_string(m->scored);
  const auto line = text.find("interval check (calibration study on independent data");
  ASSERT_NE(line, std::string::npos) << text;
  EXPECT_NE(text.substr(line, text.find('\n', line) - line).find(expected), std::string::npos) << text;
  const Json j = makeDiagnosisJson(dg, Comparison{}, Comparison{});
  ASSERT_TRUE(j.contains("interval_coverage"));
  EXPECT_EQ(j["interval_coverage"]["knee_coulomb_friction"]["covered"], m->covered);
  EXPECT_EQ(j["interval_coverage"]["knee_coulomb_friction"]["scored"], m->scored);
}

// Issue 54: the calibration study's line describes a library effect found alone in data it
// explains; a final model that does not explain these data does not quote it (a near miss
// would borrow the whole-range effect's record).
TEST(DiagnosisCoverage, NotQuotedWhenTheFinalModelDoesNotExplainTheData) {
  Diagnosis dg = acceptedFriction();
  dg.explained = false;
  const std::string text = formatDiagnosisText(dg, Comparison{}, Comparison{});
  EXPECT_EQ(text.find("interval check (calibration study"), std::string::npos) << text;
  EXPECT_NE(text.find("interval check not quoted: the final model does not explain these data"), std::string::npos)
      << text;
  EXPECT_FALSE(makeDiagnosisJson(dg, Comparison{}, Comparison{}).contains("interval_coverage"));
}

TEST(DiagnosisCoverage, NoLineWhenNothingIsAccepted) {
  const Diagnosis dg;
  EXPECT_EQ(formatDiagnosisText(dg, Comparison{}, Comparison{}).find("interval check"), std::string::npos);
  EXPECT_FALSE(makeDiagnosisJson(dg, Comparison{}, Comparison{}).contains("interval_coverage"));
}

}  // namespace
}  // namespace swingsim
