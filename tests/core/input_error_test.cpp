// Numbers in messages (core/input_error.h): the shortest text that reads back as the same
// double, and times to 0.1 ms.
#include "core/input_error.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>

namespace swingsim {
namespace {

TEST(InputError, NumbersAreTheShortestTextThatReadsBackTheSame) {
  EXPECT_EQ(formatNumber(0.05), "0.05");
  EXPECT_EQ(formatNumber(1000), "1000");
  EXPECT_EQ(formatNumber(-2.5), "-2.5");
  EXPECT_EQ(formatNumber(0.1 + 0.2), "0.30000000000000004") << "not rounded to a different number";
  for (const double v : {1e-300, 123456.789, 2.0 / 3, 9.9e37})
    EXPECT_EQ(std::strtod(formatNumber(v).c_str(), nullptr), v);
}

TEST(InputError, TimesAreRoundedToATenthOfAMillisecond) {
  EXPECT_EQ(formatSeconds(0.41234567), "0.4123");
  EXPECT_EQ(formatSeconds(0.41235001), "0.4124");
  EXPECT_EQ(formatSeconds(2), "2");
}

TEST(InputError, BothErrorKindsAreRuntimeErrorsWithTheirMessage) {
  const InputError input("a.yaml:3: mass_kg: expected a number");
  const RunError run("P1: the swing did not end");
  const std::runtime_error& asRuntime = input;
  EXPECT_STREQ(asRuntime.what(), "a.yaml:3: mass_kg: expected a number");
  EXPECT_STREQ(static_cast<const std::runtime_error&>(run).what(), "P1: the swing did not end");
}

}  // namespace
}  // namespace swingsim
