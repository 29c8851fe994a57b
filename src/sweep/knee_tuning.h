#pragma once
// Tuning a knee to a person: several knobs (any numeric key of the knee model, the knee-axis
// lowering, an added shank mass) moved at once toward targets on one swing (swing time, a
// peak knee flexion window, a minimum toe clearance, a maximum stop-impact speed). A Latin
// hypercube start set over the knobs' ranges, run in parallel, then a bounded least-squares
// polish by Ceres (numerics/bounded_least_squares.h) from the best start points. Hard limits:
// in the polish, a quadratic penalty that asks each for a small margin inside it (so the polish
// can slide along a limit); the result is always the best evaluated point that meets every
// hard limit, a point that breaks one is never a result while one that meets them exists.
// docs/tuning.md, "How hard limits are enforced".
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "swing/swing_simulation.h"

namespace swingsim {

/// One knob: a name (the study's key), its range in its own units, and whether it is
/// searched on a log scale (a resistance known only to a factor; needs lower > 0).
struct TuningKnob {
  std::string key;
  double lower = 0, upper = 1;
  bool logScale = false;
  /// The finest step a person can set, in the knob's unit (tuning_resolution.h): the result is
  /// given on multiples of it. 0: continuous (no rounding).
  double resolution = 0;
};

/// What a target constrains, in SI inside (s, rad, m, rad/s).
enum class TuningQuantity { kSwingTime, kPeakKneeFlexion, kMinToeClearance, kMaxStopImpactSpeed };
/// The study key of a quantity: swing_time_s, peak_knee_flexion_deg, min_toe_clearance_m, max_stop_impact_deg_s.
const char* tuningQuantityKey(TuningQuantity q);

/// A target: the quantity must lie in [lower, upper] (equal ends: a value). Hard: the result
/// must meet it (a point that does not is never the result while one that does was evaluated;
/// the polish sees it as HardLimitPenalty). Soft: its miss enters the least-squares cost as
/// sqrt(weight) * miss / scale.
struct TuningTarget {
  TuningQuantity quantity = TuningQuantity::kSwingTime;
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  bool hard = false;
  double weight = 1;  ///< soft targets only
  double scale = 1;   ///< the miss that costs as much as 1 (SI), tuningTargetScale
};
/// A quantity (SI) in the unit its study key names: deg for peak flexion and stop-impact speed
/// (deg/s), else as it is (s, m).
double tuningQuantityInKeyUnit(TuningQuantity q, double si);
/// The residual unit of a quantity: 0.01 s, 1 deg, 0.005 m, 10 deg/s (in SI). A soft target
/// missed by one unit adds its weight to the cost.
double tuningTargetScale(TuningQuantity q);

/// One evaluated setting: the knob values and what the swing gave (NaN where it failed).
struct TuningPoint {
  std::vector<double> knobs;
  bool ran = false;
  std::string failure;                                                ///< why it did not run (a RunError's text)
  double swingTime = std::numeric_limits<double>::quiet_NaN();        ///< s
  double peakKneeFlexion = std::numeric_limits<double>::quiet_NaN();  ///< rad
  double minToeClearance = std::numeric_limits<double>::quiet_NaN();  ///< m
  double maxStopImpactSpeed = 0;                                      ///< rad/s; 0 without an impact
  int bounces = 0;  ///< SwingResult::bounces: the continuous piece of the swing time
  /// A measured record ended inside the settle dwell (the knee in the zone, the thigh at its
  /// target): swingTime is the knee's entry into the zone, the dwell unconfirmed.
  bool dwellCutByRecord = false;
  double cost = std::numeric_limits<double>::infinity();           ///< soft cost (sum of squared residuals)
  double hardViolation = std::numeric_limits<double>::infinity();  ///< sum of hard misses / scale; 0: feasible
  bool feasible() const { return ran && hardViolation == 0; }
  double value(TuningQuantity q) const;
};

/// One swing at knob values (in the knobs' order). Must be callable from several threads at
/// once; throws RunError where the swing cannot run (the point is then failed).
using TuningEvaluator = std::function<SwingResult(const std::vector<double>& knobs)>;

/// The polish's penalty for a hard limit: the residual weight x max(0, inside - margin /
/// scale), so the polish aims at a margin of `inside` scale units and a point that falls short
/// of it costs weight^2 per squared scale unit. With soft targets pulling across the limit, the
/// polish ends about |soft gradient| / (2 weight^2) scale units short of `inside` (1e-6 to 1e-4
/// for soft targets missed by 1 to 100 scale units): still inside the limit.
struct HardLimitPenalty {
  double weight = 1e3;   ///< residual per scale unit short of the inside margin
  double inside = 1e-2;  ///< the margin asked for, in scale units (50 um of toe clearance, 0.01 deg)
};
/// The default inside margin (scale units): a result held back by a hard limit sits this close to it.
constexpr double kHardLimitInside = HardLimitPenalty{}.inside;

struct TuningSettings {
  int startPoints = 24;    ///< Latin hypercube points
  std::uint64_t seed = 1;  ///< of the start set
  int jobs = 0;            ///< threads for the start set (0: all cores)
  int maxIterations = 40;  ///< of each Ceres polish
  /// Polishes from the best start points (ranked: those meeting every hard limit first), the
  /// next one only while the soft targets are still missed.
  int polishStarts = 3;
  HardLimitPenalty penalty;
  double maxSeconds = 120;  ///< wall-clock budget of the polish
  /// s: the tolerance bands' swing-time window (checkTuningResolution); the study's
  /// `tolerance_window_s`
  double toleranceWindow = 0.010;
};

/// What a target did at the result.
struct TargetOutcome {
  TuningTarget target;
  double value = 0;   ///< the quantity at the result (SI)
  double margin = 0;  ///< distance inside the window (>= 0: met), negative: missed by that much
  bool met = false;
  bool binding = false;  ///< a hard limit at its edge (margin within kBindingFraction of its scale)
};

// The result at each knob's resolution (sweep/tuning_resolution.h).
/// How far one knob can move alone from the result, in whole steps of its resolution.
struct KnobBand {
  double low = 0, high = 0;       ///< knob units: the last values that still hold
  std::string lowStop, highStop;  ///< what stopped the walk each way ("range end", "peak_knee_flexion_deg", ...)
};

/// The result at resolution and its check.
struct ResolutionCheck {
  bool ran = false;                  ///< some knob has a resolution and the check ran (else nothing below is set)
  bool holds = false;                ///< every corner of the chosen cell meets every hard limit on one piece
  TuningPoint continuous;            ///< the polish's optimum, before rounding
  TuningPoint result;                ///< the best corner of the chosen cell (or, if none holds, of the first)
  std::vector<TuningPoint> corners;  ///< of the chosen cell
  int cellsTried = 0;
  /// One sentence: holds ("all 16 rounding neighbours meet every hard limit"), moved inside, or
  /// cannot (which limit breaks at which neighbour, by how much).
  std::string verdict;
  double window = 0;            ///< s, the swing-time window of the bands
  std::vector<KnobBand> bands;  ///< one per knob (empty if it does not hold)
};

struct TuningResult {
  std::vector<TuningKnob> knobs;
  std::vector<TuningPoint> startSet;  ///< in start-set order
  std::vector<TuningPoint> polished;  ///< every evaluation of the polish, in order
  TuningPoint best;                   ///< the result (the best feasible point; the least infeasible if none)
  bool feasible = false;              ///< some evaluated point met every hard limit
  bool interrupted = false;           ///< the stop flag ended the run
  bool converged = false;             ///< Ceres converged
  std::string stopReason;
  int iterations = 0;
  int polishStart = 0;  ///< rank of the start point whose polish gave the result (0: the best)
  /// Where that polish ended (Ceres' solution). When it breaks a hard limit (the penalty lets a
  /// strongly pulled solution past it), `best` is the best evaluated point that meets them instead.
  TuningPoint polishEnd;
  /// The result moved onto the knobs' resolutions and checked on its rounding neighbours;
  /// when it ran, `best` is its result (the continuous optimum is resolution.continuous).
  ResolutionCheck resolution;
  std::vector<TargetOutcome> targets;
  std::vector<bool> knobAtBound;
  /// d quantity / d knob at the result (targets x knobs, SI per knob unit), central
  /// differences of 1e-3 of each range (one-sided at a range end); NaN where a swing failed.
  Eigen::MatrixXd sensitivity;
  /// Whether the targets that act at the result fix every knob: the Jacobian of the acting
  /// residuals over the knobs (scaled to their ranges) has full rank (smallest singular value
  /// above kIdentifiableRatio of the largest); else `ridge` is the direction (one entry per
  /// knob, per unit range) the acting targets do not see.
  bool identifiable = true;
  std::string identifiability;  ///< one sentence: why (not)
  std::vector<double> ridge;
  int evaluations = 0;
};

/// Runs the tuning. `progress(done, total)` from the calling thread (the start set's swings);
/// the stop flag (Ctrl-C) ends it early with interrupted set and the best point so far.
/// Throws InputError where no start point ran at all (with the first failure).
TuningResult runKneeTuning(const std::vector<TuningKnob>& knobs, const std::vector<TuningTarget>& targets,
                           const TuningEvaluator& evaluate, const TuningSettings& settings,
                           const std::function<void(int, int)>& progress = {}, const volatile bool* stopFlag = nullptr);

/// The quantities of one swing and their cost against `targets` (point.knobs set by the caller).
void scoreTuningPoint(TuningPoint& point, const SwingResult& swing, const std::vector<TuningTarget>& targets);

}  // namespace swingsim
