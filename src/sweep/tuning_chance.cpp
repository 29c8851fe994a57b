#include "sweep/tuning_chance.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <tuple>

#include "core/text_format.h"
#include "sweep/sweep.h"
#include "sweep/sweep_assumptions.h"
#include "sweep/sweep_uncertainty.h"
#include "sweep/tuning_analysis.h"
#include "swing/knee_setup.h"

namespace swingsim {
namespace {

/// z of the two-sided 95 % normal interval.
constexpr double kZ95 = 1.959963984540054;

/// The tuned leg (`nominal`: its variant as loaded, `ranges` its assumptions' ranges) with
/// every assumption at its drawn value (`u` one fraction per entry of sweepAssumptions();
/// empty: every one at the files' value), as one swing.
SwingResult simulateDraw(const TunedLeg& leg, const SweepVariant& nominal, const std::vector<AssumptionRange>& ranges,
                         const std::vector<double>& u) {
  SweepVariant v = nominal;
  if (!u.empty()) applyAssumptionDraw(v, ranges, u);
  const auto knee = std::make_shared<const KneeLawSum>(makeSweepVariantKnee(v));
  const Participant adapted = calcAdaptedParticipant(v.participant, leg.lowering, v.hipEffortExponent);
  return simulateSwing(makeSwingSetup(adapted, knee, leg.lowering, leg.added), v.swing);
}

std::string describeChance(const TuningChance& c, const std::vector<TuningTarget>& targets) {
  const int n = c.options.samples;
  std::string out = fmt("meets every hard limit in %d of %d samples: %.0f %% (95 %% CI %.0f-%.0f %%)", c.met, n,
                        100 * c.chance(), 100 * c.low, 100 * c.high);
  std::size_t worst = targets.size();
  for (std::size_t t = 0; t < targets.size(); ++t)
    if (c.misses[t] > 0 && (worst == targets.size() || c.misses[t] > c.misses[worst])) worst = t;
  if (worst < targets.size())
    out += fmt("; missed most: %s (%d samples)", tuningQuantityKey(targets[worst].quantity), c.misses[worst]);
  if (c.failed > 0) out += fmt("; %d samples did not run", c.failed);
  return out;
}

}  // namespace

std::pair<double, double> calcWilsonInterval(int k, int n) {
  if (n <= 0) return {0, 1};
  const double p = double(k) / n, z2 = kZ95 * kZ95;
  const double centre = (p + z2 / (2 * n)) / (1 + z2 / n);
  const double half = kZ95 * std::sqrt(p * (1 - p) / n + z2 / (4.0 * n * n)) / (1 + z2 / n);
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

TuningChance calcTuningChance(const TunedLeg& leg, const std::vector<TuningTarget>& targets,
                              const TuningChanceOptions& options, int jobs, const volatile bool* stop) {
  TuningChance c;
  c.options = options;
  c.misses.assign(targets.size(), 0);
  if (options.samples <= 0) return c;
  const std::vector<std::vector<double>> draws = drawUncertaintySamples(options.samples, options.seed);
  SweepVariant nominal;
  nominal.participant = leg.participant;
  nominal.knee = leg.knee;
  nominal.swing = leg.options;
  const std::vector<AssumptionRange> ranges = calcAssumptionRanges(nominal);
  // Job 0 is the nominal draw; job s + 1 the s-th sample.
  std::vector<TuningPoint> points(draws.size() + 1);
  const int ran = runParallelJobs(
      static_cast<int>(points.size()), jobs,
      [&](int j) {
        const std::vector<double> u = j == 0 ? std::vector<double>{} : draws[static_cast<std::size_t>(j - 1)];
        points[static_cast<std::size_t>(j)] = evaluateTuningPoint(
            {}, targets, [&](const std::vector<double>&) { return simulateDraw(leg, nominal, ranges, u); });
      },
      {}, stop);
  if (ran < static_cast<int>(points.size()) || (stop != nullptr && *stop)) return c;
  c.nominalSwingTime = points.front().swingTime;
  for (std::size_t s = 1; s < points.size(); ++s) {
    const TuningPoint& p = points[s];
    if (!p.ran) {
      ++c.failed;
      continue;
    }
    if (p.feasible()) ++c.met;
    for (std::size_t t = 0; t < targets.size(); ++t)
      if (targets[t].hard && calcTargetMiss(targets[t], p.value(targets[t].quantity)) != 0) ++c.misses[t];
  }
  std::tie(c.low, c.high) = calcWilsonInterval(c.met, options.samples);
  c.ran = true;
  c.verdict = describeChance(c, targets);
  return c;
}

}  // namespace swingsim
