// `swingsim generate`'s sequence (study/generate_run.h): the swing-kinematics generator is
// reproducible and makes the committed demo data again; a study of an unknown kind, or whose output would overwrite
// the study, is refused with nothing written.
#include "study/generate_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "../cli/run_swingsim.h"
#include "core/input_error.h"
#include "core/units.h"
#include "io/swing_record_csv.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;
using swingsim::testing::slurp;

const std::string kRoot = SWINGSIM_SOURCE_DIR;

fs::path scratch(const std::string& name) {
  return swingsim::testing::freshTempDir("swingsim_generate_run_test", name);
}

// Two runs write the same bytes; the committed demo data are what the committed study makes.
// They were written before the leg became two Simbody bodies (the foot part of the shank's
// body), which moved the simulated swings at round-off, grown to about 1e-5 deg after the
// stop impact: so agreement within the integrator's own error (its relative accuracy 1e-5 of a
// swing of at most 100 deg: 1e-3 deg; the noise added is 0.5 deg) on every sample both have,
// and the swing end at most one sample (2 ms) apart.
TEST(GenerateRun, SwingKinematicsAreReproducibleAndTheCommittedDemoData) {
  const fs::path dir = scratch("swing");
  const std::string study = kRoot + "/studies/diagnose-demo-swing-data.yaml";
  const double kIntegratorError = 1e-5 * 100.0;  // deg
  runGenerate(study, (dir / "a").string());
  runGenerate(study, (dir / "b").string());
  for (const char* name : {"slow", "normal", "fast"}) {
    const std::string file = std::string(name) + ".csv";
    ASSERT_TRUE(fs::exists(dir / "a" / file)) << file;
    EXPECT_EQ(slurp(dir / "a" / file), slurp(dir / "b" / file)) << name;
    const SwingRecord made = readSwingRecord((dir / "a" / file).string());
    const SwingRecord committed = readSwingRecord(kRoot + "/studies/data/diagnose-demo-swing/" + file);
    const std::size_t n = std::min(made.time.size(), committed.time.size());
    EXPECT_LE(std::max(made.time.size(), committed.time.size()) - n, 1u) << name;
    ASSERT_GT(n, 100u) << name;
    for (std::size_t k = 0; k < n; ++k) {
      ASSERT_EQ(made.time[k], committed.time[k]) << name << " sample " << k;
      EXPECT_NEAR(made.hipFlexion[k] * kRadToDeg, committed.hipFlexion[k] * kRadToDeg, kIntegratorError) << name << k;
      EXPECT_NEAR(made.kneeFlexion[k] * kRadToDeg, committed.kneeFlexion[k] * kRadToDeg, kIntegratorError) << name << k;
    }
  }
}

TEST(GenerateRun, AnUnknownKindIsRefusedAtItsLineWithTheKinds) {
  const fs::path dir = scratch("kind");
  const std::string study = (dir / "s.yaml").string();
  std::ofstream(study) << "name: x\nkind: cylinder-bench-2\n";
  try {
    runGenerate(study, (dir / "out").string());
    FAIL() << "an unknown kind was taken";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("s.yaml:2"), std::string::npos) << what;
    EXPECT_NE(what.find("cylinder-bench"), std::string::npos) << what;
    EXPECT_NE(what.find("swing-kinematics"), std::string::npos) << what;
  }
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(GenerateRun, AnOutputOverTheStudyIsRefusedBeforeAnyFileIsWritten) {
  const fs::path dir = scratch("over");
  std::string text = slurp(kRoot + "/studies/diagnose-demo-swing-data.yaml");
  for (const std::string key : {"participant: ../", "model: ../"})
    text.replace(text.find(key), key.size(), key.substr(0, key.size() - 3) + kRoot + "/");
  const std::string slow = "name: slow,";
  text.replace(text.find(slow), slow.size(), "name: s,");  // its CSV, s.csv, is the study file itself
  const std::string study = (dir / "s.csv").string();
  std::ofstream(study) << text;
  try {
    runGenerate(study, dir.string());
    FAIL() << "the study would have been overwritten";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("s.csv"), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(study), text);
  EXPECT_FALSE(fs::exists(dir / "normal.csv"));  // computed, not written
  EXPECT_FALSE(fs::exists(dir / "fast.csv"));
}

}  // namespace
}  // namespace swingsim
