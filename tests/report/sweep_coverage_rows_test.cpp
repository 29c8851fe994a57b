// The sweep plant's calibration rows the report quotes: the candidates hidden with 20 seeds
// quote their own counts, and those whose hidden sizes no table of swing times can show
// (they act after the swing's end, or the participant's time scale takes them up, or the
// thigh target decides no swing time) say that the sweep cannot measure them, with no count.
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "report/diagnosis_coverage.h"
#include "report/diagnosis_report.h"

namespace swingsim {
namespace {

// The report's text and JSON with `effect` accepted (a sweep effect with one parameter).
Diagnosis acceptedSweepEffect(EffectId id, const std::string& effect, const std::string& parameter) {
  Diagnosis dg;
  CandidateScore c;
  c.id = id;
  c.effect = effect;
  c.parameters = {{parameter, 1.0, 0.9, 1.1, ""}};
  dg.accepted = {effect};
  dg.acceptedScores = {c};
  dg.explained = true;  // the line is quoted for data the final model explains
  return dg;
}

// The line of `text` that quotes the calibration study.
std::string coverageLine(const std::string& text) {
  const auto at = text.find("interval check (calibration study on independent data");
  if (at == std::string::npos) return "";
  return text.substr(at, text.find('\n', at) - at);
}

TEST(SweepCoverageRows, CandidatesActingAfterTheSwingsEndSayTheSweepCannotMeasureThem) {
  for (const char* effect : {"knee_friction_scale", "stop_restitution", "stop_stiffness"}) {
    const auto m = findMeasuredCoverage(effect);
    ASSERT_TRUE(m.has_value()) << effect;
    EXPECT_EQ(m->seeds, 0) << effect;
    const std::string line = formatMeasuredCoverage(effect);
    EXPECT_NE(line.find("not measured; the sweep cannot measure it"), std::string::npos) << line;
    EXPECT_NE(line.find("moves no swing time"), std::string::npos) << line;
    EXPECT_EQ(line.find("named first"), std::string::npos) << line;
    EXPECT_EQ(line.find("held the truth"), std::string::npos) << line;
  }
}

TEST(SweepCoverageRows, CandidatesTheTimeScaleTakesUpAndTheThighTargetSaySoToo) {
  for (const char* effect : {"hip_extension_ratio", "hip_flexion_duration", "hip_extension_duration"})
    EXPECT_NE(formatMeasuredCoverage(effect).find("hip time scale takes up"), std::string::npos) << effect;
  EXPECT_NE(formatMeasuredCoverage("thigh_target_flexion").find("decides whether a swing ends rather than when"),
            std::string::npos);
}

TEST(SweepCoverageRows, AnAcceptedUnmeasurableCandidateGetsTheLineAndNoCountsInTheJson) {
  const Diagnosis dg = acceptedSweepEffect(EffectId::kStopStiffness, "stop_stiffness", "stiffness_Nm_per_rad1p5");
  const std::string line = coverageLine(formatDiagnosisText(dg, Comparison{}, Comparison{}));
  EXPECT_NE(line.find("not measured; the sweep cannot measure it"), std::string::npos) << line;
  const Json j = makeDiagnosisJson(dg, Comparison{}, Comparison{});
  ASSERT_TRUE(j.contains("interval_coverage"));
  const Json& row = j["interval_coverage"]["stop_stiffness"];
  EXPECT_EQ(row["seeds"], 0);
  EXPECT_TRUE(row["bias_percent"].is_null()) << row.dump();
  EXPECT_NE(row["caveat"].get<std::string>().find("moves no swing time"), std::string::npos);
}

// The candidates the sweep can show, hidden with 20 seeds (docs/diagnosis.md's sweep table),
// quote their own counts and their own parameter.
TEST(SweepCoverageRows, TheMeasuredSweepCandidatesQuoteTheirOwnTwentySeeds) {
  for (const auto& [effect, parameter] : {std::pair<const char*, const char*>{"hip_effort_adaptation", "exponent"},
                                          {"hip_tempo_lowering", "change_per_100mm"}}) {
    const auto m = findMeasuredCoverage(effect);
    ASSERT_TRUE(m.has_value()) << effect;
    EXPECT_EQ(std::string(m->parameter), parameter);
    EXPECT_EQ(m->seeds, 20) << effect;
    EXPECT_LE(m->named, m->seeds) << effect;
    EXPECT_LE(m->covered, m->scored) << effect;
    EXPECT_LE(m->scored, m->seeds) << effect;
    const std::string line = formatMeasuredCoverage(effect);
    EXPECT_NE(
        line.find("named first in " + std::to_string(m->named) + " of 20 seeds; the 95 % interval of " + parameter +
                  " held the truth in " + std::to_string(m->covered) + " of " + std::to_string(m->scored)),
        std::string::npos)
        << line;
  }
}

}  // namespace
}  // namespace swingsim
