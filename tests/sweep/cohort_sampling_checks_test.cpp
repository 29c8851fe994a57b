// A cohort distribution says what it draws: a truncated normal so wide that it is flat
// across its range (sd 1e20 drew every participant at the mean) or so narrow that every draw
// is the mean is refused at its sd with the reason; and a drawn leg keeps its knee unit's
// centre of mass above the ankle at every lowering its sweep reaches.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/input_error.h"
#include "model/leg_parameters.h"
#include "sweep/cohort_sampling.h"
#include "sweep/sweep.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

CohortDistribution statureNormal(double sd) {
  CohortDistribution d;
  d.kind = CohortDistribution::Kind::kNormal;
  d.min = 1.6;
  d.max = 1.9;
  d.mean = 1.75;
  d.sd = sd;
  d.source = "Huston 2009";
  return d;
}

TEST(CohortSamplingChecks, ASpreadThatFlattensTheTruncationIsRefused) {
  const CohortProperty& stature = cohortProperties()[findCohortProperty("stature_m")];
  // sd 1e20: both ends of the truncation round to the same CDF, so every draw was the mean.
  EXPECT_EQ(calcCohortValue(statureNormal(1e20), 0.1), calcCohortValue(statureNormal(1e20), 0.9));
  const CohortDistributionProblem problem = checkCohortDistribution(stature, statureNormal(1e20));
  EXPECT_EQ(problem.key, "sd");
  EXPECT_EQ(problem.found, "1e+20");
  EXPECT_THAT(problem.expected, HasSubstr("a standard deviation of at most 10 x (max - min) = 3"));
  EXPECT_THAT(problem.expected, HasSubstr("flat across [1.6, 1.9]"));
  EXPECT_THAT(problem.expected, HasSubstr("write distribution: uniform"));
  EXPECT_EQ(checkCohortDistribution(stature, statureNormal(3.01)).key, "sd");
  EXPECT_TRUE(checkCohortDistribution(stature, statureNormal(2.99)).key.empty());
}

TEST(CohortSamplingChecks, ASpreadThatCollapsesOntoTheMeanIsRefused) {
  const CohortProperty& stature = cohortProperties()[findCohortProperty("stature_m")];
  const CohortDistributionProblem problem = checkCohortDistribution(stature, statureNormal(1e-9));
  EXPECT_EQ(problem.key, "sd");
  EXPECT_THAT(problem.expected, HasSubstr("a standard deviation of at least 0.001 x (max - min) = 0.0003"));
  EXPECT_THAT(problem.expected, HasSubstr("draws every participant at the mean 1.75"));
  EXPECT_EQ(checkCohortDistribution(stature, statureNormal(0.000299)).key, "sd");
  EXPECT_TRUE(checkCohortDistribution(stature, statureNormal(0.000301)).key.empty());
}

// Mid-range values of every property, with the knee unit's COM far below its axis.
std::vector<double> deepKneeValues() {
  std::vector<double> v;
  for (const auto& p : cohortProperties()) v.push_back(0.5 * (p.physicalMin + p.physicalMax));
  v[findCohortProperty("stature_m")] = 1.5;  // shank 0.369 m
  v[findCohortProperty("knee_com_below_axis_m")] = 0.2;
  v[findCohortProperty("knee_mass_kg")] = 0.5;
  v[findCohortProperty("pylon_mass_kg")] = 2.5;  // the shank's COM stays high: the pylon's weight
  return v;
}

TEST(CohortSamplingChecks, NoLoweringPutsTheKneeUnitBelowTheAnkle) {
  Participant templ;
  templ.comRule = ComRule::kFixedFromProximal;
  const std::vector<double> v = deepKneeValues();
  const Participant p = makeCohortParticipant(templ, v, "C001");
  const double kneeComBelowAxis = v[findCohortProperty("knee_com_below_axis_m")];
  SweepStudy study;
  study.loweringStep = 0.01;
  study.loweringMax = 0.3;
  const std::vector<double> lowerings = sweepGridLowerings(study, p);
  ASSERT_FALSE(lowerings.empty());
  for (double d : lowerings) {
    const LegGeometry g = calcLegGeometry(p, d);
    EXPECT_LE(kneeComBelowAxis, g.shankLength + 1e-9) << "lowering " << d;
  }
  // The sweep stops at the last grid point before the knee unit's COM reaches the ankle.
  EXPECT_NEAR(lowerings.back(), std::floor((p.shank.length - kneeComBelowAxis) / 0.01 + 1e-9) * 0.01, 1e-9);
  EXPECT_THROW(calcLegGeometry(p, p.shank.length - kneeComBelowAxis + 0.01), InputError);
}

}  // namespace
}  // namespace swingsim
