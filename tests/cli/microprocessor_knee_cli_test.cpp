// `swingsim simulate --knee models/microprocessor-knee-osl.yaml` (the shipped microprocessor
// knee example, docs/formats.md) runs and ends P1's swing; a bad microprocessor knee file is
// refused with file:line: key and exit 1, writing nothing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/json_file.h"
#include "run_swingsim.h"

namespace {

using swingsim::Json;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

TEST(MicroprocessorKneeCli, ShippedExampleEndsP1sSwing) {
  const fs::path out = swingsim::testing::freshTempDir("swingsim_microprocessor_knee_cli_test", "osl");
  const auto r =
      swingsim::testing::runSwingsim("simulate participants/p1.yaml --knee models/microprocessor-knee-osl.yaml --out " +
                                     out.string() + " --json " + (out / "r.json").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("knee model microprocessor-knee-osl"));
  std::ifstream js(out / "r.json");
  const Json j = Json::parse(js);
  // The swing ends (knee back in the zone), well inside P1's 1.5 s time limit.
  ASSERT_TRUE(j["swing_time_s"].is_number()) << r.output;
  EXPECT_GT(j["swing_time_s"].get<double>(), 0.2);
  EXPECT_LT(j["swing_time_s"].get<double>(), 1.0);
  EXPECT_TRUE(fs::exists(out / "P1-lower000mm.csv"));
}

TEST(MicroprocessorKneeCli, BadFileIsRefusedWithItsLineAndNothingWritten) {
  std::string text = swingsim::testing::slurp("models/microprocessor-knee-osl.yaml");
  const std::string from = "damping_Nm_s_per_rad: 3.816";
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, from.size(), "damping_Nm_s_per_rad: -3.816");
  const std::string knee =
      swingsim::testing::writeSuiteTempFile("swingsim_microprocessor_knee_cli_test", "negative-damping.yaml", text);
  const fs::path out = swingsim::testing::freshTempDir("swingsim_microprocessor_knee_cli_test", "bad");
  fs::remove_all(out);
  const auto r =
      swingsim::testing::runSwingsim("simulate participants/p1.yaml --knee " + knee + " --out " + out.string());
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("negative-damping.yaml:"));
  EXPECT_THAT(r.output,
              HasSubstr("impedance_state_machine.states[1].damping_Nm_s_per_rad: expected a damping in [0, "));
  EXPECT_THAT(r.output, HasSubstr("(got -3.816)"));
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
