#include "study/run_arguments.h"

#include <gtest/gtest.h>

#include <limits>

#include "core/input_error.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim {
namespace {

// The sample limit is the analysis's own: one constant, not a copy.
TEST(RunArguments, SamplesRangeIsTheAnalysisLimit) {
  const WholeNumberRange& r = uncertaintySamplesRange();
  EXPECT_EQ(r.min, 1);
  EXPECT_EQ(r.max, kMaxUncertaintySamples);
  EXPECT_EQ(r.check(1LL), "");
  EXPECT_EQ(r.check(static_cast<long long>(kMaxUncertaintySamples)), "");
  EXPECT_EQ(r.check(static_cast<long long>(kMaxUncertaintySamples) + 1), r.expected);
  EXPECT_EQ(r.check(0LL), r.expected);
  EXPECT_EQ(r.expected, "expected a whole number of samples from 1 to " + std::to_string(kMaxUncertaintySamples));
}

// Python's uncertainty= also takes 0 (none); the same upper limit.
TEST(RunArguments, UncertaintyOrNoneTakesZero) {
  const WholeNumberRange& r = uncertaintyOrNoneRange();
  EXPECT_EQ(r.check(0LL), "");
  EXPECT_EQ(r.max, uncertaintySamplesRange().max);
  EXPECT_EQ(r.check(-1LL), r.expected);
  EXPECT_EQ(r.check(1000000000LL), r.expected);
}

// A double is whole and in range, or refused: 2.5 is not 2, 1e300 is not cast.
TEST(RunArguments, DoublesMustBeWholeAndInRange) {
  const WholeNumberRange& r = seedRange();
  EXPECT_EQ(r.check(2.0), "");
  EXPECT_EQ(r.check(2.5), r.expected);
  EXPECT_EQ(r.check(-1.0), r.expected);
  EXPECT_EQ(r.check(1e300), r.expected);
  EXPECT_EQ(r.check(std::numeric_limits<double>::quiet_NaN()), r.expected);
  EXPECT_EQ(r.check(static_cast<double>(kMaxSeed)), "");
  EXPECT_EQ(r.check(static_cast<double>(kMaxSeed) + 1), r.expected);
}

// Each range names its bounds or its meaning in the text the CLI and Python print.
TEST(RunArguments, RangesSayWhatIsExpected) {
  EXPECT_EQ(seedRange().expected, "expected a seed from 0 to 1000000000");
  EXPECT_EQ(jobsRange().check(-3LL), "expected 0 (all cores) or a positive whole number");
  EXPECT_EQ(jobsRange().check(0LL), "");
  EXPECT_EQ(maxSwingsRange().check(0LL), "expected a whole number of swings from 1");
}

TEST(RunArguments, LoweringMustBeFinite) {
  EXPECT_EQ(checkLowering(0.05), "");
  EXPECT_EQ(checkLowering(-0.01), "");  // the swing set-up judges it against the leg
  EXPECT_EQ(checkLowering(std::numeric_limits<double>::infinity()), "expected a number");
  EXPECT_EQ(checkLowering(std::numeric_limits<double>::quiet_NaN()), "expected a number");
}

TEST(RunArguments, MessageNamesTheArgument) {
  EXPECT_EQ(formatArgumentProblem("sweep(): seed", seedRange().expected, "-1"),
            "sweep(): seed: expected a seed from 0 to 1000000000, got -1");
}

// A seed with no analysis to seed is refused with the caller's names; with samples it applies.
TEST(RunArguments, SeedNeedsAnAnalysis) {
  SweepStudy study;
  study.path = "s.yaml";
  const UncertaintyArgumentNames names{"sweep(): seed", "uncertainty=N", "seed=3"};
  try {
    applyUncertaintyArguments(study, std::nullopt, 3, names);
    FAIL() << "a seed alone was taken";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "sweep(): seed: sets the seed of the uncertainty analysis, which needs uncertainty=N or "
                 "an `uncertainty:` map in s.yaml (got seed=3 alone)");
  }
  applyUncertaintyArguments(study, 4, 3, names);
  EXPECT_EQ(study.uncertaintySamples, 4);
  EXPECT_EQ(study.uncertaintySeed, 3);
}

}  // namespace
}  // namespace swingsim
