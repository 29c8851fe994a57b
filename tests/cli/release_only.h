#pragma once
// Tests that take more than a few seconds run in the Release pass only: the sanitized build
// (SWINGSIM_SANITIZE, scripts/test.sh's second pass) runs them several times slower, and CI
// must stay under an hour. Use SWINGSIM_RELEASE_ONLY() as a test's first statement.
#include <gtest/gtest.h>

namespace swingsim::testing {
#ifdef SWINGSIM_SANITIZED
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
}  // namespace swingsim::testing

#define SWINGSIM_RELEASE_ONLY()                                                         \
  do {                                                                                  \
    if (swingsim::testing::kSanitized) GTEST_SKIP() << "Release pass only (slow under the sanitizers)"; \
  } while (false)
