#pragma once
// The leg's state at toe-off, where a swing starts: the participant's `initial` values, or,
// under the measured thigh drive, the record's own thigh and knee at toe-off.
#include <string>
#include <vector>

#include "leg/thigh_motion.h"
#include "model/leg_parameters.h"

namespace swingsim {

/// The measured knee at toe-off: its angle (rad) and rate (rad/s).
struct MeasuredKneeStart {
  double kneeFlexion = 0, kneeFlexionRate = 0;
};

/// The record's knee at toe-off, differentiated as the thigh is: the value and first
/// derivative at t = 0 of the quintic smoothing spline through the knee samples (`time`, s,
/// from toe-off; `kneeFlexion`, rad), its smoothing chosen by generalized cross-validation
/// (ThighMotion; Woltring 1986). A forward difference of the first two samples would carry
/// their noise divided by one frame. Throws InputError naming `path` for fewer than
/// ThighMotion::kMinSamples samples.
MeasuredKneeStart calcMeasuredKneeStart(const std::string& path, const std::vector<double>& time,
                                        const std::vector<double>& kneeFlexion);

/// Whether a swing of `p` starts its knee from the record: the measured thigh drive, a record
/// with the knee, and `initial.knee_start` not `initial`.
bool startsKneeFromRecord(const Participant& p);

/// The state a swing of `p` starts from: `p.initial`; under the measured thigh drive (`thigh`
/// non-null) the hip's angle and rate from the thigh spline at 0, and, unless
/// `initial.kneeStart` is KneeStart::kInitial or the record has no knee, the knee's from
/// calcMeasuredKneeStart.
InitialConditions calcToeOffState(const Participant& p, const ThighMotion* thigh);

}  // namespace swingsim
