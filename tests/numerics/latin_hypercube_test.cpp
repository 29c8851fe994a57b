// The Latin hypercube start set (numerics/latin_hypercube.h).
#include "numerics/latin_hypercube.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

namespace swingsim {
namespace {

TEST(LatinHypercube, PutsOnePointInEachStratumOfEachDimension) {
  const int n = 24, d = 3;
  const auto set = makeLatinHypercube(n, d, 7);
  ASSERT_EQ(set.size(), static_cast<std::size_t>(n));
  for (int k = 0; k < d; ++k) {
    std::set<int> strata;
    for (const auto& p : set) {
      ASSERT_GE(p[static_cast<std::size_t>(k)], 0.0);
      ASSERT_LT(p[static_cast<std::size_t>(k)], 1.0);
      strata.insert(static_cast<int>(p[static_cast<std::size_t>(k)] * n));
    }
    EXPECT_EQ(strata.size(), static_cast<std::size_t>(n)) << "dimension " << k;
  }
}

TEST(LatinHypercube, TheSameSeedGivesTheSameSetAndAnotherSeedAnother) {
  EXPECT_EQ(makeLatinHypercube(10, 2, 1), makeLatinHypercube(10, 2, 1));
  EXPECT_NE(makeLatinHypercube(10, 2, 1), makeLatinHypercube(10, 2, 2));
  // The dimensions are not paired in order (a diagonal would fill nothing).
  const auto set = makeLatinHypercube(10, 2, 1);
  int diagonal = 0;
  for (const auto& p : set) diagonal += static_cast<int>(p[0] * 10) == static_cast<int>(p[1] * 10);
  EXPECT_LT(diagonal, 10);
}

TEST(LatinHypercube, RefusesAnEmptySet) {
  EXPECT_THROW(makeLatinHypercube(0, 2, 1), std::invalid_argument);
  EXPECT_THROW(makeLatinHypercube(3, 0, 1), std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
