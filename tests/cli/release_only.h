#pragma once
// Tests that take more than a few seconds run in the Release pass only: the sanitized build
// (SWINGSIM_SANITIZE, scripts/test.sh's second pass) runs them several times slower, and CI
// must stay under an hour. Use SWINGSIM_RELEASE_ONLY() as a test's first statement.
#include <gtest/gtest.h>

#include "../test_build.h"

#define SWINGSIM_RELEASE_ONLY()                                                                         \
  do {                                                                                                  \
    if (swingsim::testing::kSanitized) GTEST_SKIP() << "Release pass only (slow under the sanitizers)"; \
  } while (false)
