#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "../cli/release_only.h"
#include "core/text_format.h"
#include "hidden_damper_comparison.h"
#include "identify/swing_plant.h"
#include "identify/synthetic_swing.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "report/diagnosis_report.h"
#include "study/diagnosis_study.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + what.size())) ++n;
  return n;
}

TEST(SwingResidualPlot, FivePanelsWithTitlesAxisUnitsAndSwingPhaseBands) {
  // Data with a hidden viscous damper, compared with the plain model: a structured residual.
  const Comparison cmp = testing::compareHiddenDamperSwing();
  ASSERT_EQ(cmp.records.size(), 1u);
  const std::string svg = renderResidualSvg(cmp.records[0], cmp, "compare: normal (train)");

  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("compare: normal (train)"), std::string::npos);
  // The five panel titles.
  EXPECT_NE(svg.find("knee flexion residual vs time (whole record), phases shaded"), std::string::npos);
  EXPECT_NE(svg.find("mean knee residual vs model knee flexion, 99 % band"), std::string::npos);
  EXPECT_NE(svg.find("mean knee residual vs model knee flexion rate, 99 % band"), std::string::npos);
  EXPECT_NE(svg.find("mean knee residual vs model knee acceleration, 99 % band"), std::string::npos);
  // Axis labels with units (x of the binned panels).
  EXPECT_NE(svg.find("knee flexion, model (deg)"), std::string::npos);
  EXPECT_NE(svg.find("knee flexion rate, model (deg/s)"), std::string::npos);
  EXPECT_NE(svg.find("knee angular acceleration, model (deg/s^2)"), std::string::npos);
  EXPECT_NE(svg.find("residual autocorrelation (white noise stays inside the 99 % band)"), std::string::npos);
  // Axis labels with units.
  EXPECT_NE(svg.find("time (s)"), std::string::npos);
  EXPECT_NE(svg.find("measured - model knee flexion (deg)"), std::string::npos);
  EXPECT_EQ(count(svg, "mean residual (deg)"), 3u);
  EXPECT_NE(svg.find("lag (s)"), std::string::npos);
  EXPECT_NE(svg.find("autocorrelation (-)"), std::string::npos);
  // Every swing phase of the model's knee is shaded and named in the legend.
  for (const auto& name : swingPhaseNames()) EXPECT_NE(svg.find(name), std::string::npos) << name;
  EXPECT_NE(svg.find("99 % band"), std::string::npos);
}

// One schema for both plants: the cylinder and the swing demo diagnoses write the same
// top-level keys, each candidate the same keys, and the plant and unit say which is which.
TEST(DiagnosisJson, CylinderAndSwingShareOneSchema) {
  SWINGSIM_RELEASE_ONLY();  // 50-180 s under the sanitizers
  std::vector<Json> docs;
  for (const char* file : {"/studies/diagnose-demo-cylinder.yaml", "/studies/diagnose-demo-swing.yaml"}) {
    const DiagnosisStudy study = loadDiagnosisStudy(kRoot + file);
    const auto plant = loadDiagnosisPlant(study, 8);
    const Diagnosis dg = runDiagnosis(*plant, study.settings);
    docs.push_back(makeDiagnosisJson(dg, plant->compare(*dg.baseline.model), plant->compare(*dg.final.model)));
  }
  auto keys = [](const Json& j) {
    std::vector<std::string> k;
    for (const auto& item : j.items()) k.push_back(item.key());
    return k;
  };
  EXPECT_EQ(keys(docs[0]), keys(docs[1]));
  EXPECT_EQ(docs[0]["plant"], "cylinder");
  EXPECT_EQ(docs[0]["unit"], "N");
  EXPECT_EQ(docs[1]["plant"], "swing");
  EXPECT_EQ(docs[1]["unit"], "deg");
  // A scored candidate carries the same keys in both (the first applicable one of step 1).
  auto firstScored = [](const Json& j) {
    for (const auto& c : j["candidates"])
      if (!c.contains("not_applicable")) return c;
    return Json();
  };
  EXPECT_EQ(keys(firstScored(docs[0])), keys(firstScored(docs[1])));
  // The demos' hidden effects (docs/diagnosis.md): named, and the base scale of the swing reported.
  EXPECT_EQ(docs[0]["accepted"], Json({"orifice_quadratic"}));
  EXPECT_EQ(docs[1]["accepted"], Json({"extension_assist_spring"}));
  EXPECT_TRUE(docs[1]["final_parameters"]["values"].contains("knee_model_scale"));
  EXPECT_TRUE(docs[0]["final_parameters"]["values"].empty());
}

// One record of a comparison: measured and model series, with the metrics the table prints.
RecordComparison makeRecord(const std::string& stem, bool training, const std::vector<double>& measured,
                            const std::vector<double>& predicted) {
  RecordComparison r;
  r.stem = stem;
  r.training = training;
  r.measured = measured;
  r.predicted = predicted;
  r.overall = calcErrorMetrics(measured, predicted);
  return r;
}

// Two training records and one held out, the same before and after (no effect accepted).
Comparison makeTwoTrainComparison() {
  Comparison c;
  c.quantity = "knee flexion";
  c.unit = "deg";
  c.decimals = 2;
  c.records = {makeRecord("normal", true, {1, 2, 3, 4}, {1, 2, 3, 5}),
               makeRecord("slow", true, {1, 2, 3, 4}, {3, 4, 5, 6}),
               makeRecord("fast", false, {1, 2, 3, 4}, {1, 3, 3, 4})};
  return c;
}

// The step line prints the pooled training RMSE under the label the before/after table uses
// for its own pooled row, with the same number; ME is defined under the table; the whiteness
// p is printed with the level it is judged at.
TEST(DiagnosisText, StepLineAndTablePrintThePooledTrainingRmseAndDefineMeAndTheWhitenessLevel) {
  const Comparison c = makeTwoTrainComparison();
  // Pooled over the 8 training samples: residuals 0 0 0 -1 and -2 -2 -2 -2.
  const double pooledRmse = std::sqrt(17.0 / 8.0);
  Diagnosis dg;
  DiagnosisStep step;
  step.currentTrainRmse = pooledRmse;
  step.currentValidationRmse = {c.records[2].overall.rmse};
  dg.steps.push_back(step);
  dg.finalWhiteness.computed = true;
  dg.finalWhiteness.q = 3.2;
  dg.finalWhiteness.lags = 2;
  dg.finalWhiteness.pValue = 0.2;
  dg.whitenessLevel = 0.05;
  dg.finalResidualWhite = true;
  const std::string text = formatDiagnosisText(dg, c, c);
  const std::string number = fmt("%.3f", pooledRmse);
  EXPECT_NE(
      text.find("step 1: current model, knee flexion RMSE: train pooled (normal, slow) " + number + " deg, fast "),
      std::string::npos)
      << text;
  const auto row = text.find("train pooled     |");
  ASSERT_NE(row, std::string::npos) << text;
  EXPECT_NE(text.substr(row, text.find('\n', row) - row).find(" " + number + " "), std::string::npos) << text;
  EXPECT_NE(text.find("ME: the largest |measured - model| (maximum absolute error)"), std::string::npos) << text;
  EXPECT_NE(text.find("p = 0.2 (white when p >= 0.05, the acceptance rule's alpha)"), std::string::npos) << text;
  // The per-phase tables of `compare` and report.md define ME as well.
  EXPECT_NE(formatComparisonTable(c).find("ME: the largest |measured - model|"), std::string::npos);
}

// A sweep candidate that the folds reject but all rows support: the ranking gives both p.
TEST(DiagnosisText, TheRankingGivesTheAllRowsPBesideTheFoldThatFails) {
  EffectScore c;
  c.effect = "hip_tempo_lowering";
  c.validationRmse = {9.0};
  c.foldPValues = {1e-5, 3e-4, 0.8};
  c.pValue = 0.8;
  c.pAdjusted = 1.0;
  c.allRowsPValue = 6.9e-4;
  c.significant = false;
  const std::string table = formatCandidateRanking({&c}, "ms", 1);
  EXPECT_NE(
      table.find("not significant; (its least significant fold p 0.8; all participants' rows p 0.00069, unadjusted);"),
      std::string::npos)
      << table;
  // Without folds (swing, cylinder) nothing is added.
  c.foldPValues.clear();
  EXPECT_EQ(formatCandidateRanking({&c}, "ms", 1).find("all participants"), std::string::npos);
}

// A candidate without information: the ranking says so and gives no other reason.
TEST(DiagnosisText, TheRankingSaysACandidateWithoutInformationHasNone) {
  EffectScore silent;
  silent.effect = "knee_viscous_damping";
  silent.informative = false;
  silent.validationRmse = {2.0};
  silent.parameters = {{"damping_Nm_s_per_rad", 0.01, std::numeric_limits<double>::quiet_NaN(),
                        std::numeric_limits<double>::quiet_NaN(), kNoInformation}};
  const std::string table = formatCandidateRanking({&silent}, "deg", 2);
  EXPECT_NE(table.find("rejected: no information in these records\n"), std::string::npos) << table;
  EXPECT_EQ(table.find("not significant"), std::string::npos) << table;
  // The JSON: "informative": false and a null interval.
  Diagnosis dg;
  DiagnosisStep step;
  CandidateScore candidate;
  static_cast<EffectScore&>(candidate) = silent;
  step.candidates.push_back(candidate);
  dg.steps.push_back(step);
  dg.whitenessLevel = 0.05;
  const Json j = makeDiagnosisJson(dg, Comparison{}, Comparison{});
  ASSERT_EQ(j["candidates"].size(), 1u);
  EXPECT_EQ(j["candidates"][0]["informative"], false);
  EXPECT_TRUE(j["candidates"][0]["confidence_intervals"]["damping_Nm_s_per_rad"].is_null());
  EXPECT_EQ(j["residual_whiteness_level"], 0.05);
}

}  // namespace
}  // namespace swingsim
