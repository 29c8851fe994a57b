// Inputs that once crashed, hung or leaked a non-InputError exception out of a loader
// (found by the libFuzzer targets in fuzz/, by review while writing them, or by probing):
// each must now give an InputError naming the file, quickly.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <functional>

#include "io/csv_table.h"
#include "io/cylinder_study.h"
#include "io/input_error.h"
#include "io/knee_model_loader.h"
#include "io/output_files.h"
#include "io/participant_loader.h"
#include "io/yaml_reader.h"
#include "swing/sweep.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

// Every regression must fail fast: these were hangs or crashes.
constexpr double kQuick = 5.0;  // s, under sanitizers

std::string inputErrorOf(const std::function<void()>& load) {
  const auto start = std::chrono::steady_clock::now();
  std::string message = "(no error)";
  try {
    load();
  } catch (const InputError& e) {
    message = e.what();
  } catch (const std::exception& e) {
    message = std::string("(escaped: not an InputError) ") + e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), kQuick);
  return message;
}

std::string kneeModelError(const std::string& text) {
  return inputErrorOf([&] { parseKneeModel(text, SWINGSIM_SOURCE_DIR "/models/fuzz.yaml"); });
}

std::string sweepError(const std::string& text) {
  return inputErrorOf([&] {
    const SweepStudy study = parseSweepStudy(text, SWINGSIM_SOURCE_DIR "/studies/fuzz.yaml");
    for (const auto& p : study.participants) sweepLowerings(study, p);
  });
}

// Review: JointStop's std::invalid_argument ("upper limit must exceed lower limit") escaped
// the loader without file or line when the stop engaged above 1e9 rad.
TEST(FuzzRegression, HyperextensionStopBeyondAnyAngleIsAnInputError) {
  const std::string e = kneeModelError(R"(kind: damping_table
damping_table: {flexion_deg: [0, 70], moment_Nm: [1, 4]}
hyperextension_stop: {engage_flexion_deg: 1e12}
)");
  EXPECT_THAT(e, HasSubstr("models/fuzz.yaml:3: hyperextension_stop.engage_flexion_deg: expected an angle near full extension"));
}

// Probe: a lowering step below the 1 um grid rounding never advanced: sweepLowerings
// looped forever, appending 0 m until memory ran out.
TEST(FuzzRegression, LoweringStepBelowTheGridIsAnInputErrorNotAHang) {
  const std::string head = "kind: knee-axis-sweep\nname: f\nparticipants: [../participants/p1.yaml]\n";
  EXPECT_THAT(sweepError(head + "lowering: {step_m: 1e-12}\n"),
              HasSubstr("studies/fuzz.yaml:4: lowering.step_m: expected a step of at least 0.0001 m (got 1e-12)"));
  // The smallest step allowed, with a max far beyond the shank: capped, a bounded grid.
  EXPECT_EQ(sweepError(head + "lowering: {step_m: 0.0001, max_m: 5}\n"), "(no error)");
  EXPECT_THAT(sweepError(head + "integrator: {sample_interval_s: 1e-300}\n"),
              HasSubstr("integrator.sample_interval_s: expected a sample interval"));
}

// Review: a time limit of 1e300 s turned a swing that never ends into a run that never ends.
TEST(FuzzRegression, HugeSwingTimeLimitIsAnInputError) {
  const std::string text = readFile("participants/p1.yaml");
  std::string bad = text;
  bad.replace(bad.find("time_limit_s: 1.5"), 17, "time_limit_s: 1e300");
  EXPECT_THAT(inputErrorOf([&] { parseParticipant(bad, "participants/p1.yaml"); }),
              HasSubstr("swing_end.time_limit_s: expected a time limit from 0 to 10 s (got 1e+300)"));
}

}  // namespace
}  // namespace swingsim
