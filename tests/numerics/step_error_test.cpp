// The error norm and tolerance check the embedded Runge-Kutta pairs share
// (numerics/step_error.h): Hairer's weighted RMS, by hand on small cases.
#include "numerics/step_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace swingsim {
namespace {

constexpr double kRoundOff = 1e-15;

TEST(StepError, NormIsTheRmsOfErrorsOverTheirScales) {
  // One component: |err| / (absTol + relTol max(|y0|, |y1|)).
  EXPECT_NEAR(calcStepErrorNorm({2}, {-4}, {0.5}, 0.1, 0.1), 0.5 / (0.1 + 0.1 * 4), kRoundOff);
  // Two components with scales 1 and 2 (absTol 1, relTol 0): sqrt((1^2 + (1/2)^2) / 2).
  EXPECT_NEAR(calcStepErrorNorm({0, 0}, {0, 0}, {1, -1}, 0, 1), 1.0, kRoundOff);
  EXPECT_NEAR(calcStepErrorNorm({0, 10}, {0, 10}, {1, 1}, 0.1, 1), std::sqrt((1.0 + 0.25) / 2), kRoundOff);
  // The larger of the two states sets the scale, whatever its sign or which end it is at.
  EXPECT_EQ(calcStepErrorNorm({-10}, {1}, {1}, 0.1, 1), calcStepErrorNorm({1}, {10}, {1}, 0.1, 1));
  EXPECT_EQ(calcStepErrorNorm({3, 3}, {3, 3}, {0, 0}, 1e-6, 1e-6), 0.0);
}

TEST(StepError, ToleranceCheckNamesTheMethod) {
  EXPECT_NO_THROW(checkStepTolerances("DormandPrince", 1e-8, 1e-12));
  for (const double bad :
       {0.0, -1e-6, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
    try {
      checkStepTolerances("BogackiShampine", bad, 1e-6);
      ADD_FAILURE() << "relTol " << bad << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), "BogackiShampine: tolerances must be positive and finite");
    }
    EXPECT_THROW(checkStepTolerances("DormandPrince", 1e-6, bad), std::invalid_argument) << "absTol " << bad;
  }
}

}  // namespace
}  // namespace swingsim
