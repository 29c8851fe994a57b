#include "sweep/tuning_analysis.h"

#include <cmath>
#include <sstream>

#include "sweep/sweep.h"

namespace swingsim {

double calcTargetMiss(const TuningTarget& target, double value) {
  if (value < target.lower) return value - target.lower;
  if (value > target.upper) return value - target.upper;
  return 0;
}

namespace {

// Signed margin inside the window, in scale units (negative outside), and its slope d margin /
// d value (SI): from the nearer edge, or from the edge the limit is held at.
double marginInScaleUnits(const TuningTarget& t, double value, LimitHold hold, double* slope) {
  const bool fromLower =
      hold == LimitHold::kAtLower || (hold == LimitHold::kPenalty && value - t.lower <= t.upper - value);
  if (slope != nullptr) *slope = (fromLower ? 1.0 : -1.0) / t.scale;
  return (fromLower ? value - t.lower : t.upper - value) / t.scale;
}

LimitHold holdOf(const std::vector<LimitHold>& holds, std::size_t i) {
  return i < holds.size() ? holds[i] : LimitHold::kPenalty;
}

Eigen::VectorXd toVector(std::vector<double> r) {
  if (r.empty()) r.push_back(0);
  return Eigen::Map<const Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size()));
}

}  // namespace

Eigen::VectorXd calcTuningResiduals(const TuningPoint& point, const std::vector<TuningTarget>& targets,
                                    const HardLimitPenalty& penalty, const std::vector<LimitHold>& holds) {
  std::vector<double> r;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const TuningTarget& t = targets[i];
    const double value = point.value(t.quantity);
    const LimitHold hold = holdOf(holds, i);
    if (!t.hard) {
      r.push_back(std::sqrt(t.weight) * calcTargetMiss(t, value) / t.scale);
      continue;
    }
    const double shortfall = penalty.inside - marginInScaleUnits(t, value, hold, nullptr);
    r.push_back(penalty.weight * (hold == LimitHold::kPenalty ? std::max(0.0, shortfall) : shortfall));
  }
  return toVector(std::move(r));
}

Eigen::VectorXd calcTuningResidualSlopes(const TuningPoint& point, const std::vector<TuningTarget>& targets,
                                         const HardLimitPenalty& penalty, const std::vector<LimitHold>& holds) {
  std::vector<double> slopes;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const TuningTarget& t = targets[i];
    const double value = point.value(t.quantity);
    const LimitHold hold = holdOf(holds, i);
    if (!t.hard) {
      const bool acts = value < t.lower || value > t.upper || t.lower == t.upper;
      slopes.push_back(acts ? std::sqrt(t.weight) / t.scale : 0.0);
      continue;
    }
    double marginSlope = 0;
    const double margin = marginInScaleUnits(t, value, hold, &marginSlope);
    slopes.push_back(hold != LimitHold::kPenalty || margin < penalty.inside ? -penalty.weight * marginSlope : 0.0);
  }
  return toVector(std::move(slopes));
}

namespace {

void setOutcomes(const std::vector<TuningTarget>& targets, TuningResult& result) {
  result.targets.clear();
  for (const TuningTarget& t : targets) {
    TargetOutcome o;
    o.target = t;
    o.value = result.best.value(t.quantity);
    o.margin = std::min(o.value - t.lower, t.upper - o.value);
    o.met = o.margin >= 0 || (t.lower == t.upper && std::abs(o.margin) <= kValueFraction * t.scale);
    o.binding = t.hard && std::abs(o.margin) <= kBindingFraction * t.scale;
    result.targets.push_back(o);
  }
  result.knobAtBound.clear();
  for (std::size_t k = 0; k < result.knobs.size(); ++k) {
    const TuningKnob& knob = result.knobs[k];
    const double x = result.best.knobs[k], tol = kAtBoundFraction * (knob.upper - knob.lower);
    result.knobAtBound.push_back(x <= knob.lower + tol || x >= knob.upper - tol);
  }
}

// Central differences of each target's quantity over 1e-3 of each knob's range (one-sided at a range end).
void setSensitivity(const std::vector<TuningTarget>& targets, const TuningEvaluator& evaluate, int jobs,
                    TuningResult& result) {
  const std::size_t n = result.knobs.size();
  std::vector<TuningPoint> ends(2 * n);
  runParallelJobs(static_cast<int>(2 * n), jobs, [&](int j) {
    const std::size_t k = static_cast<std::size_t>(j) / 2;
    const TuningKnob& knob = result.knobs[k];
    const double h = 1e-3 * (knob.upper - knob.lower);
    std::vector<double> x = result.best.knobs;
    x[k] = j % 2 == 0 ? std::max(knob.lower, x[k] - h) : std::min(knob.upper, x[k] + h);
    TuningPoint& p = ends[static_cast<std::size_t>(j)];
    p.knobs = x;
    try {
      scoreTuningPoint(p, evaluate(x), targets);
    } catch (const std::exception& e) {
      p.ran = false;
    }
  });
  result.sensitivity =
      Eigen::MatrixXd::Constant(static_cast<Eigen::Index>(targets.size()), static_cast<Eigen::Index>(n),
                                std::numeric_limits<double>::quiet_NaN());
  for (std::size_t k = 0; k < n; ++k) {
    const TuningPoint &lo = ends[2 * k], &hi = ends[2 * k + 1];
    if (!lo.ran || !hi.ran) continue;
    for (std::size_t i = 0; i < targets.size(); ++i)
      result.sensitivity(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) =
          (hi.value(targets[i].quantity) - lo.value(targets[i].quantity)) / (hi.knobs[k] - lo.knobs[k]);
  }
}

// A target acts at the result where it pulls on the knobs: a soft one missed or set to a
// value (a window of width 0), a hard one binding or missed.
bool acts(const TargetOutcome& o) {
  const TuningTarget& t = o.target;
  if (t.hard) return o.binding || !o.met;
  return !o.met || t.lower == t.upper || std::abs(o.margin) <= kBindingFraction * t.scale;
}

void setIdentifiability(TuningResult& result) {
  const std::size_t n = result.knobs.size();
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < result.targets.size(); ++i)
    if (acts(result.targets[i])) rows.push_back(i);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(std::max<std::size_t>(rows.size(), 1)),
                                            static_cast<Eigen::Index>(n));
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (std::size_t k = 0; k < n; ++k) {
      const TuningKnob& knob = result.knobs[k];
      const double perRange =
          knob.logScale ? result.best.knobs[k] * std::log(knob.upper / knob.lower) : knob.upper - knob.lower;
      J(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(k)) =
          result.sensitivity(static_cast<Eigen::Index>(rows[r]), static_cast<Eigen::Index>(k)) * perRange /
          result.targets[rows[r]].target.scale;
    }
  if (!J.allFinite()) {
    result.identifiable = false;
    result.identifiability = "not known: a swing of the sensitivity did not run";
    return;
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullV);
  const Eigen::VectorXd sv = svd.singularValues();
  const double ratio = rows.size() < n || sv(0) == 0 ? 0.0 : sv(sv.size() - 1) / sv(0);
  result.identifiable = ratio > kIdentifiableRatio;
  result.ridge.assign(n, 0.0);
  std::ostringstream s;
  s << rows.size() << " target" << (rows.size() == 1 ? "" : "s") << " act" << (rows.size() == 1 ? "s" : "") << " on "
    << n << " knob" << (n == 1 ? "" : "s");
  if (result.identifiable) {
    s << "; the targets fix every knob (smallest/largest singular value " << ratio << ")";
  } else {
    const Eigen::VectorXd v = svd.matrixV().col(static_cast<Eigen::Index>(n) - 1);
    for (std::size_t k = 0; k < n; ++k) result.ridge[k] = v(static_cast<Eigen::Index>(k));
    s << (rows.size() < n ? "; fewer acting targets than knobs: a ridge of settings meets them equally"
                          : "; the targets barely see one combination of knobs (a ridge)");
  }
  result.identifiability = s.str();
}

}  // namespace

void analyseTuningResult(const std::vector<TuningTarget>& targets, const TuningEvaluator& evaluate, int jobs,
                         TuningResult& result) {
  setOutcomes(targets, result);
  setSensitivity(targets, evaluate, jobs, result);
  setIdentifiability(result);
}

}  // namespace swingsim
