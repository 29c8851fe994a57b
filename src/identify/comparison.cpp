#include "identify/comparison.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/input_error.h"
#include "core/text_format.h"
#include "numerics/metrics.h"
#include "numerics/residual_analysis.h"

namespace swingsim {

namespace {

constexpr int kStructureBins = 12;  // equal-count bins of the binned mean residual

}  // namespace

void finishRecordComparison(RecordComparison& rc, std::size_t phases) {
  const std::size_t n = rc.measured.size();
  rc.residual.resize(n);
  for (std::size_t i = 0; i < n; ++i) rc.residual[i] = rc.measured[i] - rc.predicted[i];
  rc.overall = calcErrorMetrics(rc.measured, rc.predicted);
  double total = 0;
  for (double r : rc.residual) total += r * r;
  rc.perPhase.clear();
  rc.phaseShare.clear();
  rc.sampleShare.clear();
  for (std::size_t ph = 0; ph < phases; ++ph) {
    std::vector<bool> mask(n);
    double sq = 0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < n; ++i) {
      mask[i] = rc.phase[i] == static_cast<int>(ph);
      if (mask[i]) {
        sq += rc.residual[i] * rc.residual[i];
        ++count;
      }
    }
    rc.perPhase.push_back(calcErrorMetrics(rc.measured, rc.predicted, mask));
    rc.phaseShare.push_back(total > 0 ? sq / total : 0.0);
    rc.sampleShare.push_back(n > 0 ? static_cast<double>(count) / static_cast<double>(n) : 0.0);
  }
}

std::string describeResidualStructure(const Comparison& cmp, double effectiveSampleRatio) {
  std::string out;
  if (cmp.records.empty()) return out;
  // The phase with the largest excess of squared error over its share of samples (first record).
  double bestExcess = -1;
  const auto& first = cmp.records.front();
  for (std::size_t ph = 0; ph < cmp.phaseNames.size(); ++ph) {
    const double excess = first.phaseShare[ph] - first.sampleShare[ph];
    if (excess > bestExcess) {
      bestExcess = excess;
      out = "the largest share of squared " + cmp.quantity + " error is in " + cmp.phaseNames[ph] + " (" +
            fmt("%.0f", 100 * first.phaseShare[ph]) + " % of the error in " + fmt("%.0f", 100 * first.sampleShare[ph]) +
            " % of the samples)";
    }
  }
  // Pool the training records per state variable.
  std::vector<StateVariable> pooled = first.variables;
  for (auto& v : pooled) v.values.clear();
  std::vector<double> residual;
  for (const auto& rc : cmp.records) {
    if (!rc.training) continue;
    residual.insert(residual.end(), rc.residual.begin(), rc.residual.end());
    for (std::size_t k = 0; k < pooled.size() && k < rc.variables.size(); ++k)
      pooled[k].values.insert(pooled[k].values.end(), rc.variables[k].values.begin(), rc.variables[k].values.end());
  }
  double best = 0;
  std::string binNote;
  for (const auto& var : pooled) {
    const BinnedResidual b = calcBinnedResidual(var.values, residual, kStructureBins, effectiveSampleRatio);
    if (b.maxSignificance > best && !b.center.empty()) {
      best = b.maxSignificance;
      binNote = "; the binned mean residual departs most from zero at " + var.label + " = " +
                fmt("%.3g", b.center[b.maxBin]) + " (mean " + fmt("%.3g", b.mean[b.maxBin]) + " " + cmp.unit + ", " +
                fmt("%.1f", b.maxSignificance) + " x its 99 % half-width)";
      if (b.maxSignificance > 1) {
        // Where in the state it sits: the run of bins with a nonzero mean of that sign.
        const bool fromBottom = b.runFirst == 0, toTop = b.runLast + 1 == b.center.size();
        const std::string lo = fmt("%.3g", b.lower[b.runFirst]), hi = fmt("%.3g", b.upper[b.runLast]);
        std::string where;
        if (fromBottom && toTop)
          where = "over the whole range of " + var.label;
        else if (toTop)
          where = "only above " + var.label + " = " + lo;
        else if (fromBottom)
          where = "only below " + var.label + " = " + hi;
        else
          where = "only for " + var.label + " from " + lo + " to " + hi;
        binNote += "; the mean residual is " + std::string(b.mean[b.maxBin] > 0 ? "positive" : "negative") +
                   " (99 %) " + where;
      }
    }
  }
  return out + binNote;
}

void finishHeldBackComparison(HeldBackComparison& c) {
  std::vector<double> allMeasured, allModel;
  for (auto& r : c.records) {
    std::vector<double> diff;
    for (std::size_t i = 0; i < r.measured.size(); ++i) diff.push_back(r.model[i] - r.measured[i]);
    r.rmse = calcRms(diff);
    r.correlation = calcCorrelation(r.measured, r.model);
    allMeasured.insert(allMeasured.end(), r.measured.begin(), r.measured.end());
    allModel.insert(allModel.end(), r.model.begin(), r.model.end());
  }
  std::vector<double> diff;
  for (std::size_t i = 0; i < allMeasured.size(); ++i) diff.push_back(allModel[i] - allMeasured[i]);
  c.rmse = calcRms(diff);
  c.correlation = calcCorrelation(allMeasured, allModel);
}

std::vector<std::string> checkHeldBackComparison(const HeldBackComparison& c) {
  std::vector<std::string> out;
  for (const auto& r : c.records)
    if (r.correlation < 0)
      out.push_back(r.stem + ": the measured " + c.quantity +
                    " correlates negatively with the model's (r = " + formatNumber(r.correlation) +
                    "): is its sign flipped? An OpenSim generalized force acts along its "
                    "coordinate, so motion_columns: knee_sign applies to it too (OpenSim's knee: knee_sign: -1)");
  return out;
}

}  // namespace swingsim
