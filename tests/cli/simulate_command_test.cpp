// `swingsim simulate` on a measured trial that ends before the swing does (Winter's walking
// subject, cut at heel contact with the knee still flexed): a result, written and exit 0.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/json_file.h"
#include "run_swingsim.h"

namespace {

using ::testing::HasSubstr;
using swingsim::Json;
namespace fs = std::filesystem;

TEST(SimulateCommand, MeasuredTrialEndingBeforeTheSwingIsAResult) {
  const fs::path out = swingsim::testing::freshTempDir("swingsim_simulate_command_test", "winter");
  const auto r = swingsim::testing::runSwingsim("simulate participants/winter.yaml --out " + out.string() + " --json " +
                                                (out / "r.json").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("swing time          not reached (knee_zone)"));
  EXPECT_THAT(r.output, HasSubstr("the measured trial ended at "));
  // The drive file (time_s, hip_flexion_deg, knee_flexion_deg) has the measured knee.
  EXPECT_THAT(r.output, HasSubstr("measured knee"));
  EXPECT_TRUE(fs::exists(out / "winter-lower000mm.csv"));
  EXPECT_TRUE(fs::exists(out / "winter-lower000mm.sto"));
  EXPECT_TRUE(fs::exists(out / "winter-lower000mm-moments.svg"));
  std::ifstream js(out / "r.json");
  const Json j = Json::parse(js);
  ASSERT_TRUE(j.contains("trial_end"));
  EXPECT_EQ(j["trial_end"]["unmet"], "knee_zone");
  // The knee above its zone of stability at the trial's end, by the amount printed.
  EXPECT_GT(j["trial_end"]["knee_flexion_deg"].get<double>(), j["trial_end"]["zone_of_stability_deg"].get<double>());
  EXPECT_TRUE(j["swing_time_s"].is_null());  // NaN: no swing end
}

}  // namespace
