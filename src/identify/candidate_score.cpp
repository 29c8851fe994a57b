// Scoring one candidate effect on top of the current model: its refit (with its grid
// parameter profiled), the likelihood-ratio test and held-out errors, its parameters with
// their intervals, whether the records carry information on it, its physical sign and where
// the error fell.
#include "identify/candidate_score.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/input_error.h"
#include "numerics/profile_likelihood.h"

namespace swingsim {

namespace {

// chi^2(1) 95 % quantile, for the profile-likelihood interval of a grid parameter.
const double kChi2One95 = calcChiSquaredQuantile(0.95, 1);

std::string fmtPercent(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f", v);
  return buf;
}

// A likelihood gain below this is none: the chi^2(1) tail at 0.1 is 0.75, and the refits'
// own convergence (each record's pose refitted from its start) moves an LR by ~0.01.
constexpr double kNoLikelihoodGain = 0.1;
// A Wald interval wider than this many physical ranges comes from a Jacobian column that is
// round-off: across its whole range the parameter moves the fit by less than a hundredth of
// what the interval's edge means.
constexpr double kEnormousRanges = 100;

// How the grid parameter's interval was found when the profile's 95 % region reaches an end of
// the grid: the likelihood was not seen to fall beyond it, so that side is open (to the
// parameter's physical bound 0 below, unbounded above) and the grid's end is no 95 % limit.
std::string describeGridEdge(bool openBelow, bool openAbove, double first, double last) {
  char buf[200];
  if (openBelow && openAbove)
    std::snprintf(buf, sizeof buf,
                  "profile over the grid; its 95 %% region spans the whole grid %.4g .. %.4g: open both ways", first,
                  last);
  else if (openBelow)
    std::snprintf(buf, sizeof buf,
                  "profile over the grid; one-sided: its 95 %% region reaches the grid's smallest value %.4g and is "
                  "open below it",
                  first);
  else
    std::snprintf(
        buf, sizeof buf,
        "profile over the grid; one-sided: its 95 %% region reaches the grid's largest value %.4g and is open above it",
        last);
  return buf;
}

// Where the profile statistic n_eff ln(RSS / RSS_best) crosses chi^2_1(0.95) between a grid
// value inside the region (statistic `in`) and the next one outside (`out`): linear in the log
// of the grid value.
double interpolateCrossing(double gridIn, double in, double gridOut, double out) {
  const double share = (kChi2One95 - in) / (out - in);
  return std::exp(std::log(gridIn) + share * (std::log(gridOut) - std::log(gridIn)));
}

// The grid parameter's interval: where the profile likelihood over the grid values (and the
// refined best) crosses its 95 % level, found by walking out from the best (fits[g] at
// grid[g]); a side on which the grid ends inside the region is open (to the physical bound 0
// below, unbounded above) and says so. The fitted parameters' intervals are conditional on the
// grid value: their union over every grid value in the region, so the grid choice cannot
// narrow them.
void widenOverGridRegion(const DiagnosisPlant& plant, const std::vector<PlantFit>& fits,
                         const std::vector<double>& grid, std::size_t best, double nEff, EffectId id, double inflate,
                         std::vector<EffectParameter>& parameters) {
  const EffectDescriptor& d = describeEffect(id);
  std::vector<std::size_t> order(grid.size());
  std::vector<double> stat(grid.size());
  for (std::size_t g = 0; g < grid.size(); ++g) {
    order[g] = g;
    stat[g] = nEff * std::log(fits[g].rss / fits[best].rss);
    if (!(stat[g] <= kChi2One95)) continue;
    const auto others = parametersWithIntervals(plant, fits[g], id, inflate);
    for (std::size_t k = 0; k < others.size() && static_cast<int>(k) < d.fittedParameters; ++k) {
      parameters[k].lower = std::min(parameters[k].lower, others[k].lower);
      parameters[k].upper = std::max(parameters[k].upper, others[k].upper);
    }
  }
  EffectParameter& p = parameters.back();
  if (d.grid.size() < 2) {  // a one-value "grid" is a switch (com_rule_proportional), not a profile
    p.lower = p.upper = grid[best] * d.gridReportScale;
    return;
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return grid[a] < grid[b]; });
  const std::size_t at = static_cast<std::size_t>(std::find(order.begin(), order.end(), best) - order.begin());
  bool openBelow = true, openAbove = true;
  p.lower = 0.0;
  p.upper = std::numeric_limits<double>::infinity();
  for (std::size_t i = at; i-- > 0;)
    if (!(stat[order[i]] <= kChi2One95)) {
      p.lower = interpolateCrossing(grid[order[i + 1]], stat[order[i + 1]], grid[order[i]], stat[order[i]]) *
                d.gridReportScale;
      openBelow = false;
      break;
    }
  for (std::size_t i = at + 1; i < order.size(); ++i)
    if (!(stat[order[i]] <= kChi2One95)) {
      p.upper = interpolateCrossing(grid[order[i - 1]], stat[order[i - 1]], grid[order[i]], stat[order[i]]) *
                d.gridReportScale;
      openAbove = false;
      break;
    }
  if (openBelow || openAbove)
    p.intervalNote =
        describeGridEdge(openBelow, openAbove, d.grid.front() * d.gridReportScale, d.grid.back() * d.gridReportScale);
}

// The profile's best between grid values: the vertex of the parabola through the log grid
// value and the RSS of the best and its two neighbours, fitted once and kept when it fits the
// training records better. A best at an end of the grid is not refined (its interval is
// one-sided instead). Appends to `grid` and `fits`; returns the index of the best.
std::size_t refineGridBest(const DiagnosisPlant& plant, const PlantModel& current, EffectId id,
                           std::vector<double>& grid, std::vector<PlantFit>& fits, std::size_t best) {
  if (best == 0 || best + 1 >= grid.size() || !(grid[best - 1] > 0)) return best;
  const double u0 = std::log(grid[best - 1]), u1 = std::log(grid[best]), u2 = std::log(grid[best + 1]);
  const double r0 = fits[best - 1].rss, r1 = fits[best].rss, r2 = fits[best + 1].rss;
  const double denominator = (u1 - u0) * (r1 - r2) - (u1 - u2) * (r1 - r0);
  if (!(std::abs(denominator) > 0)) return best;
  double u = u1 - 0.5 * ((u1 - u0) * (u1 - u0) * (r1 - r2) - (u1 - u2) * (u1 - u2) * (r1 - r0)) / denominator;
  u = std::clamp(u, u0, u2);
  if (!std::isfinite(u) || std::abs(u - u1) < 1e-3) return best;
  try {
    fits.push_back(plant.fit(*plant.addEffect(current, id, std::exp(u))));
  } catch (const RunError&) {
    return best;  // the grid's own best stands
  }
  grid.push_back(std::exp(u));
  return fits.back().rss < fits[best].rss ? fits.size() - 1 : best;
}

// Where the squared error fell most from `current` to `fit`, by the current model's phases
// (`names`): "late extension (62 % of the error fall)".
std::string describeErrorFall(const std::vector<std::string>& names, const PlantFit& current, const PlantFit& s) {
  std::vector<double> fall(names.size(), 0.0);
  double totalFall = 0;
  for (std::size_t f = 0; f < current.trainResidual.size() && f < s.trainResidual.size(); ++f)
    for (std::size_t i = 0; i < current.trainResidual[f].size() && i < s.trainResidual[f].size(); ++i) {
      const double drop =
          current.trainResidual[f][i] * current.trainResidual[f][i] - s.trainResidual[f][i] * s.trainResidual[f][i];
      fall[static_cast<std::size_t>(current.trainPhase[f][i])] += drop;
      totalFall += drop;
    }
  const auto where = static_cast<std::size_t>(std::max_element(fall.begin(), fall.end()) - fall.begin());
  return names[where] +
         (totalFall > 0 ? " (" + fmtPercent(100.0 * fall[where] / totalFall) + " % of the error fall)" : "");
}

}  // namespace

const std::vector<double>* findErrors(const PlantFit& fit, EffectId id) {
  for (const auto& [effect, errors] : fit.effectErrors)
    if (effect == id) return &errors;
  return nullptr;
}

std::vector<EffectParameter> parametersWithIntervals(const DiagnosisPlant& plant, const PlantFit& fit, EffectId id,
                                                     double inflate) {
  const EffectDescriptor& d = describeEffect(id);
  const std::vector<double> values = plant.effectValues(*fit.model, id);
  std::vector<EffectParameter> out;
  for (std::size_t k = 0; k < d.parameters.size() && k < values.size(); ++k)
    out.push_back({d.parameters[k], values[k], values[k], values[k], ""});
  if (const auto* se = findErrors(fit, id))
    for (std::size_t k = 0; k < se->size() && k < out.size() && static_cast<int>(k) < d.fittedParameters; ++k)
      setNormalInterval(out[k], (*se)[k] * inflate);
  return out;
}

bool carriesInformation(const DiagnosisPlant& plant, const PlantFit& current, const PlantFit& fit, EffectId id,
                        double gridValue, double lr, const std::vector<EffectParameter>& wald, double inflate) {
  const EffectDescriptor& d = describeEffect(id);
  if (d.fittedParameters == 0) return true;  // a grid alone: its profile is the information
  const std::vector<double> neutral = plant.effectValues(*plant.addEffect(*current.model, id, gridValue), id);
  const std::vector<double>* errors = findErrors(fit, id);
  const std::vector<std::pair<double, double>>* bounds = nullptr;
  for (const auto& [effect, b] : fit.effectBounds)
    if (effect == id) bounds = &b;
  bool atNeutral = true, saysNothing = true, enormous = true;
  for (std::size_t k = 0; k < wald.size() && static_cast<int>(k) < d.fittedParameters; ++k) {
    if (k >= neutral.size() || wald[k].value != neutral[k]) atNeutral = false;
    const double se = errors && k < errors->size() ? (*errors)[k] * inflate : std::numeric_limits<double>::quiet_NaN();
    // NaN: not computed (a coefficient the active set holds at its bound), which says nothing
    // either way; 0 or infinite: a column of the Jacobian the covariance dropped or cannot fix.
    const bool degenerate = se == 0 || std::isinf(se);
    const bool hasRange = bounds && k < bounds->size() && std::isfinite((*bounds)[k].second - (*bounds)[k].first);
    const bool coversRange = hasRange && wald[k].lower <= (*bounds)[k].first && wald[k].upper >= (*bounds)[k].second;
    if (!degenerate && !coversRange) saysNothing = false;
    if (!degenerate &&
        !(hasRange && wald[k].upper - wald[k].lower > kEnormousRanges * ((*bounds)[k].second - (*bounds)[k].first)))
      enormous = false;
  }
  const bool movesNothing = atNeutral || !(std::abs(lr) > kNoLikelihoodGain) || enormous;
  return !(saysNothing && movesNothing);
}

CandidateScore scoreCandidate(const DiagnosisPlant& plant, const PlantFit& current, EffectId id,
                              const EffectSelectionSettings& settings, PlantFit* bestOut) {
  const EffectDescriptor& d = describeEffect(id);
  CandidateScore c;
  c.id = id;
  c.effect = d.name;
  c.notApplicable = plant.checkApplicable(*current.model, id);
  if (!c.notApplicable.empty()) return c;
  std::vector<double> grid = d.grid.empty() ? std::vector<double>{0.0} : d.grid;
  std::vector<PlantFit> fits;
  std::size_t best = 0;
  for (double g : grid) {
    try {
      fits.push_back(plant.fit(*plant.addEffect(*current.model, id, g)));
    } catch (const RunError& e) {
      c.notApplicable = e.what();
      return c;
    }
    if (fits.back().rss < fits[best].rss) best = fits.size() - 1;
  }
  if (!d.grid.empty()) best = refineGridBest(plant, *current.model, id, grid, fits, best);
  const PlantFit& s = fits[best];
  const int dof = d.degreesOfFreedom();
  LrTest t = calcLrTest(current.rss, s.rss, s.likelihoodResidual, dof);
  // Cross-validated plants: significant on the training rows of every fold, so the test
  // that counts is the least significant fold's.
  if (!s.foldRss.empty() && s.foldRss.size() == current.foldRss.size() && s.foldResidual.size() == s.foldRss.size()) {
    c.allRowsPValue = t.p;
    for (std::size_t f = 0; f < s.foldRss.size(); ++f) {
      const LrTest fold = calcLrTest(current.foldRss[f], s.foldRss[f], s.foldResidual[f], dof);
      c.foldPValues.push_back(fold.p);
      if (f == 0 || !(fold.p <= t.p)) t = fold;  // NaN counts as the least significant
    }
  }
  c.model = s.model;
  c.trainRmse = s.trainRmse;
  c.validationRmse = s.validationRmse;
  c.pooledValidationRmse = s.pooledValidationRmse;
  applyTestAndValidation(c, t, dof, current.validationRmse, settings, current.pooledValidationRmse);
  // Cross-validated plants test every fold's training rows already (above).
  if (s.foldRss.empty()) applyRecordRule(c, current.trainResidual, s.trainResidual, dof, settings.alpha);
  const double inflate = calcStandardErrorInflation(static_cast<double>(s.samples), t.nEff);
  c.parameters = parametersWithIntervals(plant, s, id, inflate);
  c.informative = carriesInformation(plant, current, s, id, grid[best], t.lr, c.parameters, inflate);
  if (!c.informative) {
    // No interval: any value of the physical range fits these records as well as any other.
    for (auto& p : c.parameters) {
      p.lower = p.upper = std::numeric_limits<double>::quiet_NaN();
      p.intervalNote = kNoInformation;
    }
  } else if (!d.grid.empty()) {
    widenOverGridRegion(plant, fits, grid, best, t.nEff, id, inflate, c.parameters);
  }
  c.physical = plant.checkPhysical(*s.model, id, c.physicalNote);
  c.physicalNote += c.physical ? " (ok)" : " (wrong sign)";
  c.where = describeErrorFall(plant.phaseNames(*current.model), current, s);
  for (const auto& r : s.trainResidual) c.trainResidual.insert(c.trainResidual.end(), r.begin(), r.end());
  if (bestOut) *bestOut = s;
  return c;
}

}  // namespace swingsim
