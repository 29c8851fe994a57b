// `swingsim calibrate`'s sequence (study/calibration_run.h) on a copy of P1's file: the stored
// time scale gives the target swing time when the file is loaded and swung again; a dry run
// and a refused file leave every file as it was.
#include "study/calibration_run.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "../cli/run_swingsim.h"
#include "core/input_error.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "swing/knee_setup.h"
#include "swing/swing_simulation.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;
using swingsim::testing::slurp;

const std::string kRoot = SWINGSIM_SOURCE_DIR;

// P1's file in its own folder, its knee model named by an absolute path, under `name`.
std::string copyP1(const std::string& folder, const std::string& name) {
  const fs::path dir = swingsim::testing::freshTempDir("swingsim_calibration_run_test", folder);
  std::string text = slurp(kRoot + "/participants/p1.yaml");
  const std::string rel = "knee_model: ../", title = "name: P1";
  text.replace(text.find(rel), rel.size(), "knee_model: " + kRoot + "/");
  text.replace(text.find(title), title.size(), "name: " + name);
  const std::string path = (dir / "p.yaml").string();
  std::ofstream(path) << text;
  return path;
}

double swingTimeOf(const std::string& participantPath) {
  const Participant p = loadParticipant(participantPath);
  return simulateSwing(makeSwingSetup(p, loadKneeModel(p.kneeModelPath)), SwingOptions{}).swingTime;
}

TEST(CalibrationRun, TheStoredTimeScaleGivesTheTargetWhenSwungAgain) {
  const std::string path = copyP1("store", "P1");
  const double target = 0.45;  // s; P1's stored scale gives 0.420 s
  const double before = loadParticipant(path).hipMoment.timeScale;
  CalibrationRequest request;
  request.participants = {path};
  request.target = target;
  runCalibration(request);
  const double after = loadParticipant(path).hipMoment.timeScale;
  EXPECT_NE(after, before);
  EXPECT_EQ(after, std::round(after * 1e6) / 1e6);  // six decimals
  EXPECT_NEAR(swingTimeOf(path), target, 5e-4);
}

TEST(CalibrationRun, ADryRunChangesNoFile) {
  const std::string path = copyP1("dry", "P1");
  const std::string text = slurp(path);
  CalibrationRequest request;
  request.participants = {path};
  request.column = CalibrationTarget::kMeasured;
  request.dryRun = true;
  runCalibration(request);
  EXPECT_EQ(slurp(path), text);
}

TEST(CalibrationRun, ANameOutsideBurkettsTableNeedsATargetAndNoFileIsWritten) {
  const std::string good = copyP1("name-good", "P1"), stranger = copyP1("name-other", "Q7");
  const std::string goodText = slurp(good);
  CalibrationRequest request;
  request.participants = {good, stranger};  // the first calibrates; the second is refused before any write
  try {
    runCalibration(request);
    FAIL() << "a participant without a published swing time was calibrated";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'Q7' is not a Burkett 2004 participant; give --target SECONDS"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(slurp(good), goodText);
}

}  // namespace
}  // namespace swingsim
