#pragma once
// The lowering with the best symmetry (Burkett 2004 Table 4's `*`): where the modelled
// prosthetic swing time comes closest to the sound limb's. A plain function of a lowering
// grid and its swing times, shared by the sweep and by each uncertainty sample.
#include <vector>

namespace swingsim {

/// The symmetry lowering of one lowering sweep against a sound-limb swing time.
/// `given` false (no sound-limb time): every other field is meaningless.
struct SymmetryLowering {
  bool given = false;    ///< a sound-limb swing time was given
  double soundTime = 0;  ///< s, the sound limb's swing time
  bool found = false;    ///< at least one lowering ended a swing
  /// The prosthetic swing time equals the sound limb's somewhere on the grid: `lowering` is
  /// that crossing, linearly interpolated between the two grid lowerings around it (the
  /// first crossing from the standard location if there are several). False: the sound limb
  /// is faster (or slower) than every lowering, and `lowering` is the grid point closest.
  bool reached = false;
  double lowering = 0;        ///< m
  double prostheticTime = 0;  ///< s, the modelled swing time at `lowering` (= soundTime when reached)
  double gap = 0;             ///< s, prostheticTime - soundTime (0 when reached)
  /// The swing time jumps over the sound limb's between two neighbours on different
  /// continuous pieces (swing_time_jumps.h): no lowering gives the sound limb's time there.
  /// `jumpFrom` and `jumpTo` (m) are those neighbours (the first such pair); set whether or
  /// not a crossing further on is reached.
  bool acrossJump = false;
  double jumpFrom = 0, jumpTo = 0;
  /// prostheticTime / soundTime, the symmetry index (1 = symmetric, > 1: prosthesis slower).
  double calcRatio() const { return prostheticTime / soundTime; }
};

/// The symmetry lowering of swing times `swingTimes` (s, NaN where no swing ended) at
/// `lowerings` (m, increasing, same size) against `soundTime` (s; <= 0 or NaN: not given).
/// A crossing is only looked for between neighbouring grid points that both ended a swing
/// and lie on the same continuous piece: `pieces` (same size, or empty: one piece) gives each
/// lowering's piece index (calcPieceIndex); a sign change between two pieces is a jump over
/// the sound limb's time, never interpolated.
SymmetryLowering calcSymmetryLowering(const std::vector<double>& lowerings, const std::vector<double>& swingTimes,
                                      double soundTime, const std::vector<int>& pieces = {});

}  // namespace swingsim
