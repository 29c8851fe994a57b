// The calibration rows the report quotes for the cylinder's inertia (measured on the bench
// generator's moving mass) and switch_delay (whose caveat must quote its measured rate, not
// a round figure that disagrees with its own row).
#include <gtest/gtest.h>

#include <string>

#include "report/diagnosis_coverage.h"

namespace swingsim {
namespace {

TEST(CalibrationCoverageRows, InertiaIsMeasured) {
  const auto m = findMeasuredCoverage("inertia");
  ASSERT_TRUE(m.has_value());
  EXPECT_EQ(std::string(m->parameter), "mass_kg");
  EXPECT_GE(m->seeds, 20);
  EXPECT_LE(m->covered, m->scored);
  EXPECT_LE(m->scored, m->seeds);
  const std::string line = formatMeasuredCoverage("inertia");
  EXPECT_NE(line.find("the 95 % interval of mass_kg held the truth in " + std::to_string(m->covered) + " of " +
                      std::to_string(m->scored)),
            std::string::npos)
      << line;
}

TEST(CalibrationCoverageRows, SwitchDelaysCaveatQuotesItsOwnRow) {
  const auto m = findMeasuredCoverage("switch_delay");
  ASSERT_TRUE(m.has_value());
  const std::string caveat = m->caveat;
  EXPECT_NE(caveat.find(std::to_string(m->covered) + " of " + std::to_string(m->scored) + " seeds"), std::string::npos)
      << caveat;
  EXPECT_EQ(caveat.find("about 80 %"), std::string::npos) << caveat;
}

}  // namespace
}  // namespace swingsim
