// printf-style formatting (core/text_format.h): an absent value prints "none", never a
// marker number.
#include "core/text_format.h"

#include <gtest/gtest.h>

#include <optional>

namespace swingsim {
namespace {

TEST(TextFormat, FormatsLikePrintf) { EXPECT_EQ(fmt("%.3f s", 0.25), "0.250 s"); }

TEST(TextFormat, AnAbsentValueIsNone) {
  EXPECT_EQ(fmtOrNone("%.1f deg", std::nullopt), "none");
  EXPECT_EQ(fmtOrNone("%.1f deg", std::nullopt, 57.3), "none");
}

TEST(TextFormat, APresentValueIsScaledAndFormatted) {
  EXPECT_EQ(fmtOrNone("%.1f deg", 2.0, 10.0), "20.0 deg");
  EXPECT_EQ(fmtOrNone("%.3f m", -0.0125), "-0.013 m");
}

}  // namespace
}  // namespace swingsim
