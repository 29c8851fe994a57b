#pragma once
// Reading measured swing times per participant and knee-axis lowering (the sweep plant's
// measurement; docs/formats.md "Measured sweep times"):
//   participant,lowering_m,swing_time_s[,sd_s,n]
// One header row, then one row per (participant, lowering); `participant` is the `name` of
// a participant file; sd_s is the trial-to-trial SD of one swing and n the number of swings
// averaged (both optional, together). Lines starting with '#' are comments (a source line).
// A UTF-8 byte-order mark and CRLF line ends are accepted.
#include <string>
#include <vector>

#include "model/measured_swing_time.h"

namespace swingsim {

/// Reads the file. Throws InputError with `file:line: column: expected ..., got ...` for a
/// missing column, a non-number, a lowering outside [0, 0.5] m, a swing time outside
/// (0.05, 3) s, an SD outside (0, 1) s, n not an integer in [1, 1000], a duplicate
/// (participant, lowering) or no rows.
std::vector<MeasuredSwingTime> readSweepTimesCsv(const std::string& path);
/// The same from text in memory (tests, fuzzers); `path` names it in messages.
std::vector<MeasuredSwingTime> parseSweepTimesCsv(const std::string& text, const std::string& path);

}  // namespace swingsim
