#include "sweep/sweep_symmetry.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace swingsim {

SymmetryLowering calcSymmetryLowering(const std::vector<double>& lowerings, const std::vector<double>& swingTimes,
                                      double soundTime, const std::vector<int>& pieces) {
  SymmetryLowering out;
  if (!(soundTime > 0) || !std::isfinite(soundTime)) return out;
  out.given = true;
  out.soundTime = soundTime;
  const std::size_t n = std::min(lowerings.size(), swingTimes.size());
  auto reachedAt = [&](double lowering) {
    out.found = out.reached = true;
    out.lowering = lowering;
    out.prostheticTime = soundTime;
    return out;
  };
  int nearest = -1;
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(swingTimes[k])) continue;
    const double gap = swingTimes[k] - soundTime;
    if (gap == 0) return reachedAt(lowerings[k]);
    // The first sign change between neighbours on one piece: linear interpolation of the
    // crossing. Across a jump it is no crossing: remember the first such jump.
    if (k + 1 < n && std::isfinite(swingTimes[k + 1]) && (swingTimes[k + 1] - soundTime) * gap < 0) {
      const bool samePiece = pieces.size() < n || pieces[k] == pieces[k + 1];
      if (samePiece) {
        const double next = swingTimes[k + 1] - soundTime;
        return reachedAt(lowerings[k] + (lowerings[k + 1] - lowerings[k]) * gap / (gap - next));
      }
      if (!out.acrossJump) {
        out.acrossJump = true;
        out.jumpFrom = lowerings[k];
        out.jumpTo = lowerings[k + 1];
      }
    }
    // Closest so far; a tie keeps the smaller lowering.
    if (nearest < 0 || std::fabs(gap) < std::fabs(swingTimes[static_cast<std::size_t>(nearest)] - soundTime))
      nearest = static_cast<int>(k);
  }
  if (nearest < 0) return out;
  out.found = true;
  out.lowering = lowerings[static_cast<std::size_t>(nearest)];
  out.prostheticTime = swingTimes[static_cast<std::size_t>(nearest)];
  out.gap = out.prostheticTime - soundTime;
  return out;
}

}  // namespace swingsim
