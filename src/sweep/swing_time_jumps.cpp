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
  for (const SwingEvent& e : result.events)
    if (e.name == "thigh_at_target") {
      s.thighAtTarget = e.time;
      break;
    }
  return s;
}

std::string SwingTimeJump::describeCause() const {
  if (below.bounces == above.bounces) {
    if (below.thighAtTarget && above.thighAtTarget &&
        std::fabs(*below.thighAtTarget - *above.thighAtTarget) > kJumpMinSize)
      return "the thigh's flexion grazing its target: it reaches it " +
             fmt("%.3f", std::fabs(*below.thighAtTarget - *above.thighAtTarget)) + " s later on one side";
    return "the swing end moves by " + fmt("%.0f", std::fabs(above.swingTime - below.swingTime) * 1000) + " ms";
  }
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

// Whether midpoint `m` joins side `lo` of [lo, hi]: by its bounce count where the sides' differ
// (a count unlike both joins the upper side, so the bracket keeps the lower side's piece edge),
// else by the nearer swing time.
bool joinsLower(const PieceSample& m, const PieceSample& lo, const PieceSample& hi) {
  if (lo.bounces != hi.bounces) return m.bounces == lo.bounces;
  return std::fabs(m.swingTime - lo.swingTime) <= std::fabs(m.swingTime - hi.swingTime);
}

// Narrows [lo, hi] by bisection to kJumpBracket.
void narrowJump(PieceSample& lo, PieceSample& hi, const PieceSampler& sample) {
  while (hi.lowering - lo.lowering > kJumpBracket) {
    const double mid = 0.5 * (lo.lowering + hi.lowering);
    const std::optional<PieceSample> m = sample(mid);
    if (!m) return;  // no swing end in between: the bracket so far is the answer
    (joinsLower(*m, lo, hi) ? lo : hi) = *m;
  }
}

// s: the step between neighbours of `times` (ended swings: finite neighbours only) above
// which a pair with one bounce count is bisected.
double calcJumpScreen(const std::vector<double>& times) {
  std::vector<double> steps;
  for (std::size_t k = 0; k + 1 < times.size(); ++k)
    if (std::isfinite(times[k]) && std::isfinite(times[k + 1])) steps.push_back(std::fabs(times[k + 1] - times[k]));
  if (steps.empty()) return kJumpScreenFloor;
  std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2), steps.end());
  return std::max(kJumpScreenFloor, kJumpScreenFactor * steps[steps.size() / 2]);
}

}  // namespace

std::vector<SwingTimeJump> findSwingTimeJumps(const std::vector<PieceSample>& grid, const PieceSampler& sample,
                                              double zoneOfStability) {
  std::vector<SwingTimeJump> jumps;
  std::vector<double> times;
  for (const PieceSample& p : grid) times.push_back(p.swingTime);
  const double screen = calcJumpScreen(times);
  for (std::size_t k = 0; k + 1 < grid.size(); ++k) {
    if (grid[k].bounces == grid[k + 1].bounces && std::fabs(grid[k + 1].swingTime - grid[k].swingTime) <= screen)
      continue;
    SwingTimeJump jump;
    jump.below = grid[k];
    jump.above = grid[k + 1];
    jump.zoneOfStability = zoneOfStability;
    narrowJump(jump.below, jump.above, sample);
    if (std::fabs(jump.above.swingTime - jump.below.swingTime) > kJumpMinSize) jumps.push_back(jump);
  }
  return jumps;
}

std::vector<int> calcScreenedPieces(const std::vector<double>& swingTimes) {
  const double screen = calcJumpScreen(swingTimes);
  std::vector<int> pieces(swingTimes.size(), 0);
  for (std::size_t k = 1; k < swingTimes.size(); ++k) {
    const bool jump = std::isfinite(swingTimes[k]) && std::isfinite(swingTimes[k - 1]) &&
                      std::fabs(swingTimes[k] - swingTimes[k - 1]) > screen;
    pieces[k] = pieces[k - 1] + (jump ? 1 : 0);
  }
  return pieces;
}

int calcPieceIndex(const std::vector<SwingTimeJump>& jumps, double lowering) {
  return static_cast<int>(
      std::count_if(jumps.begin(), jumps.end(), [&](const SwingTimeJump& j) { return j.calcLowering() < lowering; }));
}

const SwingTimeJump* findJumpBetween(const std::vector<SwingTimeJump>& jumps, double a, double b) {
  const double lo = std::min(a, b), hi = std::max(a, b);
  for (const SwingTimeJump& j : jumps)
    if (j.calcLowering() > lo && j.calcLowering() < hi) return &j;
  return nullptr;
}

}  // namespace swingsim
