#include <gtest/gtest.h>

#include <string>

#include "io/knee_model_loader.h"
#include "identify/swing_plant.h"
#include "identify/synthetic_swing.h"
#include "io/participant_loader.h"
#include "hidden_damper_comparison.h"
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

}  // namespace
}  // namespace swingsim
