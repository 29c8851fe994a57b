#pragma once
// A Latin hypercube sample of the unit cube (McKay, Beckman & Conover 1979): n points in d
// dimensions, each dimension cut into n equal strata with one point in each, the strata
// paired at random and each point placed at random inside its stratum. A space-filling
// start set for a local optimiser, deterministic for a given seed.
#include <cstdint>
#include <vector>

namespace swingsim {

/// `points` points (>= 1) in [0, 1)^`dimensions` (>= 1), point-major: result[i][k] is
/// coordinate k of point i. The same seed gives the same set on every platform
/// (std::mt19937_64 and integer arithmetic only). Throws std::invalid_argument on a count < 1.
std::vector<std::vector<double>> makeLatinHypercube(int points, int dimensions, std::uint64_t seed);

}  // namespace swingsim
