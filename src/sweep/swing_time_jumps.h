#pragma once
// Where the swing time jumps along the knee-axis lowering. Burkett's swing end waits for the
// knee to stay inside the zone of stability; a knee that rebounds just past the zone's edge
// adds a whole excursion to the swing, one that stops just short of it adds nothing. So the
// swing time is a piecewise continuous function of the lowering with jumps where the rebound
// grazes the zone (docs/swing-time-jumps.md). This unit finds each jump between neighbouring
// lowerings of a grid, narrows it by bisection, names its cause, and gives every lowering the
// continuous piece it lies on, so that no answer (a symmetry crossing, an interpolated time)
// is read across a jump.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "swing/swing_simulation.h"

namespace swingsim {

/// m: a jump is narrowed until its two sides are this close (0.1 mm, a tenth of the finest
/// setting a prosthetist can make at the knee axis).
constexpr double kJumpBracket = 1e-4;

/// s: a change of the swing time across one bracket larger than this is a jump. Where the
/// swing time is continuous a 10 mm step moves it by at most ~15 ms on the shipped participants
/// and the imported OpenSim legs (1.5 s/m), so across 0.1 mm by at most ~0.15 ms; a jump is a
/// whole rebound excursion or a late thigh (tens of ms).
constexpr double kJumpMinSize = 0.002;
/// A pair of neighbouring grid lowerings with the same bounce count is bisected too when its
/// swing times differ by more than this many times the grid's median neighbour difference
/// (and at least kJumpScreenFloor): a jump that keeps the bounce count (the thigh's flexion
/// grazing its target) shows only in the size of the step.
constexpr double kJumpScreenFactor = 3;
constexpr double kJumpScreenFloor = 0.005;  ///< s

/// What one swing at one lowering says about which continuous piece it lies on.
struct PieceSample {
  double lowering = 0;   ///< m
  double swingTime = 0;  ///< s
  int bounces = 0;       ///< SwingResult::bounces: the piece's signature
  /// s, the knee's first entry into the zone after its peak (the continuous companion of the
  /// swing time); absent if it never entered
  std::optional<double> firstZoneEntry;
  /// rad, highest knee flexion after the knee first left the zone (SwingResult::bounceHeight)
  std::optional<double> bounceHeight;
  /// s, when the thigh first reached its target flexion; absent if it never did
  std::optional<double> thighAtTarget;
};

/// The sample of an ended swing at `lowering`.
PieceSample makePieceSample(double lowering, const SwingResult& result);

/// One jump of the swing time between two lowerings at most kJumpBracket apart.
struct SwingTimeJump {
  PieceSample below, above;    ///< the two sides (below: the smaller lowering)
  double zoneOfStability = 0;  ///< rad, the zone's edge the rebound is measured against
  /// m, the jump's lowering (the middle of its bracket)
  double calcLowering() const { return 0.5 * (below.lowering + above.lowering); }
  /// Its cause: "a rebound 0.1 deg past the zone" (one side has no bounce), "one more bounce
  /// (2 against 1)", "the thigh's flexion grazing its target: it reaches it 0.114 s later on one
  /// side", or "the swing end moves by 61 ms" where neither explains it.
  std::string describeCause() const;
  /// "the swing jumps from 0.518 s to 0.386 s at 0.1655 m (a rebound 0.1 deg past the zone)".
  std::string describe() const;
};

/// Simulates one swing at a lowering (m) and returns its sample, or nullopt if no swing ended.
using PieceSampler = std::function<std::optional<PieceSample>(double lowering)>;

/// The jumps between neighbouring samples of `grid` (sorted by lowering; ended swings only):
/// each neighbouring pair whose bounce counts differ, or whose swing times differ by more than
/// the screen (kJumpScreenFactor x the median neighbour difference, at least kJumpScreenFloor),
/// is bisected with `sample` down to kJumpBracket, a midpoint joining the side with its bounce
/// count (where the two sides' differ) or else the side whose swing time is nearer; a bracket
/// whose swing time changes by more than kJumpMinSize is a jump. A jump out and back between
/// two grid points is not seen (docs/swing-time-jumps.md). A bisection point with no swing end
/// stops that pair's bisection at the bracket reached so far, and the jump is reported there.
std::vector<SwingTimeJump> findSwingTimeJumps(const std::vector<PieceSample>& grid, const PieceSampler& sample,
                                              double zoneOfStability);

/// Piece indices (one per grid point) of a swing-time curve known only on its grid, as the
/// uncertainty analysis keeps its samples (times, no bounce counts, nothing to bisect): a
/// neighbour step beyond the jump screen (kJumpScreenFactor x the median neighbour step, at
/// least kJumpScreenFloor) starts a new piece. A steep continuous stretch beyond the screen is
/// split too: an answer there is withheld, never read across a jump.
std::vector<int> calcScreenedPieces(const std::vector<double>& swingTimes);

/// The piece index (0, 1, ...) of a lowering: how many jumps lie below it.
int calcPieceIndex(const std::vector<SwingTimeJump>& jumps, double lowering);

/// The jump between lowerings `a` and `b` (either order), or nullptr if they lie on one piece.
const SwingTimeJump* findJumpBetween(const std::vector<SwingTimeJump>& jumps, double a, double b);

}  // namespace swingsim
