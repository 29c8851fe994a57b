#include "sweep/tuning_resolution.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/text_format.h"
#include "core/units.h"
#include "sweep/sweep.h"
#include "sweep/tuning_analysis.h"

namespace swingsim {

namespace {

// A grid index is taken as exact within this fraction of a step (round-off of value / resolution).
constexpr double kOnGrid = 1e-9;

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The valid grid indices of a knob: multiples of its resolution inside [lower, upper].
int lowestIndex(const TuningKnob& k) { return static_cast<int>(std::ceil(k.lower / k.resolution - kOnGrid)); }
int highestIndex(const TuningKnob& k) { return static_cast<int>(std::floor(k.upper / k.resolution + kOnGrid)); }
double gridValue(const TuningKnob& k, int index) {
  // Printed values stay short: 0.022, not 0.021999999999999999.
  return std::stod(fmt("%.12g", index * k.resolution));
}

// A cell: per knob the indices of its lower and upper corner (equal for a knob on the grid or
// without a resolution, whose value is kept).
struct Cell {
  std::vector<int> lo, hi;
};

// The cell around `x`: each knob rounded down and up.
Cell cellAround(const std::vector<TuningKnob>& knobs, const std::vector<double>& x) {
  Cell c;
  for (std::size_t k = 0; k < knobs.size(); ++k) {
    if (knobs[k].resolution <= 0) {
      c.lo.push_back(0);
      c.hi.push_back(0);
      continue;
    }
    const double u = x[k] / knobs[k].resolution;
    const int lo = std::clamp(static_cast<int>(std::floor(u + kOnGrid)), lowestIndex(knobs[k]), highestIndex(knobs[k]));
    const int hi = std::clamp(static_cast<int>(std::ceil(u - kOnGrid)), lowestIndex(knobs[k]), highestIndex(knobs[k]));
    c.lo.push_back(std::min(lo, hi));
    c.hi.push_back(std::max(lo, hi));
  }
  return c;
}

// The corners' knob values, every combination of each knob's lower and upper index.
std::vector<std::vector<double>> cornersOf(const std::vector<TuningKnob>& knobs, const Cell& c,
                                           const std::vector<double>& x) {
  std::vector<std::vector<double>> corners = {{}};
  for (std::size_t k = 0; k < knobs.size(); ++k) {
    std::vector<double> values;
    if (knobs[k].resolution <= 0)
      values = {x[k]};
    else {
      values.push_back(gridValue(knobs[k], c.lo[k]));
      if (c.hi[k] != c.lo[k]) values.push_back(gridValue(knobs[k], c.hi[k]));
    }
    std::vector<std::vector<double>> next;
    for (const auto& partial : corners)
      for (double v : values) {
        next.push_back(partial);
        next.back().push_back(v);
      }
    corners = std::move(next);
  }
  return corners;
}

// The cells one step of the grid around `c` in any combination of knobs (c itself left out),
// inside the knobs' ranges.
std::vector<Cell> neighbourCells(const std::vector<TuningKnob>& knobs, const Cell& c) {
  std::vector<Cell> cells = {c};
  for (std::size_t k = 0; k < knobs.size(); ++k) {
    if (knobs[k].resolution <= 0) continue;
    std::vector<Cell> next;
    for (const Cell& partial : cells)
      for (int shift : {-1, 0, 1}) {
        Cell moved = partial;
        moved.lo[k] += shift;
        moved.hi[k] += shift;
        if (moved.lo[k] < lowestIndex(knobs[k]) || moved.hi[k] > highestIndex(knobs[k])) continue;
        next.push_back(moved);
      }
    cells = std::move(next);
  }
  cells.erase(std::remove_if(cells.begin(), cells.end(), [&](const Cell& x) { return x.lo == c.lo && x.hi == c.hi; }),
              cells.end());
  return cells;
}

// "lowering_m 0.022, ...equilibrium_deg 42"
std::string describeKnobs(const std::vector<TuningKnob>& knobs, const std::vector<double>& values) {
  std::string out;
  for (std::size_t k = 0; k < knobs.size(); ++k) out += (k ? ", " : "") + knobs[k].key + " " + fmt("%.6g", values[k]);
  return out;
}

// Why a point fails the check: the first hard limit it misses, or the swing that did not run.
std::string describeFailure(const std::vector<TuningTarget>& targets, const TuningPoint& p) {
  if (!p.ran) return "no swing (" + p.failure + ")";
  for (const TuningTarget& t : targets) {
    if (!t.hard) continue;
    const double miss = calcTargetMiss(t, p.value(t.quantity));
    if (miss != 0)
      return std::string(tuningQuantityKey(t.quantity)) + " " +
             fmt("%.4g", tuningQuantityInKeyUnit(t.quantity, p.value(t.quantity))) + ", past its limit by " +
             fmt("%.2g", std::fabs(tuningQuantityInKeyUnit(t.quantity, miss)));
  }
  return "";
}

// Evaluates knob vectors on `jobs` threads, each once.
class PointCache {
 public:
  PointCache(const std::vector<TuningTarget>& targets, const TuningEvaluator& evaluate, int jobs,
             const volatile bool* stopFlag)
      : targets_(targets), evaluate_(evaluate), jobs_(jobs), stopFlag_(stopFlag) {}
  void run(const std::vector<std::vector<double>>& wanted) {
    std::vector<std::vector<double>> todo;
    for (const auto& x : wanted)
      if (!points_.count(x) && std::find(todo.begin(), todo.end(), x) == todo.end()) todo.push_back(x);
    std::vector<TuningPoint> done(todo.size());
    runParallelJobs(
        static_cast<int>(todo.size()), jobs_,
        [&](int i) {
          done[static_cast<std::size_t>(i)] =
              evaluateTuningPoint(todo[static_cast<std::size_t>(i)], targets_, evaluate_);
        },
        {}, stopFlag_);
    for (std::size_t i = 0; i < todo.size(); ++i) points_[todo[i]] = done[i];
  }
  const TuningPoint& at(const std::vector<double>& x) const { return points_.at(x); }
  TuningPoint evaluate(const std::vector<double>& x) const { return evaluateTuningPoint(x, targets_, evaluate_); }

 private:
  const std::vector<TuningTarget>& targets_;
  const TuningEvaluator& evaluate_;
  int jobs_;
  const volatile bool* stopFlag_;
  std::map<std::vector<double>, TuningPoint> points_;
};

// The first reason a cell's corners do not hold ("" if they do): a corner missing a hard
// limit, or corners on two pieces of the swing time (a jump inside the cell).
std::string cellProblem(const std::vector<TuningKnob>& knobs, const std::vector<TuningTarget>& targets,
                        const std::vector<TuningPoint>& corners) {
  for (const TuningPoint& p : corners)
    if (!p.feasible()) return "at " + describeKnobs(knobs, p.knobs) + ": " + describeFailure(targets, p);
  for (const TuningPoint& p : corners)
    if (p.bounces != corners.front().bounces)
      return "the swing time jumps inside it (" + std::to_string(corners.front().bounces) + " and " +
             std::to_string(p.bounces) + " bounces at its corners: a result within one step of a jump)";
  return "";
}

// How far a cell is from holding: its corners' hard violations (in scale units), a corner
// without a swing or on another piece counting as kFarFromHolding each.
constexpr double kFarFromHolding = 1e6;
double cellViolation(const std::vector<TuningPoint>& corners) {
  double v = 0;
  for (const TuningPoint& p : corners)
    v += !p.ran ? kFarFromHolding : p.hardViolation + (p.bounces != corners.front().bounces ? kFarFromHolding : 0);
  return v;
}

std::vector<TuningPoint> cornerPoints(const PointCache& cache, const std::vector<std::vector<double>>& corners) {
  std::vector<TuningPoint> out;
  for (const auto& x : corners) out.push_back(cache.at(x));
  return out;
}

// Walks knob k from the result in steps of its resolution (`direction` +1 or -1) while every
// hard limit holds, the swing time stays within `window` and on the result's piece; returns the
// last value that held and what stopped the walk.
std::pair<double, std::string> walkBand(const std::vector<TuningKnob>& knobs, const std::vector<TuningTarget>& targets,
                                        const PointCache& cache, const TuningPoint& result, std::size_t k,
                                        int direction, double window) {
  const TuningKnob& knob = knobs[k];
  double held = result.knobs[k];
  if (knob.resolution <= 0) return {held, "no resolution"};
  const int start = static_cast<int>(std::lround(result.knobs[k] / knob.resolution));
  for (int step = 1; step <= kMaxBandSteps; ++step) {
    const int index = start + direction * step;
    if (index < lowestIndex(knob) || index > highestIndex(knob)) return {held, "range end"};
    std::vector<double> x = result.knobs;
    x[k] = gridValue(knob, index);
    const TuningPoint p = cache.evaluate(x);
    if (!p.feasible()) return {held, describeFailure(targets, p)};
    if (p.bounces != result.bounces) return {held, "a jump of the swing time"};
    if (std::fabs(p.swingTime - result.swingTime) > window)
      return {held, "swing time " + fmt("%+.0f", (p.swingTime - result.swingTime) * 1000) + " ms"};
    held = x[k];
  }
  return {held, std::to_string(kMaxBandSteps) + " steps (not walked further)"};
}

std::vector<KnobBand> findBands(const std::vector<TuningKnob>& knobs, const std::vector<TuningTarget>& targets,
                                const PointCache& cache, const TuningPoint& result, double window, int jobs,
                                const volatile bool* stopFlag) {
  std::vector<KnobBand> bands(knobs.size());
  runParallelJobs(
      static_cast<int>(2 * knobs.size()), jobs,
      [&](int job) {
        const auto k = static_cast<std::size_t>(job / 2);
        const bool up = job % 2 == 1;
        const auto [value, stop] = walkBand(knobs, targets, cache, result, k, up ? 1 : -1, window);
        (up ? bands[k].high : bands[k].low) = value;
        (up ? bands[k].highStop : bands[k].lowStop) = stop;
      },
      {}, stopFlag);
  return bands;
}

// The cells one grid step around `current`: the best that holds (by its best corner), and the
// one that does not hold closest to holding (below `violationBelow`).
struct NeighbourScan {
  std::optional<Cell> holding;
  std::vector<TuningPoint> holdingCorners;
  TuningPoint holdingBest;
  std::optional<Cell> closest;
  double closestViolation = 0;
};

NeighbourScan scanNeighbours(const std::vector<TuningKnob>& knobs, const std::vector<TuningTarget>& targets,
                             PointCache& cache, const Cell& current, const std::vector<double>& x,
                             double violationBelow, int& cellsTried) {
  const std::vector<Cell> cells = neighbourCells(knobs, current);
  std::vector<std::vector<double>> wanted;
  for (const Cell& c : cells)
    for (const auto& corner : cornersOf(knobs, c, x)) wanted.push_back(corner);
  cache.run(wanted);
  cellsTried += static_cast<int>(cells.size());
  NeighbourScan scan;
  scan.closestViolation = violationBelow;
  for (const Cell& c : cells) {
    const std::vector<TuningPoint> corners = cornerPoints(cache, cornersOf(knobs, c, x));
    if (cellProblem(knobs, targets, corners).empty()) {
      const TuningPoint best = findBestTuningPoint(corners, {});
      if (!scan.holding || best.cost < scan.holdingBest.cost) {
        scan.holding = c;
        scan.holdingCorners = corners;
        scan.holdingBest = best;
      }
    } else if (const double v = cellViolation(corners); v < scan.closestViolation) {
      scan.closest = c;
      scan.closestViolation = v;
    }
  }
  return scan;
}

// From a cell that does not hold, steps to the neighbouring cell (one grid step in any
// combination of knobs) that is closest to holding, until one holds, none comes closer, or
// kMaxCellMoves steps; then, from the cell that holds, to a neighbouring cell that holds with a
// lower cost while there is one (at most kMaxCellMoves steps): the best corner of the last is
// the result.
void moveInside(const std::vector<TuningKnob>& knobs, const std::vector<TuningTarget>& targets, PointCache& cache,
                const Cell& first, const std::vector<double>& x, const std::string& firstProblem,
                ResolutionCheck& check) {
  Cell current = first;
  double currentViolation = cellViolation(check.corners);
  int inside = 0;
  for (int move = 1; move <= kMaxCellMoves && !check.holds; ++move) {
    const NeighbourScan scan = scanNeighbours(knobs, targets, cache, current, x, currentViolation, check.cellsTried);
    if (scan.holding) {
      current = *scan.holding;
      check.result = scan.holdingBest;
      check.corners = scan.holdingCorners;
      check.holds = true;
      inside = move;
    } else if (scan.closest) {
      current = *scan.closest;
      currentViolation = scan.closestViolation;
    } else {
      break;
    }
  }
  if (!check.holds) {
    check.verdict = "cannot: no cell within " + std::to_string(kMaxCellMoves) +
                    " grid steps of the optimum (searched "
                    "toward the limits' inside) has every corner meeting every hard limit on one piece of the swing "
                    "time; around the optimum: " +
                    firstProblem;
    return;
  }
  int along = 0;
  for (; along < kMaxCellMoves; ++along) {
    const NeighbourScan scan = scanNeighbours(knobs, targets, cache, current, x, 0, check.cellsTried);
    if (!scan.holding || !(scan.holdingBest.cost < check.result.cost)) break;
    current = *scan.holding;
    check.result = scan.holdingBest;
    check.corners = scan.holdingCorners;
  }
  check.verdict = "moved " + std::to_string(inside) + (inside == 1 ? " step" : " steps") +
                  " inside: the cell around the optimum fails (" + firstProblem + ")" +
                  (along > 0 ? ", then " + std::to_string(along) + (along == 1 ? " step" : " steps") +
                                   " to cells that hold at a lower cost"
                             : "") +
                  "; the cell chosen has all " + std::to_string(check.corners.size()) +
                  " corners meeting every hard limit on one piece of the swing time";
}

}  // namespace

std::optional<double> findDefaultKnobResolution(const std::string& key) {
  // First match wins: the known rates before the other compound units ("_per_m", "_per_s",
  // ...), which say nothing of a setting's step (0: the study must state it), before "_m".
  static const std::vector<std::pair<std::string, double>> kBySuffix = {
      {"_Nm_s_per_rad", 0.1}, {"_Nm_per_rad", 1.0}, {"_per_rad", 0},  {"_per_m", 0},     {"_per_s", 0},
      {"_deg", 1.0},          {"_kg", 0.01},        {"_scale", 0.01}, {"_factor", 0.01}, {"_m", 0.001}};
  for (const auto& [suffix, resolution] : kBySuffix)
    if (endsWith(key, suffix)) return resolution > 0 ? std::optional<double>(resolution) : std::nullopt;
  return std::nullopt;
}

double roundToKnobGrid(const TuningKnob& knob, double value) {
  if (knob.resolution <= 0) return value;
  const int index =
      std::clamp(static_cast<int>(std::lround(value / knob.resolution)), lowestIndex(knob), highestIndex(knob));
  return gridValue(knob, index);
}

ResolutionCheck checkTuningResolution(const std::vector<TuningKnob>& knobs, const std::vector<TuningTarget>& targets,
                                      const TuningEvaluator& evaluate, const TuningPoint& continuous, double window,
                                      int jobs, const volatile bool* stopFlag) {
  ResolutionCheck check;
  const auto rounded = std::count_if(knobs.begin(), knobs.end(), [](const TuningKnob& k) { return k.resolution > 0; });
  if (rounded == 0 || !continuous.ran) return check;
  check.ran = true;
  check.continuous = continuous;
  check.window = window;
  PointCache cache(targets, evaluate, jobs, stopFlag);
  const Cell first = cellAround(knobs, continuous.knobs);
  const auto firstCorners = cornersOf(knobs, first, continuous.knobs);
  cache.run(firstCorners);
  check.cellsTried = 1;
  check.corners = cornerPoints(cache, firstCorners);
  check.result = findBestTuningPoint(check.corners, {});
  const std::string firstProblem = cellProblem(knobs, targets, check.corners);
  const std::string count = std::to_string(check.corners.size());
  if (firstProblem.empty()) {
    check.holds = true;
    check.verdict = "all " + count +
                    " rounding neighbours (each knob rounded down and up) meet every hard limit on one "
                    "piece of the swing time";
  } else if (rounded > kMaxKnobsForCellSearch) {
    check.verdict = "cannot: the cell around the optimum fails (" + firstProblem + "), and with " +
                    std::to_string(rounded) + " knobs its neighbouring cells are not searched";
  } else {
    moveInside(knobs, targets, cache, first, continuous.knobs, firstProblem, check);
  }
  if (check.holds && !(stopFlag && *stopFlag))
    check.bands = findBands(knobs, targets, cache, check.result, window, jobs, stopFlag);
  return check;
}

}  // namespace swingsim
