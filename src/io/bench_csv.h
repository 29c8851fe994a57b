#pragma once
// Reading the cylinder bench inputs: bench data CSV (time_s, position_m, force_N) and the
// Winter-style knee-angle CSV (frame, knee_deg) that bench profiles are made from.
#include <cstddef>
#include <string>

#include "knee/bench_profile.h"
#include "model/bench_record.h"

namespace swingsim {

/// Reads a bench CSV. Requires columns time_s, position_m, force_N (others ignored),
/// strictly increasing time, finite numbers, at least `minRows` rows (>= 3) and a position
/// that varies. Throws InputError with `file:line: column: ...`.
BenchData readBenchCsv(const std::string& path, std::size_t minRows);

/// Reads frames `firstFrame`..`lastFrame` (heel strike to heel strike, `frame` column) of
/// knee_deg from a Winter-style CSV (columns frame, knee_deg). The last frame is the next
/// heel strike and is dropped (the stride repeats). Throws InputError naming the file.
KneeAngleStride readKneeAngleStride(const std::string& csvPath, int firstFrame, int lastFrame);

}  // namespace swingsim
