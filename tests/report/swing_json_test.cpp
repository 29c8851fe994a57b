// JSON of one swing (report/swing_json.h): what the swing did not have is null, never a
// marker number; what it had is there in the file's units.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/units.h"
#include "report/swing_json.h"

namespace swingsim {
namespace {

constexpr double kRoundOff = 1e-12;  // one unit conversion

TEST(SwingJson, AbsentQuantitiesAreNull) {
  SwingResult r;  // nothing set: no swing end, no knee peak, no bounce peak, no clearance
  r.swingTime = std::numeric_limits<double>::quiet_NaN();
  TrialEnd end;
  end.unmet = "knee_peak";
  r.trialEnd = end;
  const Json j = makeSwingResultJson("P", 0.0, r);
  for (const char* key : {"swing_time_s", "peak_knee_flexion_deg", "peak_knee_flexion_time_s", "bounce_height_deg",
                          "min_toe_clearance_m"})
    EXPECT_TRUE(j.at(key).is_null()) << key << ": " << j.at(key);
  EXPECT_TRUE(j.at("trial_end").at("settle_dwell_done_s").is_null());
  EXPECT_EQ(formatJson(j).find("e+"), std::string::npos);  // no marker number in the text
}

TEST(SwingJson, PresentQuantitiesAreNumbersInTheFileUnits) {
  SwingResult r;
  r.swingTime = 0.4;
  r.peakKneeFlexion = KneePeak{60 * kDegToRad, 0.2};
  r.bounce = true;
  r.bounces = 1;
  r.bounceHeight = 10 * kDegToRad;
  r.minToeClearance = 0.01;
  const Json j = makeSwingResultJson("P", 0.0, r);
  EXPECT_NEAR(j.at("swing_time_s").get<double>(), 0.4, kRoundOff);
  EXPECT_NEAR(j.at("peak_knee_flexion_deg").get<double>(), 60, kRoundOff);
  EXPECT_NEAR(j.at("peak_knee_flexion_time_s").get<double>(), 0.2, kRoundOff);
  EXPECT_NEAR(j.at("bounce_height_deg").get<double>(), 10, kRoundOff);
  EXPECT_NEAR(j.at("min_toe_clearance_m").get<double>(), 0.01, kRoundOff);
  EXPECT_FALSE(j.contains("trial_end"));
}

TEST(SwingJson, SettleDwellDoneIsThereWhenTheDwellWasUnmet) {
  SwingResult r;
  TrialEnd end;
  end.unmet = "settle_dwell";
  end.dwellDone = 0.03;
  r.trialEnd = end;
  EXPECT_NEAR(makeSwingResultJson("P", 0.0, r).at("trial_end").at("settle_dwell_done_s").get<double>(), 0.03,
              kRoundOff);
}

}  // namespace
}  // namespace swingsim
