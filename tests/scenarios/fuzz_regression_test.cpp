// Inputs that once crashed, hung or leaked a non-InputError exception out of a loader
// (found by the libFuzzer targets in fuzz/, by review while writing them, or by probing):
// each must now give an InputError naming the file, quickly.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <functional>

#include "core/input_error.h"
#include "core/output_files.h"
#include "io/csv_table.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "io/yaml_reader.h"
#include "study/cylinder_study.h"
#include "study/sweep_study.h"
#include "sweep/sweep.h"

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
  EXPECT_THAT(
      e,
      HasSubstr("models/fuzz.yaml:3: hyperextension_stop.engage_flexion_deg: expected an angle near full extension"));
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

std::string cylinderStudyError(const std::string& text) {
  return inputErrorOf([&] {
    YamlMap yaml = YamlMap::loadString(text, SWINGSIM_SOURCE_DIR "/studies/fuzz.yaml");
    yaml.getChoice("kind", {"cylinder-bench"}, "");
    readCylinderBenchStudy(yaml);
    yaml.finish();
  });
}

const std::string kBenchHead = R"(kind: cylinder-bench
model: ../models/mauch-4phase.yaml
knee_angles: data/winter-natural-cadence.csv
output_dir: /tmp/unused
conditions: [{name: normal, stride_s: 0.987}]
)";

// Probe: sample_rate_Hz: 1e300 overflowed the sample count (undefined behaviour, 0 samples):
// `swingsim generate` wrote three header-only bench files and exited 0. cycles: 9e8 ran
// the generator out of memory (2.3 GB after 20 s and growing).
TEST(FuzzRegression, BenchRecordSizeIsBounded) {
  EXPECT_THAT(cylinderStudyError(kBenchHead + "sample_rate_Hz: 1e300\n"),
              HasSubstr("sample_rate_Hz: expected a sample rate above 0 and at most 100000 Hz (got 1e+300)"));
  EXPECT_THAT(cylinderStudyError(kBenchHead + "cycles: 900000000\n"), HasSubstr("cycles: must be from 1 to 1000"));
  EXPECT_THAT(
      cylinderStudyError(kBenchHead + "cycles: 1000\nsample_rate_Hz: 100000\n"),
      HasSubstr("conditions[0].stride_s: cycles x stride_s x sample_rate_Hz must give 16 to 10 million samples"));
  EXPECT_THAT(cylinderStudyError(kBenchHead + "hold_samples: 1e9\n"),
              HasSubstr("hold_samples: must be from 0 to 1000"));
  EXPECT_EQ(cylinderStudyError(kBenchHead), "(no error)");
}

// Fuzz (cylinder_study_fuzz and diagnosis_study_fuzz, 2026-11-24): an alias inside the list its anchor names
// (`key: &a [*a]`) is a cycle; the duplicate-key walk recursed until the stack overflowed.
TEST(FuzzRegression, AnAliasInsideItsOwnValueIsAnInputErrorNotAStackOverflow) {
  const std::string error =
      inputErrorOf([] { YamlMap::loadString("model: &loop\n  - *loop\n", SWINGSIM_SOURCE_DIR "/studies/fuzz.yaml"); });
  EXPECT_THAT(error, HasSubstr("levels deep (does an alias (*name) refer to the value that holds it?)"));
  // The fuzzer's own input.
  const std::string found =
      "# Chie&data/ma^^^`mn-  \n: &data/mauch21^^^^^^^^`ml\n  -  *data/mauch21^^^^^^^^`ml\n"
      "  - ../h0\x9ephase.Runo\n";
  EXPECT_NE(inputErrorOf([&] { YamlMap::loadString(found, SWINGSIM_SOURCE_DIR "/studies/fuzz.yaml"); }), "(no error)");
  // diagnosis_study_fuzz's: the anchor on the whole file, its alias under one of its keys.
  EXPECT_THAT(inputErrorOf([] {
                YamlMap::loadString(" &./paemo-swing\npast: *./paemo-swing\naswg \n",
                                    SWINGSIM_SOURCE_DIR "/studies/fuzz.yaml");
              }),
              HasSubstr("levels deep"));
}

}  // namespace
}  // namespace swingsim
