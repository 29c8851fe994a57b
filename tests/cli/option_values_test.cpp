// Option values are checked while the command line is parsed (CLI11): a bad value, a missing
// argument or an option that does not fit the others is a usage error (exit 2) whose message
// names the option, and nothing runs. `SUB --help` gives each option's unit and default.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "run_swingsim.h"

namespace {

using swingsim::testing::CliRun;
using swingsim::testing::runSwingsim;
using ::testing::HasSubstr;

TEST(OptionValues, BadValuesAreUsageErrorsNamingTheOption) {
  struct Case {
    std::string args, message;
  };
  const Case cases[] = {
      {"simulate participants/p1.yaml --lowering abc", "--lowering: expected a number (got 'abc')"},
      {"simulate participants/p1.yaml --lowering inf", "--lowering: expected a number (got 'inf')"},
      {"simulate participants/p1.yaml --hip-rate-deg-s 1,5", "--hip-rate-deg-s: expected a number (got '1,5')"},
      {"simulate participants/p1.yaml --knee-rate-deg-s 1e9",
       "--knee-rate-deg-s: expected a knee rate in [-3000, 3000] deg/s (a swinging knee peaks near 500 deg/s)"},
      {"simulate participants/p1.yaml --add-mass 0.5",
       "--add-mass: expected KG@METRES below the knee, e.g. 0.5@0.20 (got '0.5')"},
      {"simulate participants/p1.yaml --add-mass -1@0.2", "--add-mass: expected KG@METRES"},
      {"sweep studies/burkett2004.yaml --jobs -1",
       "--jobs: expected 0 (all cores) or a positive whole number (got '-1')"},
      {"sweep studies/burkett2004.yaml --jobs 1.5",
       "--jobs: expected 0 (all cores) or a positive whole number (got '1.5')"},
      {"sweep studies/burkett2004.yaml --add-mass 1@x", "--add-mass: expected KG@METRES"},
      {"sweep studies/burkett2004.yaml --uncertainty 0",
       "--uncertainty: expected a whole number of samples from 1 to 100000 (got '0')"},
      {"sweep studies/burkett2004.yaml --uncertainty -3",
       "--uncertainty: expected a whole number of samples from 1 to 100000 (got '-3')"},
      {"sweep studies/burkett2004.yaml --uncertainty abc",
       "--uncertainty: expected a whole number of samples from 1 to 100000 (got 'abc')"},
      {"sweep studies/burkett2004.yaml --uncertainty 2.5",
       "--uncertainty: expected a whole number of samples from 1 to 100000 (got '2.5')"},
      {"sweep studies/burkett2004.yaml --uncertainty 100001",
       "--uncertainty: expected a whole number of samples from 1 to 100000 (got '100001')"},
      {"sweep studies/burkett2004.yaml --uncertainty 5 --seed -1",
       "--seed: expected a seed from 0 to 1000000000 (got '-1')"},
      {"sweep studies/burkett2004.yaml --uncertainty 5 --seed x",
       "--seed: expected a seed from 0 to 1000000000 (got 'x')"},
      {"calibrate participants/p1.yaml --target soon --dry-run",
       "--target: expected model, measured or a positive swing time in seconds, found 'soon'"},
      {"calibrate participants/p1.yaml participants/p2.yaml --target 0.4 --dry-run",
       "--target: applies to one participant file"},
      {"simulate participants/p1.yaml --lowering", "--lowering"},  // no value
      {"simulate", "PARTICIPANT.yaml is required"},
      {"fit", "STUDY.yaml is required"},
      {"simulate participants/p1.yaml participants/p2.yaml", "participants/p2.yaml"},
      {"frobnicate", "frobnicate"},
  };
  for (const Case& c : cases) {
    // Should a check fail to stop the run, it writes nothing.
    const bool hasOut = c.args.rfind("simulate", 0) == 0 || c.args.rfind("sweep", 0) == 0;
    const CliRun r = runSwingsim(c.args + (hasOut ? " --out /nonexistent/swingsim-option-values" : ""));
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.output;
    EXPECT_THAT(r.output, HasSubstr(c.message)) << c.args;
    EXPECT_THAT(r.output, HasSubstr("swingsim: ")) << c.args;
    EXPECT_THAT(r.output, HasSubstr("--help")) << c.args << ": no pointer to the help";
  }
}

TEST(OptionValues, HelpGivesUnitsAndDefaults) {
  const CliRun simulate = runSwingsim("simulate --help");
  ASSERT_EQ(simulate.code, 0);
  EXPECT_THAT(simulate.output, HasSubstr("knee-axis lowering below the standard location, m (default 0)"));
  EXPECT_THAT(simulate.output, HasSubstr("hip flexion rate at toe-off, deg/s (default: the participant's, 0)"));
  const CliRun sweep = runSwingsim("sweep --help");
  EXPECT_THAT(sweep.output, HasSubstr("worker threads, 0 = all cores (default 0)"));
  const CliRun top = runSwingsim("--help");
  ASSERT_EQ(top.code, 0);
  for (const char* c : {"simulate", "sweep", "calibrate", "fit", "compare", "diagnose", "generate", "--version"})
    EXPECT_THAT(top.output, HasSubstr(c));
}

}  // namespace
