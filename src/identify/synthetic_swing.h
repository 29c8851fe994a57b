#pragma once
// Synthetic measured swings, exactly as `swingsim generate` (kind: swing-kinematics) makes
// them: the Simbody swing (simulateSwing) of a truth model that may carry hidden
// effects, sampled from toe-off to the swing end plus the bounce window, with seeded white
// noise on the hip and knee angles. The recorded hip moment is the participant's profile
// WITHOUT the hidden hip_moment_scale (that is what "measured" means for that effect).
#include <cstdint>
#include <string>

#include "identify/swing_plant.h"

namespace swingsim {

/// A walking condition: the participant's hip moment profile stretched in time (tau) and
/// scaled in amplitude.
struct SwingCondition {
  std::string name;
  double timeScale = 1.0;       ///< multiplies the profile's time_scale
  double amplitudeScale = 1.0;  ///< multiplies both amplitudes (or the table's moments)
};

/// One record. `noise`: angle noise standard deviation, deg (the same on hip and knee).
/// Throws RunError if the truth swing fails.
SwingRecord makeSyntheticSwing(const SwingBase& base, const SwingModelParams& truth, const SwingCondition& condition,
                               double noise, std::uint64_t seed, double sampleInterval = 0.002);

}  // namespace swingsim
