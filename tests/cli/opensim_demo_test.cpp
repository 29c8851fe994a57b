// The lab-data demo end to end on OpenSim's public subject01 walk, as the pipeline wrote it
// (studies/opensim-subject01-walk.yaml, docs/opensim-demo.md): the swings found in the IK
// file, the participant imported from the scaled model, and the diagnosis with the moving
// and the fixed hip. Release pass only: two diagnoses take about 5 s there.
#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io/json_file.h"
#include "release_only.h"
#include "run_swingsim.h"

namespace {

namespace fs = std::filesystem;
using swingsim::Json;
using swingsim::testing::CliRun;
using swingsim::testing::runSwingsim;
using ::testing::HasSubstr;

const std::string kRoot = SWINGSIM_SOURCE_DIR;
const std::string kData = kRoot + "/studies/data/opensim-subject01/";

fs::path freshDir(const std::string& name) { return swingsim::testing::freshTempDir("swingsim_opensim_demo", name); }

// A healthy subject's knee swung by his own thigh through a passive hinge whose damping is
// refitted: the knee should follow within a few degrees (Winter's walk: about 2-3 deg).
constexpr double kKneeRmseLimitDeg = 5;
// The refits' reference integrator against Simbody on the final model (moving-hip checks in
// tests/swing/reference_swing_test.cpp agree to 1e-7 deg at tight tolerance; the plant runs
// Simbody at 1e-4).
constexpr double kSimbodyCheckLimitDeg = 0.05;

Json readJson(const fs::path& path) { return Json::parse(swingsim::testing::slurp(path)); }

TEST(OpenSimDemo, SwingsFoundInTheIkFileAreTheForcePlatesThenTheKinematics) {
  const CliRun r = runSwingsim("swings " + kData + "gait2392_subject01_walk1_ik.mot --side r --grf " + kData +
                               "subject01_walk1_grf.mot");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("    1     1.4086          1.8522      0.4436  grf           grf"));
  EXPECT_THAT(r.output, HasSubstr("kinematics    kinematics"));  // swing 2 lies past the GRF file's end
}

TEST(OpenSimDemo, ShippedParticipantIsWhatImportOsimWrites) {
  const fs::path dir = freshDir("import");
  const CliRun r = runSwingsim("import-osim " + kData +
                               "gait2354_subject01_simbody.osim --side r --name opensim-subject01 "
                               "--knee " +
                               kRoot + "/models/passive-knee.yaml --out " + (dir / "p.yaml").string());
  ASSERT_EQ(r.code, 0) << r.output;
  // The shipped file adds a three-line header saying how it was made; the rest is the output,
  // apart from the knee model's path (relative to where each file lies).
  std::string shipped = swingsim::testing::slurp(kRoot + "/participants/opensim-subject01.yaml");
  for (int i = 0; i < 3; ++i) shipped.erase(0, shipped.find('\n') + 1);
  std::string written = swingsim::testing::slurp(dir / "p.yaml");
  const auto strip = [](std::string s) {
    const auto at = s.find("knee_model: ");
    return s.erase(at, s.find('\n', at) - at);
  };
  EXPECT_EQ(strip(written), strip(shipped));
}

TEST(OpenSimDemo, DiagnosisRunsOnThePipelineFilesWithTheMovingAndTheFixedHip) {
  SWINGSIM_RELEASE_ONLY();
  const fs::path dir = freshDir("diagnose");
  for (const std::string study : {"opensim-subject01-walk", "opensim-subject01-walk-fixed-hip"}) {
    const fs::path json = dir / (study + ".json");
    const CliRun r = runSwingsim("diagnose " + kRoot + "/studies/" + study + ".yaml --out " + (dir / study).string() +
                                 " --json " + json.string());
    ASSERT_EQ(r.code, 0) << r.output;
    const Json d = readJson(json);
    EXPECT_LT(d["final"]["train"]["rmse"].get<double>(), kKneeRmseLimitDeg) << study;
    EXPECT_LT(d["final"]["validation"]["right-swing-2"]["rmse"].get<double>(), kKneeRmseLimitDeg) << study;
    // The knee moment from inverse dynamics is compared where the .sto covers the swing.
    EXPECT_TRUE(d["knee_moment_comparison"]["after"]["files"].contains("right-swing-1")) << study;
    EXPECT_THAT(r.output, HasSubstr("Simbody check of the final model"));
    const auto at = r.output.find("max knee difference ");
    ASSERT_NE(at, std::string::npos);
    EXPECT_LT(std::stod(r.output.substr(at + 20)), kSimbodyCheckLimitDeg) << study;
    for (const char* f :
         {"report.md", "held-back.svg", "before-right-swing-1-overlay.svg", "after-right-swing-2-overlay.svg"})
      EXPECT_TRUE(fs::exists(dir / study / f)) << study << ": " << f;
  }
}

}  // namespace
