// The report of an accepted hyperextension_phase quotes its measured interval (held against
// Chien Table 1's phase 4 in the calibration study), not "not measured", and says that its
// estimate is biased beyond its spread.
#include <gtest/gtest.h>

#include <string>

#include "report/diagnosis_coverage.h"

namespace swingsim {
namespace {

TEST(HyperextensionCoverage, TheLineQuotesTheMeasuredCoefficients) {
  const auto m = findMeasuredCoverage("hyperextension_phase");
  ASSERT_TRUE(m.has_value());
  EXPECT_EQ(std::string(m->parameter), "f_N");
  EXPECT_EQ(m->scored, m->seeds);  // every seed scored: a coefficient held against a truth
  const std::string line = formatMeasuredCoverage("hyperextension_phase");
  EXPECT_NE(line.find("the 95 % interval of f_N held the truth in"), std::string::npos) << line;
  EXPECT_NE(line.find("k_N_per_m and c_Ns_per_m"), std::string::npos) << line;
  EXPECT_NE(line.find("bias"), std::string::npos) << line;
  EXPECT_EQ(line.find("not measured"), std::string::npos) << line;
}

}  // namespace
}  // namespace swingsim
