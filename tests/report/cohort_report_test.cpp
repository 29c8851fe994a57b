// The cohort report (report/cohort_report.h) on a hand-made cohort of three: two calibrated
// (one fastest inside the grid, one at its end), one not. report.md names the draw, the
// distributions with their sources, who was left out, the intervals and the predictors;
// cohort.csv and the JSON leave absent numbers empty or null; the figures are written.
#include "report/cohort_report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "io/json_file.h"

namespace swingsim {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Fixture {
  Cohort cohort;
  std::vector<CohortParticipantResult> results;
  CohortSummary summary;

  Fixture() {
    cohort.study.name = "tiny";
    cohort.study.loweringStep = 0.025;
    cohort.study.loweringMax = 0.1;
    cohort.templatePath = "participants/p1.yaml";
    cohort.count = 3;
    cohort.seed = 7;
    for (std::size_t k = 0; k < cohortProperties().size(); ++k) {
      CohortDistribution d;
      d.min = 1;
      d.max = 2;
      d.source = "source " + std::to_string(k);
      cohort.distributions.push_back(d);
    }
    cohort.distributions[1].kind = CohortDistribution::Kind::kNormal;
    cohort.distributions[1].mean = 1.5;
    cohort.distributions[1].sd = 0.25;
    for (const char* name : {"A", "B", "C"}) {
      Participant p;
      p.name = name;
      p.bodyMass = 70;
      cohort.study.participants.push_back(p);
      cohort.values.push_back(std::vector<double>(cohortProperties().size(), 1.25));
    }
    results.resize(3);
    results[0] = calibrated({0.45, 0.43, 0.44}, 1);
    results[1] = calibrated({0.45, 0.44, 0.42}, 2);
    results[2].ran = true;
    results[2].failure = "target out of reach";
    results[2].timeScale = kNaN;
    summary.participants = 3;
    summary.calibrated = 2;
    summary.fastestLowering = {0.025, 0.05, kNaN};
    summary.timeGained = {0.02, 0.03, kNaN};
    summary.fastestLoweringInterval = {0.04, 0.026, 0.049, 2};
    summary.timeGainedInterval = {0.025, 0.0205, 0.0295, 2};
    CohortPredictor stature{"stature_m", "stature (m)", {1.7, 1.8, kNaN}, {0.8, 0.1, 0.95, 2}};
    CohortPredictor constant{"knee_mass_kg", "knee unit mass (kg)", {1, 1, 1}, {kNaN, kNaN, kNaN, 2}};
    summary.predictors = {stature, constant};
  }
  static CohortParticipantResult calibrated(std::vector<double> times, int best) {
    CohortParticipantResult r;
    r.ran = r.calibrated = true;
    r.timeScale = 1.1;
    r.sweep.lowerings = {0, 0.025, 0.05};
    r.sweep.swingTimes = std::move(times);
    r.sweep.best = best;
    return r;
  }
  std::string file(const std::string& name) const {
    for (const auto& [n, text] : makeCohortReport(cohort, results, summary))
      if (n == name) return text;
    ADD_FAILURE() << name << " not written";
    return "";
  }
};

TEST(CohortReport, MarkdownNamesTheDrawTheSourcesAndWhoWasLeftOut) {
  const Fixture f;
  const std::string md = f.file("report.md");
  EXPECT_EQ(
      md.rfind("# Cohort study tiny\n\n3 participants drawn with seed 7 from the distributions below; each starts "
               "from `p1.yaml`",
               0),
      0u)
      << md;
  EXPECT_NE(md.find("lowered in 25 mm steps up to 100 mm"), std::string::npos);
  EXPECT_NE(md.find("| stature (m) | uniform 1 .. 2 | source 0 |\n"), std::string::npos);
  EXPECT_NE(md.find("| body mass index (kg/m^2) | normal mean 1.5, sd 0.25, truncated to 1 .. 2 | source 1 |\n"),
            std::string::npos);
  EXPECT_NE(md.find("2 of 3 participants calibrated (not calibrated, left out: C;"), std::string::npos);
  EXPECT_NE(md.find("| fastest lowering (mm) | 40 | 26 | 49 | 2 |\n"), std::string::npos);
  EXPECT_NE(md.find("| time gained (ms) | 25.0 | 20.5 | 29.5 | 2 |\n"), std::string::npos);
  EXPECT_NE(md.find("1 participants are fastest at their largest lowering"), std::string::npos) << "B";
  EXPECT_NE(md.find("| stature (m) | +0.80 | +0.10 .. +0.95 | 2 |\n"), std::string::npos);
  EXPECT_NE(md.find("| knee unit mass (kg) | - | - .. - | 2 |\n"), std::string::npos) << "an undefined rho";
  EXPECT_NE(md.find("![strongest predictor](cohort-gain-vs-stature_m.svg)"), std::string::npos);
}

TEST(CohortReport, WritesTheFiguresItLinks) {
  const Fixture f;
  for (const char* name : {"cohort-fastest-lowering.svg", "cohort-time-gained.svg", "cohort-predictors.svg",
                           "cohort-gain-vs-stature_m.svg"})
    EXPECT_EQ(f.file(name).rfind("<svg", 0), 0u) << name;
  EXPECT_NE(f.file("cohort-gain-vs-stature_m.svg").find("Time gained against stature (m) (rho 0.80)"),
            std::string::npos);
}

TEST(CohortReport, CsvAndJsonLeaveAbsentNumbersEmptyOrNull) {
  const Fixture f;
  const std::string csv = f.file("cohort.csv");
  EXPECT_EQ(csv.rfind("participant,stature_m,body_mass_index_kg_m2,", 0), 0u);
  EXPECT_NE(csv.find(",body_mass_kg,calibrated,hip_time_scale,standard_swing_time_s,fastest_lowering_m,"
                     "fastest_swing_time_s,time_gained_s\n"),
            std::string::npos);
  EXPECT_NE(csv.find(",70,0,,,,,\n"), std::string::npos) << "C: nothing but its draw";
  EXPECT_NE(csv.find(",70,1,1.1000000000000001,0.45000000000000001,0.025000000000000001,0.42999999999999999,"
                     "0.02\n"),
            std::string::npos)
      << csv;
  const Json j = Json::parse(formatCohortJson(f.cohort, f.results, f.summary));
  EXPECT_EQ(j.at("study").get<std::string>(), "tiny");
  EXPECT_EQ(j.at("calibrated").get<int>(), 2);
  const Json& c = j.at("participants_results").at(2);
  EXPECT_EQ(c.at("failure").get<std::string>(), "target out of reach");
  EXPECT_TRUE(c.at("fastest_lowering_m").is_null());
  EXPECT_TRUE(c.at("hip_time_scale").is_null());
  EXPECT_FALSE(j.at("participants_results").at(0).contains("failure"));
  EXPECT_DOUBLE_EQ(j.at("participants_results").at(1).at("fastest_swing_time_s").get<double>(), 0.42);
  EXPECT_TRUE(j.at("predictors").at(1).at("rho").is_null());
  EXPECT_EQ(j.at("predictors").at(0).at("key").get<std::string>(), "stature_m");
}

TEST(CohortReport, SummaryGivesTheIntervalsAndTheStrongestPredictors) {
  const Fixture f;
  const std::string s = formatCohortSummary(f.cohort, f.summary);
  EXPECT_EQ(s,
            "cohort tiny: 3 participants (seed 7), 2 calibrated\n"
            "  fastest lowering  median 40 mm (5-95 %: 26 .. 49 mm)\n"
            "  time gained       median 25.0 ms (5-95 %: 20.5 .. 29.5 ms)\n"
            "  predictor 1       stature (m): rho +0.80 (95 %: +0.10 .. +0.95)\n"
            "  predictor 2       knee unit mass (kg): rho - (95 %: - .. -)\n");
}

}  // namespace
}  // namespace swingsim
