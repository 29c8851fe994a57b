#pragma once
// Burkett 2004's terminal-impact findings checked on a sweep: does the knee bounce, where,
// and if not, what takes the rebound's energy. For each participant: the stop impact with
// its energy bookkeeping at the standard location and at the largest lowering, and the
// sweep repeated without the knee friction near extension (Burkett Table 2's Tc), the
// suspect named by that bookkeeping.
#include <string>
#include <vector>

#include "sweep/sweep.h"

namespace swingsim {

// TrackedImpactSwing and TerminalImpactCheck are in sweep/sweep.h (SweepResults holds them).

/// Runs the check on `jobs` threads (0 = all cores): two tracked swings per participant
/// and one friction-free sweep of the lowering grid (no added mass, no off-grid lowerings).
/// Fills results.terminalImpact, one entry per participant.
void checkTerminalImpact(const SweepStudy& study, SweepResults& results, int jobs);

}  // namespace swingsim
