// The plausibility check of file values (core/plausible_ranges.h): the bounds are inclusive,
// the message names the quantity, range, unit and reason, and a missing-data marker gets
// its hint.
#include "core/plausible_ranges.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

namespace swingsim {
namespace {

constexpr PlausibleRange kTestRange{-2, 3.5, "N", "what a test bench reaches"};

TEST(PlausibleRanges, BoundsAreInsideAndTheMessageSaysWhatWasExpected) {
  EXPECT_EQ(checkPlausible(-2, kTestRange, "a force"), "");
  EXPECT_EQ(checkPlausible(3.5, kTestRange, "a force"), "");
  EXPECT_EQ(checkPlausible(3.6, kTestRange, "a force"), "expected a force in [-2, 3.5] N (what a test bench reaches)");
  EXPECT_EQ(checkPlausible(std::numeric_limits<double>::quiet_NaN(), kTestRange, "a force"),
            "expected a force in [-2, 3.5] N (what a test bench reaches)")
      << "NaN is never in range";
  constexpr PlausibleRange kUnitless{0, 1, "", "a fraction"};
  EXPECT_EQ(checkPlausible(2, kUnitless, "a fraction"), "expected a fraction in [0, 1] (a fraction)");
}

TEST(PlausibleRanges, AMissingDataMarkerIsNamed) {
  EXPECT_EQ(checkPlausible(9.9e37, kTestRange, "a force"),
            "expected a force in [-2, 3.5] N (what a test bench reaches); a value this large is usually a missing-data "
            "marker: remove the row or fill the gap");
  EXPECT_NE(checkPlausible(-1e38, kTestRange, "a force").find("missing-data marker"), std::string::npos);
  EXPECT_EQ(checkPlausible(1e36, kTestRange, "a force").find("missing-data marker"), std::string::npos);
}

}  // namespace
}  // namespace swingsim
