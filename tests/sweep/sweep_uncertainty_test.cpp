// How sure is the optimum (docs/uncertainty.md): the Monte Carlo is reproducible from its seed
// whatever the thread count, the sensitivity is sorted by effect, and the nominal run is
// the plain sweep. Small on purpose: one participant, a 50 mm grid, a few samples.
#include "sweep/sweep_uncertainty.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "study/sweep_study.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;

SweepStudy smallStudy() {
  SweepStudy s = loadSweepStudy(kRoot + "/studies/burkett2004.yaml");
  s.participants.resize(1);  // P1
  s.loweringStep = 0.05;
  s.includePublishedLowerings = false;
  s.addedMasses = {0.0};
  s.addedMassDistances.clear();
  return s;
}

// NaN-aware equality: two runs agree when every swing time is bit-identical or both NaN.
void expectSameSummaries(const LoweringSweepSummary& a, const LoweringSweepSummary& b, const std::string& what) {
  ASSERT_EQ(a.lowerings, b.lowerings) << what;
  ASSERT_EQ(a.swingTimes.size(), b.swingTimes.size()) << what;
  for (std::size_t k = 0; k < a.swingTimes.size(); ++k) {
    if (std::isnan(a.swingTimes[k]))
      EXPECT_TRUE(std::isnan(b.swingTimes[k])) << what << " lowering " << a.lowerings[k];
    else
      EXPECT_EQ(a.swingTimes[k], b.swingTimes[k]) << what << " lowering " << a.lowerings[k];
  }
  EXPECT_EQ(a.best, b.best) << what;
}

TEST(SweepUncertainty, DrawsComeFromTheSeed) {
  const auto a = drawUncertaintySamples(4, 7), b = drawUncertaintySamples(4, 7), c = drawUncertaintySamples(4, 8);
  ASSERT_EQ(a.size(), 4u);
  ASSERT_EQ(a[0].size(), sweepAssumptions().size());
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  for (const auto& sample : a)
    for (double u : sample) {
      EXPECT_GE(u, 0.0);
      EXPECT_LT(u, 1.0);
    }
  // More samples extend the same stream: the first four draws do not depend on N.
  const auto longer = drawUncertaintySamples(6, 7);
  EXPECT_EQ(std::vector<std::vector<double>>(longer.begin(), longer.begin() + 4), a);
}

TEST(SweepUncertainty, SameSeedSameResultsWhateverTheThreadCount) {
  const SweepStudy s = smallStudy();
  UncertaintyOptions o;
  o.samples = 3;
  o.seed = 11;
  o.sensitivity = false;
  const UncertaintyResults one = runSweepUncertainty(s, o, 1);
  const UncertaintyResults two = runSweepUncertainty(s, o, 2);
  EXPECT_FALSE(one.interrupted);
  EXPECT_EQ(one.draws, two.draws);
  ASSERT_EQ(one.participants.size(), 1u);
  ASSERT_EQ(one.participants[0].samples.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k)
    expectSameSummaries(one.participants[0].samples[k], two.participants[0].samples[k], "sample " + std::to_string(k));
  EXPECT_EQ(one.participants[0].fastestLowering.median, two.participants[0].fastestLowering.median);
  EXPECT_EQ(one.participants[0].fastestTime.p95, two.participants[0].fastestTime.p95);

  // Another seed draws other assumption values, so other swing times.
  o.seed = 12;
  const UncertaintyResults other = runSweepUncertainty(s, o, 2);
  EXPECT_NE(other.draws, one.draws);
  EXPECT_NE(other.participants[0].samples[0].swingTimes, one.participants[0].samples[0].swingTimes);
}

// The nominal run is the plain sweep's grid with every assumption at the files' value: the
// same fastest lowering and swing time as runSweep.
TEST(SweepUncertainty, NominalIsThePlainSweep) {
  const SweepStudy s = smallStudy();
  const SweepResults plain = runSweep(s, 2);
  UncertaintyOptions o;
  o.samples = 0;
  o.sensitivity = false;
  const UncertaintyResults u = runSweepUncertainty(s, o, 2);
  const auto& ps = plain.participants[0];
  ASSERT_GE(ps.best, 0);
  EXPECT_EQ(u.participants[0].nominal.calcFastestLowering(), ps.points[static_cast<std::size_t>(ps.best)].lowering);
  EXPECT_EQ(u.participants[0].nominal.calcFastestTime(), ps.points[static_cast<std::size_t>(ps.best)].result.swingTime);
}

TEST(SweepUncertainty, SensitivityIsSortedByEffectAndCoversEveryAssumption) {
  const SweepStudy s = smallStudy();
  UncertaintyOptions o;
  o.samples = 0;
  const UncertaintyResults u = runSweepUncertainty(s, o, 0);
  const auto& rows = u.participants[0].sensitivity;
  ASSERT_EQ(rows.size(), sweepAssumptions().size());
  for (std::size_t k = 1; k < rows.size(); ++k) {
    const double before = rows[k - 1].calcLoweringEffect(), now = rows[k].calcLoweringEffect();
    EXPECT_GE(before, now) << rows[k - 1].assumption << " before " << rows[k].assumption;
    if (before == now) {
      EXPECT_GE(rows[k - 1].calcTimeEffect(), rows[k].calcTimeEffect()) << rows[k].assumption;
    }
  }
  // The hip time scale drives the whole swing: its two ends give different swing times.
  for (const auto& r : rows)
    if (r.assumption == "hip_time_scale") {
      EXPECT_LT(r.lowValue, r.highValue);
      EXPECT_GT(r.calcTimeEffect(), 0.0);
    }
}

TEST(SweepUncertainty, IntervalIsTheFivetoNinetyFivePercentRange) {
  std::vector<double> v;
  for (int i = 0; i <= 100; ++i) v.push_back(i);  // 0..100: percentiles are the values themselves
  v.push_back(std::nan(""));                      // ignored
  const Interval i = calcInterval(v);
  EXPECT_EQ(i.count, 101);
  EXPECT_DOUBLE_EQ(i.median, 50);
  EXPECT_DOUBLE_EQ(i.p05, 5);
  EXPECT_DOUBLE_EQ(i.p95, 95);
  EXPECT_TRUE(std::isnan(calcInterval({}).median));
}

}  // namespace
}  // namespace swingsim

namespace swingsim {
namespace {

// Shards are contiguous slices of the swing order that tile it, sizes within one.
TEST(UncertaintyPlanSlices, ShardsTileTheSwings) {
  for (std::size_t count : {0u, 1u, 7u, 81u, 84000u})
    for (int shards : {1, 2, 3, 7, 100}) {
      std::size_t next = 0, smallest = count, largest = 0;
      for (int k = 0; k < shards; ++k) {
        const auto [first, last] = calcShardSwings(count, k, shards);
        EXPECT_EQ(first, next) << count << " in " << shards;
        ASSERT_GE(last, first);
        smallest = std::min(smallest, last - first);
        largest = std::max(largest, last - first);
        next = last;
      }
      EXPECT_EQ(next, count) << count << " in " << shards;
      EXPECT_LE(largest - smallest, 1u) << count << " in " << shards;
    }
}

// The plan's order: the one-at-a-time runs first, then the samples one by one; swings run in
// any slices, in any order, stopped and resumed, give the one-go run's results bit for bit.
TEST(UncertaintyPlanSlices, SlicesStoppedAndResumedGiveTheOneGoResults) {
  SweepStudy s = smallStudy();
  s.loweringMax = 0.10;  // 0, 0.05, 0.10 m
  UncertaintyOptions o;
  o.samples = 2;
  o.seed = 5;
  const UncertaintyPlan plan = planSweepUncertainty(s, o);
  ASSERT_GT(plan.sensitivitySwings, 0u);
  ASSERT_LT(plan.sensitivitySwings, plan.swingCount);
  EXPECT_EQ(plan.runs.back().kind, UncertaintyRun::Kind::kSample);
  EXPECT_EQ(plan.runs.back().sample, 1u);
  for (std::size_t k = 0; k < plan.swingCount; ++k) {
    const UncertaintyRun& run = plan.findRun(k);
    ASSERT_GE(k, run.firstSwing);
    ASSERT_LT(k, run.firstSwing + run.lowerings.size());
  }

  const UncertaintyResults oneGo = runSweepUncertainty(s, o, 2);
  ASSERT_FALSE(oneGo.interrupted);

  UncertaintySwingTimes times = UncertaintySwingTimes::makeEmpty(plan.swingCount);
  const auto [first, last] = calcShardSwings(plan.swingCount, 1, 2);
  // The second half first, stopped after 5 swings, then resumed; then the first half.
  UncertaintyRunControl stopEarly;
  stopEarly.stopAfterSwings = 5;
  EXPECT_FALSE(runUncertaintySwings(plan, first, last, times, 1, stopEarly));
  EXPECT_EQ(times.countFinished(), 5u);
  EXPECT_EQ(countFinishedSamples(plan, times), 0);
  EXPECT_TRUE(assembleUncertaintyResults(s, plan, times).interrupted);
  EXPECT_TRUE(runUncertaintySwings(plan, first, last, times, 2));
  EXPECT_EQ(times.countFinished(), last - first);
  EXPECT_TRUE(runUncertaintySwings(plan, 0, first, times, 2));
  EXPECT_EQ(countFinishedSamples(plan, times), 2);

  const UncertaintyResults pieced = assembleUncertaintyResults(s, plan, times);
  ASSERT_FALSE(pieced.interrupted);
  const auto& a = oneGo.participants[0];
  const auto& b = pieced.participants[0];
  expectSameSummaries(a.nominal, b.nominal, "nominal");
  ASSERT_EQ(a.sensitivity.size(), b.sensitivity.size());
  for (std::size_t k = 0; k < a.sensitivity.size(); ++k) {
    EXPECT_EQ(a.sensitivity[k].assumption, b.sensitivity[k].assumption);
    expectSameSummaries(a.sensitivity[k].low, b.sensitivity[k].low, a.sensitivity[k].assumption + " low");
    expectSameSummaries(a.sensitivity[k].high, b.sensitivity[k].high, a.sensitivity[k].assumption + " high");
  }
  ASSERT_EQ(a.samples.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) expectSameSummaries(a.samples[k], b.samples[k], "sample " + std::to_string(k));
  EXPECT_EQ(a.fastestTime.median, b.fastestTime.median);
}

}  // namespace
}  // namespace swingsim
