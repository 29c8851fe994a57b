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

namespace swingsim {

const char* tuningQuantityKey(TuningQuantity q) {
  switch (q) {
    case TuningQuantity::kSwingTime: return "swing_time_s";
    case TuningQuantity::kPeakKneeFlexion: return "peak_knee_flexion_deg";
    case TuningQuantity::kMinToeClearance: return "min_toe_clearance_m";
    case TuningQuantity::kMaxStopImpactSpeed: return "max_stop_impact_deg_s";
  }
  return "";
}

double tuningTargetScale(TuningQuantity q) {
  switch (q) {
    case TuningQuantity::kSwingTime: return 0.01;
    case TuningQuantity::kPeakKneeFlexion: return 1 * kDegToRad;
    case TuningQuantity::kMinToeClearance: return 0.005;
    case TuningQuantity::kMaxStopImpactSpeed: return 10 * kDegToRad;
  }
  return 1;
}

double TuningPoint::value(TuningQuantity q) const {
  switch (q) {
    case TuningQuantity::kSwingTime: return swingTime;
    case TuningQuantity::kPeakKneeFlexion: return peakKneeFlexion;
    case TuningQuantity::kMinToeClearance: return minToeClearance;
    case TuningQuantity::kMaxStopImpactSpeed: return maxStopImpactSpeed;
  }
  return 0;
}

void scoreTuningPoint(TuningPoint& point, const SwingResult& swing, const std::vector<TuningTarget>& targets) {
  point.swingTime = swing.swingTime;
  if (swing.peakKneeFlexion) point.peakKneeFlexion = swing.peakKneeFlexion->flexion;
  if (swing.minToeClearance) point.minToeClearance = *swing.minToeClearance;
  point.maxStopImpactSpeed = 0;
  for (const StopImpact& im : swing.impacts) point.maxStopImpactSpeed = std::max(point.maxStopImpactSpeed, im.impactRate);
  point.ran = true;
  point.cost = 0;
  point.hardViolation = 0;
  for (const TuningTarget& t : targets) {
    const double value = point.value(t.quantity);
    if (!std::isfinite(value)) {
      point.ran = false;
      point.failure = std::string("the swing has no ") + tuningQuantityKey(t.quantity);
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

namespace {

// One swing at `knobs`, scored; a swing that cannot run is a failed point, not an error.
TuningPoint evaluatePoint(const std::vector<double>& knobs, const std::vector<TuningTarget>& targets,
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
        points[index] = evaluatePoint(knobValuesAt(knobs, unit[index]), targets, evaluate);
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

// The residuals at x and, if asked, their Jacobian by one-sided differences that stay inside
// the knobs' ranges. Only x itself must meet the hard limits (else it throws: Ceres rejects
// the step); the difference points need not, so a polish can follow a hard limit's edge
// instead of ending at the first point near it.
class PolishResiduals {
 public:
  /// `free`: the knobs the polish moves (indices into `knobs`); the others stay at `fixed`'s values.
  PolishResiduals(const std::vector<TuningKnob>& knobs, const std::vector<TuningTarget>& targets, const TuningEvaluator& evaluate,
                  bool feasible, const volatile bool* stopFlag, std::vector<TuningPoint>& evaluated,
                  std::vector<std::size_t> free, std::vector<double> fixed)
      : knobs_(knobs), targets_(targets), evaluate_(evaluate), feasible_(feasible), stop_(stopFlag), evaluated_(evaluated),
        free_(std::move(free)), fixed_(std::move(fixed)) {}

  Eigen::VectorXd operator()(const Eigen::VectorXd& x, Eigen::MatrixXd* jacobian) const {
    std::vector<double> all = fixed_;
    for (std::size_t i = 0; i < free_.size(); ++i) all[free_[i]] = x[static_cast<Eigen::Index>(i)];
    const TuningPoint p = run(all);
    if (feasible_ && p.hardViolation > 0) throw RunError("breaks a hard limit");
    const Eigen::VectorXd r = calcTuningResiduals(p, targets_, feasible_);
    if (jacobian == nullptr) return r;
    jacobian->resize(r.size(), x.size());
    for (std::size_t i = 0; i < free_.size(); ++i) {
      const TuningKnob& knob = knobs_[free_[i]];
      const double value = all[free_[i]];
      double h = kDifferenceStep * (knob.logScale ? value : knob.upper - knob.lower);
      if (value + h > knob.upper) h = -h;
      std::vector<double> moved = all;
      moved[free_[i]] += h;
      jacobian->col(static_cast<Eigen::Index>(i)) = (calcTuningResiduals(run(moved), targets_, feasible_) - r) / h;
    }
    return r;
  }

 private:
  TuningPoint run(const std::vector<double>& x) const {
    if (stop_ != nullptr && *stop_) throw RunError("stopped");
    TuningPoint p = evaluatePoint(x, targets_, evaluate_);
    evaluated_.push_back(p);
    if (!p.ran) throw RunError(p.failure);
    return p;
  }

  const std::vector<TuningKnob>& knobs_;
  const std::vector<TuningTarget>& targets_;
  const TuningEvaluator& evaluate_;
  bool feasible_;
  const volatile bool* stop_;
  std::vector<TuningPoint>& evaluated_;
  std::vector<std::size_t> free_;
  std::vector<double> fixed_;
};

// The Ceres polish from `start` over the knobs not in `held` (held ones stay at start's
// values): toward the soft targets among feasible points (a point that breaks a hard limit
// throws, so Ceres rejects the step), or, where `start` is not feasible, toward the least
// hard violation. Every evaluation is kept in `result.polished`.
void polish(const std::vector<TuningKnob>& knobs, const std::vector<TuningTarget>& targets, const TuningEvaluator& evaluate,
            const TuningSettings& settings, const TuningPoint& start, const std::vector<bool>& held,
            const volatile bool* stopFlag, TuningResult& result) {
  std::vector<BoundedParameter> parameters;
  std::vector<std::size_t> free;
  for (std::size_t k = 0; k < knobs.size(); ++k) {
    if (held[k]) continue;
    free.push_back(k);
    parameters.push_back({knobs[k].key, start.knobs[k], knobs[k].lower, knobs[k].upper, knobs[k].logScale,
                          knobs[k].logScale ? 1.0 : knobs[k].upper - knobs[k].lower});
  }
  if (free.empty()) return;
  const PolishResiduals residuals(knobs, targets, evaluate, start.feasible(), stopFlag, result.polished, free, start.knobs);
  BoundedFitSettings fit;
  fit.maxIterations = settings.maxIterations;
  fit.maxSeconds = settings.maxSeconds;
  fit.computeCovariance = false;
  // A value target is met within 1 % of its scale (kValueFraction): a cost of 1e-8 or less.
  fit.functionTolerance = 1e-12;
  fit.parameterTolerance = 1e-10;
  try {
    const BoundedFitResult r = solveBoundedLeastSquares(ResidualJacobianFunction(std::cref(residuals)), parameters, fit);
    result.converged = r.converged;
    result.stopReason = r.stopReason;
    result.iterations = r.iterations;
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

// Ceres keeps a bound by projecting its steps onto the box, which can stall a polish whose
// best point has a knob at a range end while another knob still has room: polish again from
// that point with the knobs at a range end held there (an active-set restart, still Ceres).
void repolishAtRangeEnds(const std::vector<TuningKnob>& knobs, const std::vector<TuningTarget>& targets,
                         const TuningEvaluator& evaluate, const TuningSettings& settings, const TuningPoint& start,
                         const volatile bool* stopFlag, TuningResult& one) {
  const TuningPoint best = findBestTuningPoint(one.polished, {start});
  std::vector<bool> held(knobs.size(), false);
  std::size_t count = 0;
  for (std::size_t k = 0; k < knobs.size(); ++k) {
    const double tol = kAtBoundFraction * (knobs[k].upper - knobs[k].lower);
    held[k] = best.knobs[k] <= knobs[k].lower + tol || best.knobs[k] >= knobs[k].upper - tol;
    count += held[k] ? 1 : 0;
  }
  if (count == 0 || count == knobs.size() || !best.ran) return;
  TuningResult again;
  polish(knobs, targets, evaluate, settings, best, held, stopFlag, again);
  one.polished.insert(one.polished.end(), again.polished.begin(), again.polished.end());
  one.iterations += again.iterations;
  if (!again.stopReason.empty() || again.converged) {
    one.converged = again.converged;
    one.stopReason = again.stopReason;
  }
}

// The start points in order of merit, for the polish.
std::vector<TuningPoint> rankStarts(std::vector<TuningPoint> points) {
  std::stable_sort(points.begin(), points.end(), isBetter);
  return points;
}

// Polishes from the best start; while the best point so far still misses a soft target (its
// cost above kMetCost), from the next-best feasible start too, up to settings.polishStarts:
// a polish that runs into a hard limit ends there (rejection), and another start may go round it.
void polishFromBestStarts(const std::vector<TuningKnob>& knobs, const std::vector<TuningTarget>& targets,
                          const TuningEvaluator& evaluate, const TuningSettings& settings, const volatile bool* stopFlag,
                          TuningResult& result) {
  constexpr double kMetCost = 1e-8;  // every value target within 1e-4 of its scale
  const std::vector<TuningPoint> starts = rankStarts(result.startSet);
  double bestCost = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < starts.size() && static_cast<int>(i) < settings.polishStarts; ++i) {
    if (!starts[i].ran || (i > 0 && !starts[i].feasible()) || (stopFlag != nullptr && *stopFlag)) break;
    TuningResult one;
    polish(knobs, targets, evaluate, settings, starts[i], std::vector<bool>(knobs.size(), false), stopFlag, one);
    repolishAtRangeEnds(knobs, targets, evaluate, settings, starts[i], stopFlag, one);
    const TuningPoint best = findBestTuningPoint(one.polished, {starts[i]});
    if (i == 0 || isBetter(best, findBestTuningPoint(result.polished, {result.best}))) {
      result.converged = one.converged;
      result.stopReason = one.stopReason;
      result.iterations = one.iterations;
      result.polishStart = static_cast<int>(i);
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
  result.feasible = result.best.feasible();
  result.evaluations = static_cast<int>(result.startSet.size() + result.polished.size());
  if (!result.interrupted) analyseTuningResult(targets, evaluate, settings.jobs, result);
  return result;
}

}  // namespace swingsim
