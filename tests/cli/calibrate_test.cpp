// `swingsim calibrate` edits the user's participant file through the parsed document: any
// valid YAML style loads back after the edit, symlinks and permissions survive, and a
// failing file on the command line leaves every file unchanged.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "io/participant_loader.h"
#include "run_swingsim.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;
const std::string kRoot = SWINGSIM_SOURCE_DIR;

using testing::slurp;

fs::path freshDir(const std::string& name) { return testing::freshTempDir("swingsim_calibrate_test", name); }

// P1 with the knee model path made absolute, so the file can live anywhere.
std::string p1Text() {
  std::string t = slurp(kRoot + "/participants/p1.yaml");
  return std::regex_replace(t, std::regex("\\.\\./models/"), kRoot + "/models/");
}

// Calibrates `text` written as `name` to 0.43 s and checks the result loads, holds the
// printed time scale, and differs from the original in nothing else.
void expectCalibrated(const std::string& name, const std::string& text) {
  const fs::path dir = freshDir(name);
  const fs::path file = dir / "p.yaml";
  std::ofstream(file) << text;
  const Participant before = loadParticipant(file.string());
  const auto r = testing::runSwingsim("calibrate " + file.string() + " --target 0.43");
  ASSERT_EQ(r.code, 0) << name << "\n" << r.output;
  ASSERT_THAT(r.output, ::testing::HasSubstr("stored in"));
  const Participant after = loadParticipant(file.string());  // throws if the file was corrupted
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.output, m, std::regex("time scale ([0-9.]+)"))) << r.output;
  EXPECT_NEAR(after.hipMoment.timeScale, std::stod(m[1]), 1e-6) << name;
  Participant expected = before;
  expected.hipMoment.timeScale = after.hipMoment.timeScale;
  EXPECT_EQ(formatParticipantYaml(after, dir.string()), formatParticipantYaml(expected, dir.string())) << name;
}

TEST(Calibrate, EditsFlowStyleIndentedAndSpacedYamlThroughTheParsedDocument) {
  const std::string base = p1Text();
  // hip_moment as one flow map.
  std::string flow = base.substr(0, base.find("hip_moment:")) +
                     "hip_moment: {profile: biphasic_sine, flexion_amplitude_Nm: 30, flexion_duration_s: 0.20, "
                     "extension_amplitude_Nm: 15, extension_duration_s: 0.20, time_scale: 1.08}\n";
  expectCalibrated("flow", flow);
  // Every block indented by 4 spaces.
  expectCalibrated("indent4", std::regex_replace(base, std::regex("\n  "), "\n    "));
  // A space before the colon.
  expectCalibrated("spaced", std::regex_replace(base, std::regex("time_scale: "), "time_scale : "));
}

TEST(Calibrate, KeepsTheLeadingCommentsThePermissionsAndWritesThroughASymlink) {
  const fs::path dir = freshDir("symlink");
  const fs::path target = dir / "real.yaml", link = dir / "link.yaml";
  std::ofstream(target) << p1Text();
  fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write, fs::perm_options::replace);
  fs::create_symlink(target, link);
  const auto r = testing::runSwingsim("calibrate " + link.string() + " --target 0.43");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(fs::status(target).permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
  const std::string text = slurp(target);
  EXPECT_EQ(text.rfind("# Participant P1: Burkett, Smeathers & Barker (2004)", 0), 0u) << text.substr(0, 200);
  EXPECT_NO_THROW(loadParticipant(link.string()));
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().string().find(".tmp-"), std::string::npos) << "left behind: " << e.path();
}

TEST(Calibrate, AFailingFileLeavesEveryFileUnchanged) {
  const fs::path dir = freshDir("allornothing");
  const fs::path good = dir / "good.yaml", bad = dir / "bad.yaml";
  std::ofstream(good) << p1Text();
  std::ofstream(bad) << std::regex_replace(p1Text(), std::regex("mass_kg: 3.350"), "mass_kg: -3.35");
  const std::string before = slurp(good);
  const auto r = testing::runSwingsim("calibrate " + good.string() + " " + bad.string());
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_THAT(r.output, ::testing::HasSubstr("bad.yaml:10: segments.thigh.mass_kg: must be positive"));
  EXPECT_EQ(slurp(good), before);
}

}  // namespace
}  // namespace swingsim

namespace swingsim {
namespace {

// --target measured calibrates to Burkett Table 3's measured column; a word that is neither
// column nor a number is refused before anything runs.
TEST(Calibrate, TargetMeasuredUsesTable3MeasuredAndBadTargetsAreRefused) {
  const fs::path dir = freshDir("measured");
  const fs::path file = dir / "p.yaml";
  std::ofstream(file) << p1Text();
  const auto r = testing::runSwingsim("calibrate " + file.string() + " --target measured --dry-run");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_THAT(r.output, ::testing::HasSubstr("(target 0.4630 s)"));  // Table 3, P1 measured
  for (const char* bad : {"fast", "-0.4", "0", "nan", "0.4s"}) {
    const auto b = testing::runSwingsim("calibrate " + file.string() + " --target " + bad + " --dry-run");
    EXPECT_NE(b.code, 0) << bad;
    EXPECT_THAT(b.output, ::testing::HasSubstr("expected model, measured or a positive swing time")) << bad;
  }
}

}  // namespace
}  // namespace swingsim
