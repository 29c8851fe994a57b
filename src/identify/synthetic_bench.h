#pragma once
// Synthetic cylinder bench records, exactly as `swingsim generate` (kind: cylinder-bench)
// makes them: bench profile (docs/mauch.md), the shared velocity estimate, the truth
// model's force (which may carry hidden effects) and seeded white noise.
#include <cstdint>
#include <string>

#include "identify/bench_data.h"
#include "knee/bench_profile.h"

namespace swingsim {

/// One record. `noise` is the force noise standard deviation (N). Throws
/// std::invalid_argument on bad profile parameters.
BenchData makeSyntheticBench(const MauchCylinderParams& truth, const KneeAngleStride& stride,
                             const BenchProfileParams& profile, double noise, std::uint64_t seed,
                             const std::string& stem);

}  // namespace swingsim
