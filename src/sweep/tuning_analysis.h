#pragma once
// What a knee tuning's result means (sweep/knee_tuning.h): each target's margin, the limits
// that bind, the sensitivity of each target to each knob, and whether the targets fix the knobs.
#include <vector>

#include <Eigen/Dense>

#include "sweep/knee_tuning.h"

namespace swingsim {

/// The smallest singular value, relative to the largest, of the acting targets' Jacobian
/// over the knobs (each scaled to its range) below which the knobs are not identifiable: a
/// direction that moves the targets 1000 times less than the best-seen one is a ridge.
constexpr double kIdentifiableRatio = 1e-3;
/// The polish's wall inside each hard limit: within kWallWidth scale units of its edge, a
/// limit adds the residual kWallWeight x (kWallWidth - margin / scale), so the polish sees
/// the limit coming and slides along it (points past the edge are rejected). A result held
/// back by a limit sits inside this band: that limit binds.
constexpr double kWallWidth = 0.5;
constexpr double kWallWeight = 10;
/// A hard limit binds when its margin is within this fraction of its scale (tuningTargetScale).
constexpr double kBindingFraction = kWallWidth;
/// A value target (min = max) is met within this fraction of its scale (0.1 ms of swing time).
constexpr double kValueFraction = 1e-2;
/// A knob is at its range end within this fraction of the range.
constexpr double kAtBoundFraction = 1e-4;

/// Signed miss of `value` against the target's window: 0 inside, value - lower below it
/// (negative), value - upper above it (positive). SI.
double calcTargetMiss(const TuningTarget& target, double value);

/// The residual vector of a point that ran: the soft targets' sqrt(weight) * miss / scale and
/// each hard limit's wall (`feasible`), or the hard limits' miss / scale (looking for a
/// feasible point). Never empty: a single 0 when there is nothing of that kind.
Eigen::VectorXd calcTuningResiduals(const TuningPoint& point, const std::vector<TuningTarget>& targets, bool feasible);

/// The better point of two lists: feasible first, then the lower cost, else the lower hard
/// violation; a point that did not run is never better than one that did.
TuningPoint findBestTuningPoint(const std::vector<TuningPoint>& a, const std::vector<TuningPoint>& b);

/// Fills result.targets, knobAtBound, sensitivity and the identifiability from result.best,
/// running 2 swings per knob (on `jobs` threads) for the sensitivity.
void analyseTuningResult(const std::vector<TuningTarget>& targets, const TuningEvaluator& evaluate, int jobs,
                         TuningResult& result);

}  // namespace swingsim
