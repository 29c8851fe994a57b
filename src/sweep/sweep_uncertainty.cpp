#include "sweep/sweep_uncertainty.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>

#include "core/input_error.h"
#include "sweep/swing_time_jumps.h"
#include "swing/knee_setup.h"

namespace swingsim {

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();
constexpr double kSameSwingTime = 1e-12;  // s: a later lowering must be faster than this to win (as runSweep)

double percentileSorted(const std::vector<double>& v, double q) {
  const double h = q * static_cast<double>(v.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (h - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

// The nominal symmetry lowering and its interval over the samples (no sound-limb time: none).
// Each curve is kept as times only, so a step beyond the jump screen is taken for a jump
// (calcScreenedPieces): a sample whose sound-limb time falls in one does not reach it.
void addSymmetry(ParticipantUncertainty& pu, double soundTime) {
  pu.symmetry = calcSymmetryLowering(pu.nominal.lowerings, pu.nominal.swingTimes, soundTime,
                                     calcScreenedPieces(pu.nominal.swingTimes));
  if (!pu.symmetry.given) return;
  std::vector<double> lowerings;
  for (const auto& s : pu.samples) {
    const SymmetryLowering sample =
        calcSymmetryLowering(s.lowerings, s.swingTimes, soundTime, calcScreenedPieces(s.swingTimes));
    if (!sample.found) continue;  // counted in samplesWithoutSwingEnd
    lowerings.push_back(sample.lowering);
    if (!sample.reached) ++pu.symmetryNotReached;
  }
  pu.symmetryLowering = calcInterval(lowerings);
}

}  // namespace

void pickBest(LoweringSweepSummary& s) {
  s.best = -1;
  for (std::size_t k = 0; k < s.swingTimes.size(); ++k) {
    if (!std::isfinite(s.swingTimes[k])) continue;
    if (s.best < 0 || s.swingTimes[k] < s.swingTimes[static_cast<std::size_t>(s.best)] - kSameSwingTime)
      s.best = static_cast<int>(k);
  }
}

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

SweepVariant UncertaintyPlan::makeVariant(const UncertaintyRun& run) const {
  const auto& table = sweepAssumptions();
  const std::vector<AssumptionRange>& range = ranges[run.participant];
  SweepVariant v = nominals[run.participant];
  switch (run.kind) {
    case UncertaintyRun::Kind::kNominal:
      break;
    case UncertaintyRun::Kind::kLow:
      table[run.assumption].apply(v, range[run.assumption].low);
      break;
    case UncertaintyRun::Kind::kHigh:
      table[run.assumption].apply(v, range[run.assumption].high);
      break;
    case UncertaintyRun::Kind::kSample:
      applyAssumptionDraw(v, range, draws[run.sample]);
      break;
  }
  return v;
}

const UncertaintyRun& UncertaintyPlan::findRun(std::size_t swing) const {
  // The last run starting at or before `swing` (runs with no lowerings share a start).
  auto it = std::upper_bound(runs.begin(), runs.end(), swing,
                             [](std::size_t s, const UncertaintyRun& r) { return s < r.firstSwing; });
  while (it != runs.begin() && (it - 1)->lowerings.empty()) --it;
  return *(it - 1);
}

SwingSetup PlannedSwing::makeSetup() const { return makeSwingSetup(participant, knee, lowering); }

PlannedSwing UncertaintyPlan::makeSwing(std::size_t swing) const {
  PlannedSwing planned;
  planned.run = &findRun(swing);
  planned.lowering = planned.run->lowerings[swing - planned.run->firstSwing];
  planned.variant = makeVariant(*planned.run);
  planned.knee = std::make_shared<const KneeLawSum>(makeSweepVariantKnee(planned.variant));
  planned.participant =
      calcAdaptedParticipant(planned.variant.participant, planned.lowering, planned.variant.hipEffortExponent);
  return planned;
}

UncertaintyPlan planSweepUncertainty(const SweepStudy& study, const UncertaintyOptions& options) {
  const auto& table = sweepAssumptions();
  UncertaintyPlan plan;
  plan.options = options;
  plan.draws = drawUncertaintySamples(options.samples, options.seed);
  auto addRun = [&](UncertaintyRun run) {
    const SweepVariant variant = plan.makeVariant(run);
    try {
      (void)makeSweepVariantKnee(variant);  // built again per swing; checked here, before any runs
    } catch (const std::invalid_argument& e) {
      throw RunError("sweep " + study.name + ": participant " + variant.participant.name +
                     ": an assumption's value makes an unusable knee law: " + e.what());
    }
    run.lowerings = sweepGridLowerings(study, variant.participant);
    run.firstSwing = plan.swingCount;
    plan.swingCount += run.lowerings.size();
    plan.runs.push_back(std::move(run));
  };
  using Kind = UncertaintyRun::Kind;
  for (std::size_t i = 0; i < study.participants.size(); ++i) {
    plan.nominals.push_back(makeNominalVariant(study, study.participants[i]));
    plan.ranges.push_back(calcAssumptionRanges(plan.nominals.back()));
  }
  for (std::size_t i = 0; i < study.participants.size(); ++i) {
    addRun({i, Kind::kNominal, 0, 0, {}, 0});
    if (!options.sensitivity) continue;
    for (std::size_t k = 0; k < table.size(); ++k) {
      if (!plan.ranges[i][k].applicable) continue;
      addRun({i, Kind::kLow, k, 0, {}, 0});
      addRun({i, Kind::kHigh, k, 0, {}, 0});
    }
  }
  plan.sensitivitySwings = plan.swingCount;
  for (std::size_t s = 0; s < plan.draws.size(); ++s)
    for (std::size_t i = 0; i < study.participants.size(); ++i) addRun({i, Kind::kSample, 0, s, {}, 0});
  return plan;
}

UncertaintySwingTimes UncertaintySwingTimes::makeEmpty(std::size_t count) {
  UncertaintySwingTimes t;
  t.swingTimes.assign(count, kNaN);
  t.finished.assign(count, 0);
  return t;
}

std::size_t UncertaintySwingTimes::countFinished() const {
  return static_cast<std::size_t>(std::count(finished.begin(), finished.end(), 1));
}

std::pair<std::size_t, std::size_t> calcShardSwings(std::size_t count, int index, int shards) {
  const auto bound = [&](int k) {
    return static_cast<std::size_t>(static_cast<unsigned long long>(count) * static_cast<unsigned>(k) /
                                    static_cast<unsigned>(shards));
  };
  return {bound(index), bound(index + 1)};
}

bool runUncertaintySwings(const UncertaintyPlan& plan, std::size_t first, std::size_t last,
                          UncertaintySwingTimes& times, int jobs, const UncertaintyRunControl& control) {
  std::vector<std::size_t> todo;
  for (std::size_t s = first; s < last; ++s)
    if (!times.finished[s]) todo.push_back(s);
  // Stops when the caller's flag is set or after control.stopAfterSwings swings.
  volatile bool stop = false;
  std::atomic<long> finishedHere{0};
  auto runOne = [&](int k) {
    const std::size_t swing = todo[static_cast<std::size_t>(k)];
    double swingTime = kNaN;
    try {
      const PlannedSwing planned = plan.makeSwing(swing);
      swingTime = simulateSwing(planned.makeSetup(), planned.variant.swing).swingTime;
    } catch (const std::exception&) {
      // No swing end at this lowering under these assumptions (the thigh short of its
      // target, a time limit): the point drops out of the fastest-lowering search, as in runSweep.
    }
    times.swingTimes[swing] = swingTime;
    times.finished[swing] = 1;
    const long n = finishedHere.fetch_add(1) + 1;
    if ((control.stopAfterSwings >= 0 && n >= control.stopAfterSwings) || (control.stopFlag && *control.stopFlag))
      stop = true;
  };
  auto progress = [&](int done, int total) {
    if (control.stopFlag && *control.stopFlag) stop = true;
    if (control.progress) control.progress(done, total);
  };
  const int total = static_cast<int>(todo.size());
  const int done = runParallelJobs(total, jobs, runOne, progress, &stop);
  return done == total;
}

int countFinishedSamples(const UncertaintyPlan& plan, const UncertaintySwingTimes& times) {
  std::vector<char> complete(plan.draws.size(), 1);
  for (const auto& run : plan.runs) {
    if (run.kind != UncertaintyRun::Kind::kSample) continue;
    for (std::size_t k = 0; k < run.lowerings.size(); ++k)
      if (!times.finished[run.firstSwing + k]) complete[run.sample] = 0;
  }
  return static_cast<int>(std::count(complete.begin(), complete.end(), 1));
}

UncertaintyResults assembleUncertaintyResults(const SweepStudy& study, const UncertaintyPlan& plan,
                                              const UncertaintySwingTimes& times) {
  const auto& table = sweepAssumptions();
  UncertaintyResults results;
  results.samples = plan.options.samples;
  results.seed = plan.options.seed;
  results.draws = plan.draws;
  results.interrupted = times.countFinished() < plan.swingCount;

  auto summaryOf = [&](const UncertaintyRun& run) {
    LoweringSweepSummary s;
    s.lowerings = run.lowerings;
    s.swingTimes.assign(times.swingTimes.begin() + static_cast<std::ptrdiff_t>(run.firstSwing),
                        times.swingTimes.begin() + static_cast<std::ptrdiff_t>(run.firstSwing + run.lowerings.size()));
    pickBest(s);
    return s;
  };
  using Kind = UncertaintyRun::Kind;
  for (std::size_t i = 0; i < study.participants.size(); ++i) {
    ParticipantUncertainty pu;
    pu.name = study.participants[i].name;
    std::vector<const UncertaintyRun*> low(table.size(), nullptr), high(table.size(), nullptr);
    for (const auto& run : plan.runs) {
      if (run.participant != i) continue;
      if (run.kind == Kind::kNominal) pu.nominal = summaryOf(run);
      if (run.kind == Kind::kLow) low[run.assumption] = &run;
      if (run.kind == Kind::kHigh) high[run.assumption] = &run;
      if (run.kind == Kind::kSample) pu.samples.push_back(summaryOf(run));  // runs are in sample order
    }
    for (std::size_t k = 0; k < table.size(); ++k) {
      if (!low[k] || !high[k]) continue;
      SensitivityRow row;
      row.assumption = table[k].key;
      row.name = table[k].name;
      row.unit = table[k].unit;
      row.lowValue = plan.ranges[i][k].low;
      row.highValue = plan.ranges[i][k].high;
      row.low = summaryOf(*low[k]);
      row.high = summaryOf(*high[k]);
      pu.sensitivity.push_back(std::move(row));
    }
    // Largest change of the fastest lowering first; ties (most often "no change") by the
    // change of its swing time. Stable, so equal rows keep the table order.
    std::stable_sort(pu.sensitivity.begin(), pu.sensitivity.end(),
                     [](const SensitivityRow& a, const SensitivityRow& b) {
                       if (a.calcLoweringEffect() != b.calcLoweringEffect())
                         return a.calcLoweringEffect() > b.calcLoweringEffect();
                       return a.calcTimeEffect() > b.calcTimeEffect();
                     });
    std::vector<double> fastestLowering, fastestTime;
    for (const auto& s : pu.samples) {
      fastestLowering.push_back(s.calcFastestLowering());
      fastestTime.push_back(s.calcFastestTime());
      if (s.best < 0) ++pu.samplesWithoutSwingEnd;
    }
    pu.fastestLowering = calcInterval(fastestLowering);
    pu.fastestTime = calcInterval(fastestTime);
    addSymmetry(pu, study.participants[i].soundLimbSwingTime.value_or(0));
    // The band: per lowering of the nominal grid, over the samples that reached it.
    for (std::size_t k = 0; k < pu.nominal.lowerings.size(); ++k) {
      const double d = pu.nominal.lowerings[k];
      std::vector<double> bandTimes;
      for (const auto& s : pu.samples)
        for (std::size_t j = 0; j < s.lowerings.size(); ++j)
          if (std::fabs(s.lowerings[j] - d) < 1e-9 && std::isfinite(s.swingTimes[j]))
            bandTimes.push_back(s.swingTimes[j]);
      const bool enough = !pu.samples.empty() && 2 * bandTimes.size() >= pu.samples.size();
      const Interval band = calcInterval(bandTimes);
      pu.bandLowerings.push_back(d);
      pu.bandP05.push_back(enough ? band.p05 : kNaN);
      pu.bandMedian.push_back(enough ? band.median : kNaN);
      pu.bandP95.push_back(enough ? band.p95 : kNaN);
    }
    results.participants.push_back(std::move(pu));
  }
  return results;
}

UncertaintyResults runSweepUncertainty(const SweepStudy& study, const UncertaintyOptions& options, int jobs,
                                       const std::function<void(int, int)>& progress, const volatile bool* stopFlag) {
  const UncertaintyPlan plan = planSweepUncertainty(study, options);
  UncertaintySwingTimes times = UncertaintySwingTimes::makeEmpty(plan.swingCount);
  UncertaintyRunControl control;
  control.progress = progress;
  control.stopFlag = stopFlag;
  runUncertaintySwings(plan, 0, plan.swingCount, times, jobs, control);
  return assembleUncertaintyResults(study, plan, times);
}

}  // namespace swingsim
