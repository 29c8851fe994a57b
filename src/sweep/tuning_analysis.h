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
/// A hard limit binds when its margin is within this fraction of its scale (tuningTargetScale):
/// 5 times the polish's inside margin (kHardLimitInside), 0.25 mm of toe clearance, 0.05 deg.
constexpr double kBindingFraction = 5 * kHardLimitInside;
/// A value target (min = max) is met within this fraction of its scale (0.1 ms of swing time).
constexpr double kValueFraction = 1e-2;
/// A knob is at its range end within this fraction of the range.
constexpr double kAtBoundFraction = 1e-4;

/// Signed miss of `value` against the target's window: 0 inside, value - lower below it
/// (negative), value - upper above it (positive). SI.
double calcTargetMiss(const TuningTarget& target, double value);

/// How the polish sees a hard limit: a one-sided penalty (kPenalty), or held at its lower or
/// upper edge as an equality (the active-set restart of knee_tuning.cpp).
enum class LimitHold { kPenalty, kAtLower, kAtUpper };

/// The residual vector of a point that ran, one entry per target in order: a soft target's
/// sqrt(weight) * miss / scale; a hard limit's penalty.weight * max(0, penalty.inside - margin
/// / scale), or, held at an edge (`holds`, one per target; empty: none held), penalty.weight *
/// (penalty.inside - margin from that edge / scale), negative where the point is further inside.
/// A single 0 when there are no targets.
Eigen::VectorXd calcTuningResiduals(const TuningPoint& point, const std::vector<TuningTarget>& targets,
                                    const HardLimitPenalty& penalty, const std::vector<LimitHold>& holds = {});
/// d residual / d quantity (SI) of each entry of calcTuningResiduals at `point`, from the side
/// of each window's edge (and of the penalty's kink) where the point is: 0 for a soft target
/// inside its window and for a hard limit with at least the inside margin (unless held).
Eigen::VectorXd calcTuningResidualSlopes(const TuningPoint& point, const std::vector<TuningTarget>& targets,
                                         const HardLimitPenalty& penalty, const std::vector<LimitHold>& holds = {});

/// One swing at `knobs`, scored against `targets`; a swing that cannot run (evaluate throws)
/// is a failed point (ran false, its failure text), never an error.
TuningPoint evaluateTuningPoint(const std::vector<double>& knobs, const std::vector<TuningTarget>& targets,
                                const TuningEvaluator& evaluate);

/// The better point of two lists: feasible first, then the lower cost, else the lower hard
/// violation; a point that did not run is never better than one that did.
TuningPoint findBestTuningPoint(const std::vector<TuningPoint>& a, const std::vector<TuningPoint>& b);

/// Fills result.targets, knobAtBound, sensitivity and the identifiability from result.best,
/// running 2 swings per knob (on `jobs` threads) for the sensitivity.
void analyseTuningResult(const std::vector<TuningTarget>& targets, const TuningEvaluator& evaluate, int jobs,
                         TuningResult& result);

}  // namespace swingsim
