#include "numerics/latin_hypercube.h"

#include <random>
#include <stdexcept>

namespace swingsim {

std::vector<std::vector<double>> makeLatinHypercube(int points, int dimensions, std::uint64_t seed) {
  if (points < 1 || dimensions < 1)
    throw std::invalid_argument("makeLatinHypercube: needs at least one point and one dimension");
  std::mt19937_64 random(seed);
  // Uniform in [0, 1) from 53 random bits: the same on every platform (uniform_real_distribution is not).
  const auto unit = [&random] { return static_cast<double>(random() >> 11) * 0x1.0p-53; };
  std::vector<std::vector<double>> set(static_cast<std::size_t>(points),
                                       std::vector<double>(static_cast<std::size_t>(dimensions)));
  std::vector<int> strata(static_cast<std::size_t>(points));
  for (int k = 0; k < dimensions; ++k) {
    for (int i = 0; i < points; ++i) strata[static_cast<std::size_t>(i)] = i;
    // Fisher-Yates with the generator's raw output (std::shuffle's draws are implementation-defined).
    for (int i = points - 1; i > 0; --i) {
      const auto j = static_cast<int>(random() % static_cast<std::uint64_t>(i + 1));
      std::swap(strata[static_cast<std::size_t>(i)], strata[static_cast<std::size_t>(j)]);
    }
    for (int i = 0; i < points; ++i)
      set[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] =
          (strata[static_cast<std::size_t>(i)] + unit()) / points;
  }
  return set;
}

}  // namespace swingsim
