#include "sweep/knee_tuning.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/input_error.h"
#include "core/units.h"
#include "numerics/bounded_least_squares.h"
#include "numerics/latin_hypercube.h"
#include "sweep/sweep.h"
#include "sweep/tuning_analysis.h"
#include "sweep/tuning_resolution.h"

namespace swingsim {

const char* tuningQuantityKey(TuningQuantity q) {
  switch (q) {
    case TuningQuantity::kSwingTime:
      return "swing_time_s";
    case TuningQuantity::kPeakKneeFlexion:
      return "peak_knee_flexion_deg";
    case TuningQuantity::kMinToeClearance:
      return "min_toe_clearance_m";
    case TuningQuantity::kMaxStopImpactSpeed:
      return "max_stop_impact_deg_s";
  }
  return "";
}

double tuningQuantityInKeyUnit(TuningQuantity q, double si) {
  return q == TuningQuantity::kPeakKneeFlexion || q == TuningQuantity::kMaxStopImpactSpeed ? si * kRadToDeg : si;
}

double tuningTargetScale(TuningQuantity q) {
  switch (q) {
    case TuningQuantity::kSwingTime:
      return 0.01;
    case TuningQuantity::kPeakKneeFlexion:
      return 1 * kDegToRad;
    case TuningQuantity::kMinToeClearance:
      return 0.005;
    case TuningQuantity::kMaxStopImpactSpeed:
      return 10 * kDegToRad;
  }
  return 1;
}

double TuningPoint::value(TuningQuantity q) const {
  switch (q) {
    case TuningQuantity::kSwingTime:
      return swingTime;
    case TuningQuantity::kPeakKneeFlexion:
      return peakKneeFlexion;
    case TuningQuantity::kMinToeClearance:
      return minToeClearance;
    case TuningQuantity::kMaxStopImpactSpeed:
      return maxStopImpactSpeed;
  }
  return 0;
}

void scoreTuningPoint(TuningPoint& point, const SwingResult& swing, const std::vector<TuningTarget>& targets) {
  point.swingTime = swing.swingTime;
  // A measured record that ends while the knee rests in the zone with the thigh at its target
  // (only the settle dwell unfinished): the swing end is that entry, as the dwell would have
  // confirmed unless the knee left the zone after the record.
  point.dwellCutByRecord = false;
  if (!std::isfinite(point.swingTime) && swing.trialEnd && swing.trialEnd->unmet == "settle_dwell" &&
      swing.trialEnd->dwellDone) {
    point.swingTime = swing.trialEnd->time - *swing.trialEnd->dwellDone;
    point.dwellCutByRecord = true;
  }
  point.bounces = swing.bounces;
  if (swing.peakKneeFlexion) point.peakKneeFlexion = swing.peakKneeFlexion->flexion;
  if (swing.minToeClearance) point.minToeClearance = *swing.minToeClearance;
  point.maxStopImpactSpeed = 0;
  for (const StopImpact& im : swing.impacts)
    point.maxStopImpactSpeed = std::max(point.maxStopImpactSpeed, im.impactRate);
  point.ran = true;
  point.cost = 0;
  point.hardViolation = 0;
  for (const TuningTarget& t : targets) {
    const double value = point.value(t.quantity);
    if (!std::isfinite(value)) {
      point.ran = false;
      point.failure = std::string("the swing has no ") + tuningQuantityKey(t.quantity) +
                      (swing.trialEnd ? " (" + swing.trialEnd->describe() + ")" : "");
      point.cost = point.hardViolation = std::numeric_limits<double>::infinity();
      return;
    }
    const double miss = calcTargetMiss(t, value) / t.scale;
    if (t.hard)
      point.hardViolation += std::abs(miss);
    else
      point.cost += t.weight * miss * miss;
  }
}

TuningPoint evaluateTuningPoint(const std::vector<double>& knobs, const std::vector<TuningTarget>& targets,
                                const TuningEvaluator& evaluate) {
  TuningPoint point;
  point.knobs = knobs;
  try {
    scoreTuningPoint(point, evaluate(knobs), targets);
  } catch (const std::exception& e) {
    point.ran = false;
    point.failure = e.what();
  }
  return point;
}

namespace {

// Knob values of a unit-cube point: linear, or geometric for a log-scaled knob.
std::vector<double> knobValuesAt(const std::vector<TuningKnob>& knobs, const std::vector<double>& unit) {
  std::vector<double> values(knobs.size());
  for (std::size_t k = 0; k < knobs.size(); ++k) {
    const TuningKnob& knob = knobs[k];
    values[k] = knob.logScale ? knob.lower * std::pow(knob.upper / knob.lower, unit[k])
                              : knob.lower + unit[k] * (knob.upper - knob.lower);
  }
  return values;
}

// The start set, run on settings.jobs threads; points the stop flag kept from running are dropped.
std::vector<TuningPoint> runStartSet(const std::vector<TuningKnob>& knobs, const std::vector<TuningTarget>& targets,
                                     const TuningEvaluator& evaluate, const TuningSettings& settings,
                                     const std::function<void(int, int)>& progress, const volatile bool* stopFlag) {
  const auto unit = makeLatinHypercube(settings.startPoints, static_cast<int>(knobs.size()), settings.seed);
  std::vector<TuningPoint> points(unit.size());
  std::vector<char> done(unit.size(), 0);
  runParallelJobs(
      static_cast<int>(unit.size()), settings.jobs,
      [&](int i) {
        const auto index = static_cast<std::size_t>(i);
        points[index] = evaluateTuningPoint(knobValuesAt(knobs, unit[index]), targets, evaluate);
        done[index] = 1;
      },
      progress, stopFlag);
  std::vector<TuningPoint> ran;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (done[i]) ran.push_back(std::move(points[i]));
  return ran;
}

// Step of the polish's difference Jacobian: 1e-4 of a linear knob's range, 1e-4 of a
// log-scaled knob's value (a swing time is smooth to ~1e-6 s at the default accuracy).
constexpr double kDifferenceStep = 1e-4;

// The residuals at x (calcTuningResiduals: soft targets and each hard limit's penalty) and, if
// asked, their Jacobian: the residuals' slopes at x times each quantity's one-sided difference
// (steps inside the knobs' ranges). Differencing the swing's quantities, not the residuals,
// keeps a penalty's kink out of the Jacobian: a point just past the inside margin sees the
// limit's full slope even when its difference point falls back inside. A point that breaks a
// hard limit is evaluated like any other (only a swing that cannot run throws, and Ceres then
// rejects the step), so a polish can cross a limit and come back along it.
class PolishResiduals {
 public:
  /// `free`: the knobs the polish moves (indices into `knobs`); the others stay at `fixed`'s values.
  PolishResiduals(const std::vector<TuningKnob>& knobs, const std::vector<TuningTarget>& targets,
                  const TuningEvaluator& evaluate, const HardLimitPenalty& penalty, std::vector<LimitHold> holds,
                  int jobs, const volatile bool* stopFlag, std::vector<TuningPoint>& evaluated,
                  std::vector<std::size_t> free, std::vector<double> fixed)
      : knobs_(knobs),
        targets_(targets),
        evaluate_(evaluate),
        penalty_(penalty),
        holds_(std::move(holds)),
        jobs_(jobs),
        stop_(stopFlag),
        evaluated_(evaluated),
        free_(std::move(free)),
        fixed_(std::move(fixed)) {}

  Eigen::VectorXd operator()(const Eigen::VectorXd& x, Eigen::MatrixXd* jacobian) const {
    const std::vector<double> all = knobsAt(x);
    const TuningPoint p = runOrReuse(all);
    const Eigen::VectorXd r = calcTuningResiduals(p, targets_, penalty_, holds_);
    if (jacobian == nullptr) return r;
    const Eigen::VectorXd slopes = calcTuningResidualSlopes(p, targets_, penalty_, holds_);
    std::vector<double> steps(free_.size());
    const std::vector<TuningPoint> moved = runDifferencePoints(all, steps);
    jacobian->setZero(r.size(), x.size());
    for (std::size_t i = 0; i < free_.size(); ++i)
      for (std::size_t t = 0; t < targets_.size(); ++t)
        (*jacobian)(static_cast<Eigen::Index>(t), static_cast<Eigen::Index>(i)) =
            slopes[static_cast<Eigen::Index>(t)] *
            (moved[i].value(targets_[t].quantity) - p.value(targets_[t].quantity)) / steps[i];
    return r;
  }

  /// Every knob's value at the free knobs' values x.
  std::vector<double> knobsAt(const Eigen::VectorXd& x) const {
    std::vector<double> all = fixed_;
    for (std::size_t i = 0; i < free_.size(); ++i) all[free_[i]] = x[static_cast<Eigen::Index>(i)];
    return all;
  }

 private:
  // The point at x: Ceres evaluates an accepted step's Jacobian right after the step itself,
  // so the last evaluated point is reused when it is x (one swing less per iteration).
  TuningPoint runOrReuse(const std::vector<double>& x) const {
    if (!evaluated_.empty() && evaluated_.back().ran && evaluated_.back().knobs == x) return evaluated_.back();
    if (stop_ != nullptr && *stop_) throw RunError("stopped");
    evaluated_.push_back(evaluateTuningPoint(x, targets_, evaluate_));
    if (!evaluated_.back().ran) throw RunError(evaluated_.back().failure);
    return evaluated_.back();
  }

  // The difference points of the free knobs from `all`, run on jobs_ threads (kept in knob
  // order, so any thread count gives the same polish); each step (inside the knob's range) in `steps`.
  std::vector<TuningPoint> runDifferencePoints(const std::vector<double>& all, std::vector<double>& steps) const {
    std::vector<TuningPoint> moved(free_.size());
    for (std::size_t i = 0; i < free_.size(); ++i) {
      const TuningKnob& knob = knobs_[free_[i]];
      const double value = all[free_[i]];
      steps[i] = kDifferenceStep * (knob.logScale ? value : knob.upper - knob.lower);
      if (value + steps[i] > knob.upper) steps[i] = -steps[i];
    }
    runParallelJobs(
        static_cast<int>(free_.size()), jobs_,
        [&](int j) {
          const auto i = static_cast<std::size_t>(j);
          std::vector<double> x = all;
          x[free_[i]] += steps[i];
          moved[i] = evaluateTuningPoint(x, targets_, evaluate_);
        },
        {}, stop_);
    if (stop_ != nullptr && *stop_) throw RunError("stopped");
    for (const TuningPoint& q : moved) evaluated_.push_back(q);
    for (const TuningPoint& q : moved)
      if (!q.ran) throw RunError(q.failure);
    return moved;
  }

  const std::vector<TuningKnob>& knobs_;
  const std::vector<TuningTarget>& targets_;
  const TuningEvaluator& evaluate_;
  HardLimitPenalty penalty_;
  std::vector<LimitHold> holds_;
  int jobs_;
  const volatile bool* stop_;
  std::vector<TuningPoint>& evaluated_;
  std::vector<std::size_t> free_;
  std::vector<double> fixed_;
};

// The evaluated point at `knobs` (the last one: Ceres evaluates its solution last), or a point
// that did not run.
TuningPoint findEvaluated(const std::vector<TuningPoint>& evaluated, const std::vector<double>& knobs) {
  for (auto p = evaluated.rbegin(); p != evaluated.rend(); ++p)
    if (p->knobs == knobs) return *p;
  return TuningPoint{};
}

// What a polish holds: knobs at a range end (held at their values) and hard limits held at an
// edge as equalities. Empty: a free polish, every hard limit a one-sided penalty.
struct ActiveSet {
  std::vector<bool> knobs;
  std::vector<LimitHold> limits;
  std::size_t knobCount() const { return static_cast<std::size_t>(std::count(knobs.begin(), knobs.end(), true)); }
  std::size_t limitCount() const {
    return static_cast<std::size_t>(limits.size() - std::count(limits.begin(), limits.end(), LimitHold::kPenalty));
  }
};

// The Ceres polish from `start` over the knobs `active` does not hold (held ones stay at
// start's values), toward the soft targets with each hard limit a penalty (HardLimitPenalty)
// or, where `active` holds it, an equality at its edge; from a start that breaks a hard limit
// the penalty leads it back first. Every evaluation is kept in `result.polished`; Ceres'
// solution is `result.polishEnd`.
void polish(const std::vector<TuningKnob>& knobs, const std::vector<TuningTarget>& targets,
            const TuningEvaluator& evaluate, const TuningSettings& settings, const TuningPoint& start,
            const ActiveSet& active, const volatile bool* stopFlag, TuningResult& result) {
  std::vector<BoundedParameter> parameters;
  std::vector<std::size_t> free;
  for (std::size_t k = 0; k < knobs.size(); ++k) {
    if (k < active.knobs.size() && active.knobs[k]) continue;
    free.push_back(k);
    parameters.push_back({knobs[k].key, start.knobs[k], knobs[k].lower, knobs[k].upper, knobs[k].logScale,
                          knobs[k].logScale ? 1.0 : knobs[k].upper - knobs[k].lower});
  }
  if (free.empty()) return;
  const PolishResiduals residuals(knobs, targets, evaluate, settings.penalty, active.limits, settings.jobs, stopFlag,
                                  result.polished, free, start.knobs);
  BoundedFitSettings fit;
  fit.maxIterations = settings.maxIterations;
  fit.maxSeconds = settings.maxSeconds;
  fit.computeCovariance = false;
  // A value target is met within 1 % of its scale (kValueFraction): a cost of 1e-8 or less.
  fit.functionTolerance = 1e-12;
  fit.parameterTolerance = 1e-10;
  // The hard limits' penalties are steep and one-sided: Ceres' projected line search would
  // shrink each step crossing one to a crawl (measured: 40 iterations of ~1e-4 of a range).
  fit.boundsLineSearch = false;
  try {
    const BoundedFitResult r =
        solveBoundedLeastSquares(ResidualJacobianFunction(std::cref(residuals)), parameters, fit);
    result.converged = r.converged;
    result.stopReason = r.stopReason;
    result.iterations = r.iterations;
    result.polishEnd = findEvaluated(result.polished, residuals.knobsAt(r.x));
  } catch (const std::exception& e) {
    result.stopReason = e.what();
  }
}

// Better: feasible before infeasible; then lower cost (feasible) or lower violation.
bool isBetter(const TuningPoint& a, const TuningPoint& b) {
  if (a.ran != b.ran) return a.ran;
  if (a.feasible() != b.feasible()) return a.feasible();
  if (a.feasible()) return a.cost < b.cost;
  return a.hardViolation < b.hardViolation || (a.hardViolation == b.hardViolation && a.cost < b.cost);
}

// The soft cost below which the soft targets count as met: every value target within 1e-4 of its scale.
constexpr double kMetCost = 1e-8;

// A hard limit enters the active set where the polish's best point is within this many scale
// units of its edge, or past it.
constexpr double kActiveBand = 0.5;
// Restarts on the active set after each polish: the second one after a held limit was released.
constexpr int kActiveSetRestarts = 2;

// The active set at `point`: the knobs at a range end and the hard limits within kActiveBand
// of an edge (held at the nearer edge), except those in `released`.
ActiveSet findActiveSet(const std::vector<TuningKnob>& knobs, const std::vector<TuningTarget>& targets,
                        const TuningPoint& point, const std::vector<bool>& released) {
  ActiveSet a{std::vector<bool>(knobs.size(), false), std::vector<LimitHold>(targets.size(), LimitHold::kPenalty)};
  for (std::size_t k = 0; k < knobs.size(); ++k) {
    const double tol = kAtBoundFraction * (knobs[k].upper - knobs[k].lower);
    a.knobs[k] = point.knobs[k] <= knobs[k].lower + tol || point.knobs[k] >= knobs[k].upper - tol;
  }
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const TuningTarget& t = targets[i];
    const double value = point.value(t.quantity);
    if (!t.hard || released[i]) continue;
    if (value - t.lower < kActiveBand * t.scale && value - t.lower <= t.upper - value)
      a.limits[i] = LimitHold::kAtLower;
    else if (t.upper - value < kActiveBand * t.scale)
      a.limits[i] = LimitHold::kAtUpper;
  }
  return a;
}

// Releases the held limits whose multiplier has the wrong sign: where the polish on the active
// set ended further inside than the inside margin, the soft targets pull the point away from
// that edge, so the limit does not act. Returns whether any was released.
bool releaseLimitsPulledInside(const std::vector<TuningTarget>& targets, const HardLimitPenalty& penalty,
                               const TuningPoint& end, const ActiveSet& active, std::vector<bool>& released) {
  if (!end.ran) return false;
  const Eigen::VectorXd r = calcTuningResiduals(end, targets, penalty, active.limits);
  bool any = false;
  for (std::size_t i = 0; i < targets.size(); ++i)
    if (active.limits[i] != LimitHold::kPenalty && r[static_cast<Eigen::Index>(i)] < 0) released[i] = any = true;
  return any;
}

// Ceres keeps a bound by projecting its steps onto the box, and sees a one-sided penalty only
// once past its kink: a polish whose best point has a knob at a range end, or sits at a hard
// limit, can stall there while the soft targets could still gain along it. So polish again
// from that point on its active set: the knobs at a range end held there, the limits at their
// edge held as equalities (smooth residuals, along which Gauss-Newton slides); a held limit
// the soft targets pull away from is released and the polish repeated (an active-set method,
// each step still Ceres).
void repolishOnActiveSet(const std::vector<TuningKnob>& knobs, const std::vector<TuningTarget>& targets,
                         const TuningEvaluator& evaluate, const TuningSettings& settings, const TuningPoint& start,
                         const volatile bool* stopFlag, TuningResult& one) {
  std::vector<bool> released(targets.size(), false);
  for (int round = 0; round < kActiveSetRestarts; ++round) {
    const TuningPoint best = findBestTuningPoint(one.polished, {start});
    // Nothing to gain where the soft targets are met (kMetCost) at a point meeting every limit.
    if (!best.ran || (best.feasible() && best.cost <= kMetCost) || (stopFlag != nullptr && *stopFlag)) return;
    const ActiveSet active = findActiveSet(knobs, targets, best, released);
    if (active.knobCount() == knobs.size() || active.knobCount() + active.limitCount() == 0) return;
    TuningResult again;
    polish(knobs, targets, evaluate, settings, best, active, stopFlag, again);
    one.polished.insert(one.polished.end(), again.polished.begin(), again.polished.end());
    one.iterations += again.iterations;
    if (!again.stopReason.empty() || again.converged) {
      one.converged = again.converged;
      one.stopReason = again.stopReason;
      one.polishEnd = again.polishEnd;
    }
    if (!releaseLimitsPulledInside(targets, settings.penalty, again.polishEnd, active, released)) return;
  }
}

// The start points in order of merit, for the polish.
std::vector<TuningPoint> rankStarts(std::vector<TuningPoint> points) {
  std::stable_sort(points.begin(), points.end(), isBetter);
  return points;
}

// Polishes from the best start; while the best point so far still misses a soft target (its
// cost above kMetCost), from the next-best start too, up to settings.polishStarts: a local
// polish finds the optimum of its own basin, and another start may lie in a better one.
void polishFromBestStarts(const std::vector<TuningKnob>& knobs, const std::vector<TuningTarget>& targets,
                          const TuningEvaluator& evaluate, const TuningSettings& settings,
                          const volatile bool* stopFlag, TuningResult& result) {
  const std::vector<TuningPoint> starts = rankStarts(result.startSet);
  double bestCost = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < starts.size() && static_cast<int>(i) < settings.polishStarts; ++i) {
    if (!starts[i].ran || (stopFlag != nullptr && *stopFlag)) break;
    TuningResult one;
    polish(knobs, targets, evaluate, settings, starts[i], ActiveSet{}, stopFlag, one);
    repolishOnActiveSet(knobs, targets, evaluate, settings, starts[i], stopFlag, one);
    const TuningPoint best = findBestTuningPoint(one.polished, {starts[i]});
    if (i == 0 || isBetter(best, findBestTuningPoint(result.polished, {result.best}))) {
      result.converged = one.converged;
      result.stopReason = one.stopReason;
      result.iterations = one.iterations;
      result.polishStart = static_cast<int>(i);
      result.polishEnd = one.polishEnd;
    }
    result.polished.insert(result.polished.end(), one.polished.begin(), one.polished.end());
    bestCost = std::min(bestCost, best.feasible() ? best.cost : bestCost);
    if (bestCost <= kMetCost) break;
  }
}

}  // namespace

TuningPoint findBestTuningPoint(const std::vector<TuningPoint>& a, const std::vector<TuningPoint>& b) {
  TuningPoint best;
  bool any = false;
  for (const auto* set : {&a, &b})
    for (const TuningPoint& p : *set)
      if (!any || isBetter(p, best)) best = p, any = true;
  return best;
}

TuningResult runKneeTuning(const std::vector<TuningKnob>& knobs, const std::vector<TuningTarget>& targets,
                           const TuningEvaluator& evaluate, const TuningSettings& settings,
                           const std::function<void(int, int)>& progress, const volatile bool* stopFlag) {
  TuningResult result;
  result.knobs = knobs;
  result.startSet = runStartSet(knobs, targets, evaluate, settings, progress, stopFlag);
  result.interrupted = stopFlag != nullptr && *stopFlag;
  const TuningPoint start = findBestTuningPoint(result.startSet, {});
  result.best = start;
  if (!start.ran) {
    if (result.interrupted) return result;
    throw InputError("no point of the start set ran; the first failed: " +
                     (result.startSet.empty() ? std::string("none ran") : result.startSet.front().failure));
  }
  if (!result.interrupted) polishFromBestStarts(knobs, targets, evaluate, settings, stopFlag, result);
  result.interrupted = stopFlag != nullptr && *stopFlag;
  result.best = findBestTuningPoint(result.startSet, result.polished);
  if (!result.interrupted) {
    result.resolution =
        checkTuningResolution(knobs, targets, evaluate, result.best, settings.toleranceWindow, settings.jobs, stopFlag);
    if (result.resolution.ran) result.best = result.resolution.result;
    result.interrupted = stopFlag != nullptr && *stopFlag;
  }
  result.feasible = result.best.feasible();
  result.evaluations = static_cast<int>(result.startSet.size() + result.polished.size());
  if (!result.interrupted) analyseTuningResult(targets, evaluate, settings.jobs, result);
  return result;
}

}  // namespace swingsim
