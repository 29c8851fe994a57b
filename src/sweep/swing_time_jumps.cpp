#include "sweep/swing_time_jumps.h"

#include <algorithm>
#include <cmath>

#include "core/text_format.h"
#include "core/units.h"

namespace swingsim {

PieceSample makePieceSample(double lowering, const SwingResult& result) {
  PieceSample s;
  s.lowering = lowering;
  s.swingTime = result.swingTime;
  s.bounces = result.bounces;
  s.firstZoneEntry = calcFirstZoneEntry(result);
  s.bounceHeight = result.bounceHeight;
  return s;
}

std::string SwingTimeJump::describeCause() const {
  const PieceSample& more = below.bounces > above.bounces ? below : above;
  const PieceSample& fewer = below.bounces > above.bounces ? above : below;
  if (fewer.bounces == 0) {
    if (!more.bounceHeight) return "a rebound past the zone";
    // Two significant digits: at the narrowed edge the rebound is past the zone by a hair.
    return "a rebound " + fmt("%.2g", (*more.bounceHeight - zoneOfStability) * kRadToDeg) + " deg past the zone";
  }
  if (more.bounces == fewer.bounces + 1)
    return "one more bounce (" + std::to_string(more.bounces) + " against " + std::to_string(fewer.bounces) + ")";
  return std::to_string(more.bounces - fewer.bounces) + " more bounces (" + std::to_string(more.bounces) + " against " +
         std::to_string(fewer.bounces) + ")";
}

std::string SwingTimeJump::describe() const {
  return "the swing jumps from " + fmt("%.3f", below.swingTime) + " s to " + fmt("%.3f", above.swingTime) + " s at " +
         fmt("%.4f", calcLowering()) + " m (" + describeCause() + ")";
}

namespace {

// Narrows [lo, hi] (different bounce counts) by bisection to kJumpBracket; the side a midpoint
// joins is the one with its bounce count (a count unlike both joins the upper side, so the
// bracket keeps the lower side's piece edge).
void narrowJump(PieceSample& lo, PieceSample& hi, const PieceSampler& sample) {
  while (hi.lowering - lo.lowering > kJumpBracket) {
    const double mid = 0.5 * (lo.lowering + hi.lowering);
    const std::optional<PieceSample> m = sample(mid);
    if (!m) return;  // no swing end in between: the bracket so far is the answer
    (m->bounces == lo.bounces ? lo : hi) = *m;
  }
}

}  // namespace

std::vector<SwingTimeJump> findSwingTimeJumps(const std::vector<PieceSample>& grid, const PieceSampler& sample,
                                              double zoneOfStability) {
  std::vector<SwingTimeJump> jumps;
  for (std::size_t k = 0; k + 1 < grid.size(); ++k) {
    if (grid[k].bounces == grid[k + 1].bounces) continue;
    SwingTimeJump jump;
    jump.below = grid[k];
    jump.above = grid[k + 1];
    jump.zoneOfStability = zoneOfStability;
    narrowJump(jump.below, jump.above, sample);
    if (std::fabs(jump.above.swingTime - jump.below.swingTime) > kJumpMinSize) jumps.push_back(jump);
  }
  return jumps;
}

int calcPieceIndex(const std::vector<SwingTimeJump>& jumps, double lowering) {
  return static_cast<int>(std::count_if(jumps.begin(), jumps.end(),
                                        [&](const SwingTimeJump& j) { return j.calcLowering() < lowering; }));
}

const SwingTimeJump* findJumpBetween(const std::vector<SwingTimeJump>& jumps, double a, double b) {
  const double lo = std::min(a, b), hi = std::max(a, b);
  for (const SwingTimeJump& j : jumps)
    if (j.calcLowering() > lo && j.calcLowering() < hi) return &j;
  return nullptr;
}

}  // namespace swingsim
