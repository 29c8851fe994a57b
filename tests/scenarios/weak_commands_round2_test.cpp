// Issue 41 items 6 and 7 with the real binary: `calibrate` on a thigh-driven participant
// refused with the reason (it advised --target, which then failed too), `measurement_noise: 0`
// refused instead of silently meaning "estimate it", and a swing record's knee moment in
// N mm refused as such (the 2000 N m range let 1.5 N m written as 1500 through).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../cli/run_swingsim.h"

namespace {

namespace fs = std::filesystem;
using swingsim::testing::freshTempDir;
using swingsim::testing::runSwingsim;
using swingsim::testing::slurp;
using ::testing::HasSubstr;
using ::testing::Not;

const std::string kRoot = SWINGSIM_SOURCE_DIR;
const std::string kSuite = "swingsim-weak-commands";
const std::string kData = kRoot + "/studies/data/diagnose-demo-swing/";

// The swing diagnosis demo with absolute paths, training on `train`, plus `extra` lines.
fs::path writeSwingDiagnosis(const fs::path& dir, const std::string& train, const std::string& extra = "") {
  const fs::path path = dir / "diagnose.yaml";
  std::ofstream(path) << "kind: swing-diagnosis\nname: weak\nparticipant: " << kRoot
                      << "/participants/p1.yaml\nbase_model: " << kRoot
                      << "/models/damping-table-default.yaml\ntrain: [" << train << "]\nvalidate: [" << kData
                      << "slow.csv, " << kData << "fast.csv]\n"
                      << extra;
  return path;
}

TEST(WeakCommandsRound2, CalibrateOnAThighDrivenParticipantGivesTheReasonNotAdviceThatFails) {
  const auto run = runSwingsim("calibrate " + kRoot + "/participants/winter.yaml --dry-run");
  EXPECT_EQ(run.code, 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("winter.yaml: drive: thigh_kinematics: the measured thigh drives"));
  EXPECT_THAT(run.output, HasSubstr("no hip moment time scale to calibrate"));
  EXPECT_THAT(run.output, Not(HasSubstr("give --target")));
}

TEST(WeakCommandsRound2, MeasurementNoiseZeroIsRefusedWithTheAlternative) {
  const fs::path dir = freshTempDir(kSuite, "noise-zero");
  const auto run = runSwingsim(
      "diagnose " + writeSwingDiagnosis(dir, kData + "normal.csv", "acceptance: {measurement_noise: 0}\n").string() +
      " --out " + (dir / "out").string());
  EXPECT_EQ(run.code, 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("diagnose.yaml:7: acceptance.measurement_noise: expected a positive noise"));
  EXPECT_THAT(run.output, HasSubstr("leave measurement_noise out to estimate it from the data"));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(WeakCommandsRound2, AKneeMomentInNmmIsRefusedAsSuch) {
  const fs::path dir = freshTempDir(kSuite, "moment-nmm");
  // The demo's training record with a knee moment of up to 1.5 N m written in N mm.
  std::string in = slurp(kData + "normal.csv");
  std::string out;
  std::size_t line = 0, start = 0;
  for (std::size_t end; (end = in.find('\n', start)) != std::string::npos; start = end + 1, ++line)
    out += in.substr(start, end - start) +
           (line == 0 ? ",knee_moment_Nm" : "," + std::to_string(1500.0 * (line % 7) / 6)) + "\n";
  const fs::path record = dir / "normal-nmm.csv";
  std::ofstream(record) << out;
  const auto run = runSwingsim("diagnose " + writeSwingDiagnosis(dir, record.string()).string() + " --out " +
                               (dir / "out").string());
  EXPECT_EQ(run.code, 1) << run.output;
  EXPECT_THAT(run.output,
              HasSubstr("normal-nmm.csv: knee_moment: expected a peak |moment| of at most 10 N m/kg x 70 kg"));
  EXPECT_THAT(run.output, HasSubstr("it looks like N mm"));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace
