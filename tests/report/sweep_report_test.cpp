// The sweep's JSON and CSV (report/sweep_report.h) on hand-made results: a quantity a swing
// did not have is null (JSON) or an empty field (CSV), never a marker number.
#include "report/sweep_report.h"

#include <gtest/gtest.h>

#include <string>

#include "core/units.h"
#include "io/json_file.h"

namespace swingsim {
namespace {

constexpr double kRoundOff = 1e-9;  // one unit conversion and the JSON's round trip

// One participant with two ended swings: a plain one with every quantity, and one whose
// knee left the zone but had no bounce peak and (a printer's worst case) no peak at all.
SweepResults makeResults() {
  SweepPoint full;
  full.lowering = 0;
  full.ran = full.ok = true;
  full.result.swingTime = 0.4;
  full.result.peakKneeFlexion = KneePeak{60 * kDegToRad, 0.2};
  full.result.minToeClearance = 0.01;
  SweepPoint sparse = full;
  sparse.lowering = 0.05;
  sparse.result.peakKneeFlexion.reset();
  sparse.result.minToeClearance.reset();
  sparse.result.bounce = true;
  sparse.result.bounces = 1;
  ParticipantSweep ps;
  ps.name = "P";
  ps.points = {full, sparse};
  ps.best = 0;
  SweepResults results;
  results.study = "s";
  results.participants = {ps};
  return results;
}

TEST(SweepReport, JsonHasNullForAbsentQuantities) {
  const Json j = Json::parse(formatSweepJson(makeResults(), nullptr));
  const Json& p = j.at("participants").at(0);
  EXPECT_NEAR(p.at("peak_knee_flexion_deg").at(0).get<double>(), 60, kRoundOff);
  EXPECT_NEAR(p.at("min_toe_clearance_m").at(0).get<double>(), 0.01, kRoundOff);
  EXPECT_TRUE(p.at("bounce_height_deg").at(0).is_null());  // no bounce
  EXPECT_TRUE(p.at("peak_knee_flexion_deg").at(1).is_null());
  EXPECT_TRUE(p.at("min_toe_clearance_m").at(1).is_null());
  EXPECT_TRUE(p.at("bounce_height_deg").at(1).is_null());  // a bounce without its peak
}

TEST(SweepReport, CsvHasEmptyFieldsForAbsentQuantities) {
  const std::string csv = formatSweepCsv(makeResults());
  EXPECT_NE(csv.find("P,0.000,0.000,0.000,1,0.400000,60.000,0.200000,0,0.0100,ended\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("P,0.050,0.000,0.000,1,0.400000,,,1,,ended\n"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("e+"), std::string::npos) << csv;
}

}  // namespace
}  // namespace swingsim
