// `swingsim sweep STUDY --uncertainty N [--seed S]` end to end: the
// documented JSON keys per participant, the tornado figure and the report section, and a
// --seed without anything to seed refused before any swing runs. A tiny study: one
// participant, a 50 mm grid, two samples.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

#include "run_swingsim.h"

namespace {

using swingsim::testing::CliRun;
using swingsim::testing::freshTempDir;
using swingsim::testing::runSwingsim;
using swingsim::testing::slurp;
using ::testing::HasSubstr;

std::filesystem::path writeTinyStudy(const std::filesystem::path& dir, const std::string& extra) {
  return swingsim::testing::writeTinySweepStudy(dir, 0.2, extra);
}

TEST(SweepUncertaintyCli, WritesIntervalsSensitivityAndTornado) {
  const auto dir = freshTempDir("swingsim-uncertainty-cli", "run");
  const auto study = writeTinyStudy(dir, "uncertainty: {samples: 2, seed: 5}\n");
  const CliRun r = runSwingsim("sweep " + study.string() + " --out " + (dir / "out").string() + " --json " +
                               (dir / "out.json").string() + " --jobs 2");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("How sure is the optimum: 2 Monte Carlo samples, seed 5"));
  EXPECT_THAT(r.output, HasSubstr("swings/s"));  // the progress line's rate and time left
  EXPECT_THAT(r.output, HasSubstr("s left"));

  const auto json = nlohmann::json::parse(slurp(dir / "out.json"));
  const auto& p = json.at("participants").at(0);
  EXPECT_EQ(p.at("uncertainty_samples"), 2);
  EXPECT_EQ(p.at("seed"), 5);
  for (const char* key : {"fastest_lowering_interval_m", "fastest_time_interval_s"}) {
    const auto& i = p.at(key);
    EXPECT_LE(i.at("p05").get<double>(), i.at("median").get<double>()) << key;
    EXPECT_LE(i.at("median").get<double>(), i.at("p95").get<double>()) << key;
  }
  const auto& rows = p.at("sensitivity");
  ASSERT_GE(rows.size(), 10u);
  for (const char* key : {"assumption", "low_value", "high_value", "fastest_lowering_low_m", "fastest_lowering_high_m",
                          "time_low_s", "time_high_s"})
    EXPECT_TRUE(rows.at(0).contains(key)) << key;

  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "figures" / "P1-tornado.svg"));
  const std::string report = slurp(dir / "out" / "report.md");
  EXPECT_THAT(report, HasSubstr("## How sure is the optimum"));
  EXPECT_THAT(report, HasSubstr("figures/P1-tornado.svg"));
  EXPECT_THAT(slurp(dir / "out" / "figures" / "P1-swing-time.svg"), HasSubstr("5-95 % over the assumptions"));

  // The same seed on one thread: byte-identical JSON and report.
  const CliRun again = runSwingsim("sweep " + study.string() + " --out " + (dir / "out1").string() + " --json " +
                                   (dir / "out1.json").string() + " --jobs 1");
  ASSERT_EQ(again.code, 0) << again.output;
  EXPECT_EQ(slurp(dir / "out1.json"), slurp(dir / "out.json"));
  EXPECT_EQ(slurp(dir / "out1" / "report.md"), report);
  EXPECT_EQ(slurp(dir / "out1" / "figures" / "P1-tornado.svg"), slurp(dir / "out" / "figures" / "P1-tornado.svg"));
}

// The command line overrides the study's map; without either there is nothing to seed.
TEST(SweepUncertaintyCli, SeedAloneIsRefusedBeforeAnySwing) {
  const auto dir = freshTempDir("swingsim-uncertainty-cli", "seed-alone");
  const auto study = writeTinyStudy(dir, "");
  const CliRun r = runSwingsim("sweep " + study.string() + " --seed 3 --out " + (dir / "out").string());
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("swingsim: --seed: sets the seed of the uncertainty analysis, which needs "
                                  "--uncertainty N or an `uncertainty:` map in"));
  EXPECT_THAT(r.output, ::testing::Not(HasSubstr("swings (")));  // no progress: nothing ran
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

}  // namespace
