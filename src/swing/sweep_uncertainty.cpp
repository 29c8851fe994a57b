#include "swing/sweep_uncertainty.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>

#include "core/input_error.h"

namespace swingsim {

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();
constexpr double kSameSwingTime = 1e-12;  // s: a later lowering must be faster than this to win (as runSweep)

/// One participant's lowering sweep under one set of assumption values, ready to run.
struct Scenario {
  SweepVariant variant;
  KneeLawSum knee;
  LoweringSweepSummary summary;
};

struct Job {
  std::size_t scenario;
  std::size_t lowering;
};

// The study's on-grid lowerings for a participant (no Table 4 extras: they are never the
// "fastest" in runSweep either).
std::vector<double> gridLowerings(const SweepStudy& study, const Participant& p) {
  SweepStudy grid;
  grid.loweringStep = study.loweringStep;
  grid.loweringMax = study.loweringMax;
  grid.includePublishedLowerings = false;
  return sweepLowerings(grid, p);
}

void pickBest(LoweringSweepSummary& s) {
  s.best = -1;
  for (std::size_t k = 0; k < s.swingTimes.size(); ++k) {
    if (!std::isfinite(s.swingTimes[k])) continue;
    if (s.best < 0 || s.swingTimes[k] < s.swingTimes[static_cast<std::size_t>(s.best)] - kSameSwingTime)
      s.best = static_cast<int>(k);
  }
}

double percentileSorted(const std::vector<double>& v, double q) {
  const double h = q * static_cast<double>(v.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (h - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

}  // namespace

double LoweringSweepSummary::calcFastestLowering() const {
  return best >= 0 ? lowerings[static_cast<std::size_t>(best)] : kNaN;
}

double LoweringSweepSummary::calcFastestTime() const {
  return best >= 0 ? swingTimes[static_cast<std::size_t>(best)] : kNaN;
}

double SensitivityRow::calcLoweringEffect() const {
  const double d = std::fabs(high.calcFastestLowering() - low.calcFastestLowering());
  return std::isfinite(d) ? d : kInf;
}

double SensitivityRow::calcTimeEffect() const {
  const double d = std::fabs(high.calcFastestTime() - low.calcFastestTime());
  return std::isfinite(d) ? d : kInf;
}

Interval calcInterval(std::vector<double> values) {
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }), values.end());
  Interval out;
  out.count = static_cast<int>(values.size());
  if (values.empty()) {
    out.median = out.p05 = out.p95 = kNaN;
    return out;
  }
  std::sort(values.begin(), values.end());
  out.median = percentileSorted(values, 0.50);
  out.p05 = percentileSorted(values, 0.05);
  out.p95 = percentileSorted(values, 0.95);
  return out;
}

std::vector<std::vector<double>> drawUncertaintySamples(int samples, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  const std::size_t n = sweepAssumptions().size();
  std::vector<std::vector<double>> draws(static_cast<std::size_t>(std::max(0, samples)), std::vector<double>(n));
  // 53 random bits -> [0, 1): std::uniform_real_distribution's algorithm is the library's
  // choice, this is the same everywhere.
  for (auto& sample : draws)
    for (double& u : sample) u = static_cast<double>(engine() >> 11) * 0x1.0p-53;
  return draws;
}

SweepVariant makeNominalVariant(const SweepStudy& study, const Participant& participant) {
  SweepVariant v;
  v.participant = participant;
  v.knee = findStudyKneeModel(study, participant);
  v.swing = study.swing;
  v.swing.recordTrajectory = false;
  return v;
}

UncertaintyResults runSweepUncertainty(const SweepStudy& study, const UncertaintyOptions& options, int jobs,
                                       const std::function<void(int, int)>& progress,
                                       const volatile bool* stopFlag) {
  const auto& table = sweepAssumptions();
  UncertaintyResults results;
  results.samples = options.samples;
  results.seed = options.seed;
  results.draws = drawUncertaintySamples(options.samples, options.seed);

  // Scenarios, per participant: the nominal one, then low and high of each applicable
  // assumption (sensitivity), then the samples. Indices are remembered to read results back.
  std::vector<Scenario> scenarios;
  struct ParticipantIndex {
    std::size_t nominal = 0;
    std::vector<std::pair<std::size_t, std::size_t>> oat;  // assumption -> (low scenario, high scenario); unused if n/a
    std::vector<bool> applicable;
    std::vector<AssumptionRange> ranges;
    std::vector<std::size_t> samples;
  };
  std::vector<ParticipantIndex> index(study.participants.size());
  auto addScenario = [&](SweepVariant variant) {
    Scenario s;
    s.summary.lowerings = gridLowerings(study, variant.participant);
    s.summary.swingTimes.assign(s.summary.lowerings.size(), kNaN);
    try {
      s.knee = makeSweepVariantKnee(variant);
    } catch (const std::invalid_argument& e) {
      throw RunError("sweep " + study.name + ": participant " + variant.participant.name +
                     ": an assumption's value makes an unusable knee law: " + e.what());
    }
    s.variant = std::move(variant);
    scenarios.push_back(std::move(s));
    return scenarios.size() - 1;
  };
  for (std::size_t i = 0; i < study.participants.size(); ++i) {
    const SweepVariant nominal = makeNominalVariant(study, study.participants[i]);
    ParticipantIndex& pi = index[i];
    pi.nominal = addScenario(nominal);
    for (const auto& a : table) {
      pi.ranges.push_back(a.calcRange(nominal));
      pi.applicable.push_back(pi.ranges.back().applicable);
      pi.oat.emplace_back(0, 0);
      if (!options.sensitivity || !pi.ranges.back().applicable) continue;
      SweepVariant low = nominal, high = nominal;
      a.apply(low, pi.ranges.back().low);
      a.apply(high, pi.ranges.back().high);
      pi.oat.back() = {addScenario(std::move(low)), addScenario(std::move(high))};
    }
    for (const auto& draw : results.draws) {
      SweepVariant v = nominal;
      for (std::size_t k = 0; k < table.size(); ++k)
        table[k].apply(v, calcAssumptionValue(table[k], pi.ranges[k], draw[k]));
      pi.samples.push_back(addScenario(std::move(v)));
    }
  }

  std::vector<Job> work;
  for (std::size_t s = 0; s < scenarios.size(); ++s)
    for (std::size_t k = 0; k < scenarios[s].summary.lowerings.size(); ++k) work.push_back({s, k});

  const int total = static_cast<int>(work.size());
  auto runOne = [&](const Job& job) {
    Scenario& sc = scenarios[job.scenario];
    const double lowering = sc.summary.lowerings[job.lowering];
    try {
      SwingSetup setup;
      setup.participant = calcAdaptedParticipant(sc.variant.participant, lowering, sc.variant.hipEffortExponent);
      setup.knee = &sc.knee;
      setup.lowering = lowering;
      sc.summary.swingTimes[job.lowering] = simulateSwing(setup, sc.variant.swing).swingTime;
    } catch (const std::exception&) {
      // No swing end at this lowering under these assumptions (the thigh short of its
      // target, a time limit): the point drops out of the fastest-lowering search, as in runSweep.
    }
  };
  const int done = runParallelJobs(total, jobs, [&](int k) { runOne(work[static_cast<std::size_t>(k)]); }, progress, stopFlag);
  results.interrupted = done < total;

  for (auto& sc : scenarios) pickBest(sc.summary);
  for (std::size_t i = 0; i < study.participants.size(); ++i) {
    const ParticipantIndex& pi = index[i];
    ParticipantUncertainty pu;
    pu.name = study.participants[i].name;
    pu.nominal = scenarios[pi.nominal].summary;
    for (std::size_t k = 0; k < table.size(); ++k) {
      if (!options.sensitivity || !pi.applicable[k]) continue;
      SensitivityRow row;
      row.assumption = table[k].key;
      row.name = table[k].name;
      row.unit = table[k].unit;
      row.lowValue = pi.ranges[k].low;
      row.highValue = pi.ranges[k].high;
      row.low = scenarios[pi.oat[k].first].summary;
      row.high = scenarios[pi.oat[k].second].summary;
      pu.sensitivity.push_back(std::move(row));
    }
    // Largest change of the fastest lowering first; ties (most often "no change") by the
    // change of its swing time. Stable, so equal rows keep the table order.
    std::stable_sort(pu.sensitivity.begin(), pu.sensitivity.end(), [](const SensitivityRow& a, const SensitivityRow& b) {
      if (a.calcLoweringEffect() != b.calcLoweringEffect()) return a.calcLoweringEffect() > b.calcLoweringEffect();
      return a.calcTimeEffect() > b.calcTimeEffect();
    });
    std::vector<double> fastestLowering, fastestTime;
    for (std::size_t s : pi.samples) {
      pu.samples.push_back(scenarios[s].summary);
      fastestLowering.push_back(scenarios[s].summary.calcFastestLowering());
      fastestTime.push_back(scenarios[s].summary.calcFastestTime());
      if (scenarios[s].summary.best < 0) ++pu.samplesWithoutSwingEnd;
    }
    pu.fastestLowering = calcInterval(fastestLowering);
    pu.fastestTime = calcInterval(fastestTime);
    // The band: per lowering of the nominal grid, over the samples that reached it.
    for (std::size_t k = 0; k < pu.nominal.lowerings.size(); ++k) {
      const double d = pu.nominal.lowerings[k];
      std::vector<double> times;
      for (const auto& s : pu.samples)
        for (std::size_t j = 0; j < s.lowerings.size(); ++j)
          if (std::fabs(s.lowerings[j] - d) < 1e-9 && std::isfinite(s.swingTimes[j])) times.push_back(s.swingTimes[j]);
      const bool enough = !pu.samples.empty() && 2 * times.size() >= pu.samples.size();
      const Interval band = calcInterval(times);
      pu.bandLowerings.push_back(d);
      pu.bandP05.push_back(enough ? band.p05 : kNaN);
      pu.bandMedian.push_back(enough ? band.median : kNaN);
      pu.bandP95.push_back(enough ? band.p95 : kNaN);
    }
    results.participants.push_back(std::move(pu));
  }
  return results;
}

}  // namespace swingsim
