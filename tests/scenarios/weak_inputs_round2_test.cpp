// Issue 41 item 7: the second set's weak cases, each refused with its file, line, key and
// reason (they were answered "bad file", "expected a finite number" or taken silently):
// YAML merge keys, very deep nesting, a subnormal number, a Mauch hyperextension position
// of -1e300 m, and a relative path in a file read from a pipe.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "../cli/run_swingsim.h"
#include "../test_build.h"
#include "core/input_error.h"
#include "io/csv_table.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "io/yaml_reader.h"

namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using namespace swingsim;

const std::string kRoot = SWINGSIM_SOURCE_DIR;

template <class F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// participants/p1.yaml with `from` replaced by `to` (and its knee model found from anywhere).
std::string p1With(const std::string& from, const std::string& to) {
  std::string text = swingsim::testing::slurp(kRoot + "/participants/p1.yaml");
  text.replace(text.find("../models/"), 10, kRoot + "/models/");
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(WeakInputsRound2, AYamlMergeKeyIsNamedAsUnsupportedWithItsLine) {
  const std::string text = "a: &base {x: 1}\nb:\n  <<: *base\n  y: 2\n";
  EXPECT_THAT(errorOf([&] { YamlMap::loadString(text, "m.yaml"); }),
              HasSubstr("m.yaml:3: <<: YAML merge keys are not supported"));
}

TEST(WeakInputsRound2, VeryDeepNestingSaysTheDepthLimit) {
  const std::string text = "a: " + std::string(5000, '[') + std::string(5000, ']') + "\n";
  const std::string error = errorOf([&] { YamlMap::loadString(text, "deep.yaml"); });
  EXPECT_THAT(error, HasSubstr("deep.yaml:1: values nested more than 64 levels deep (the limit"));
  EXPECT_THAT(error, Not(HasSubstr("bad file")));
}

TEST(WeakInputsRound2, ASubnormalNumberIsTooSmallNotNonFinite) {
  const std::string error =
      errorOf([&] { parseParticipant(p1With("knee_friction_Nm: 10", "knee_friction_Nm: 1e-320"), "p.yaml"); });
  EXPECT_THAT(error, HasSubstr("p.yaml:13: knee_friction_Nm: too small"));
  EXPECT_THAT(error, HasSubstr("below 1e-300"));
  EXPECT_THAT(error, Not(HasSubstr("finite")));
}

TEST(WeakInputsRound2, ANumberThatUnderflowsToZeroIsTooSmallNotZero) {
  const std::string error =
      errorOf([&] { parseParticipant(p1With("knee_friction_Nm: 10", "knee_friction_Nm: 1e-400"), "p.yaml"); });
  EXPECT_THAT(error, HasSubstr("p.yaml:13: knee_friction_Nm: too small"));
}

TEST(WeakInputsRound2, ASubnormalNumberInACsvIsTooSmallNotNonFinite) {
  CsvSpec spec;
  spec.required = {"a", "b"};
  const std::string error = errorOf([&] { parseCsv("a,b\n1,1e-320\n", "t.csv", spec); });
  EXPECT_THAT(error, HasSubstr("b: too small"));
  EXPECT_THAT(error, Not(HasSubstr("finite")));
}

TEST(WeakInputsRound2, AMauchHyperextensionPositionOfMinus1e300IsRefused) {
  std::string text = swingsim::testing::slurp(kRoot + "/models/mauch-2phase.yaml");
  text.replace(text.find("hyperextension_position_m: 0.00005"), 34, "hyperextension_position_m: -1e300");
  EXPECT_THAT(errorOf([&] { parseKneeModel(text, "m.yaml"); }),
              HasSubstr("m.yaml:16: switches.hyperextension_position_m: expected a piston position in [-0.1, 0.1] m"));
}

TEST(WeakInputsRound2, ARelativeKneeModelInAFileReadFromAPipeNamesTheKeyAndTheReason) {
  // Process substitution needs bash: `swingsim simulate <(cat p1.yaml)` reads /dev/fd/63.
  const std::string command = "bash -c '" + std::string(SWINGSIM_BINARY) + " simulate <(cat " + kRoot +
                              "/participants/p1.yaml) --out /tmp/swingsim-never-written' 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string output;
  char buf[4096];
  while (std::fgets(buf, sizeof buf, pipe)) output += buf;
  const int status = pclose(pipe);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << output;
  struct {
    std::string output;
  } run{output};
  EXPECT_THAT(run.output, HasSubstr(":14: knee_model: relative path '../models/damping-table-default.yaml' cannot be "
                                    "resolved next to /dev/fd/"));
  EXPECT_THAT(run.output, HasSubstr("(a pipe); give an absolute path or a file"));
}

}  // namespace
