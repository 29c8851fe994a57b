// Cohort sampling: reproducible with a seed, every drawn value inside its range, a truncated
// normal that is still a normal inside its range, and a drawn leg that adds up (segment
// masses and the shank's centre of mass recomputed here by hand).
#include "sweep/cohort_sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/input_error.h"

namespace swingsim {
namespace {

constexpr double kRound = 1e-12;  // closed-form sums: rounding only

std::vector<CohortDistribution> wideDistributions() {
  std::vector<CohortDistribution> out;
  for (const auto& p : cohortProperties()) {
    CohortDistribution d;
    const double span = p.physicalMax - p.physicalMin;
    d.min = p.physicalMin + 0.25 * span;
    d.max = p.physicalMin + 0.45 * span;
    d.source = "test";
    if (out.size() % 2 == 0) {  // every other one a truncated normal, its mean off-centre
      d.kind = CohortDistribution::Kind::kNormal;
      d.mean = d.min + 0.3 * (d.max - d.min);
      d.sd = 0.5 * (d.max - d.min);
    }
    out.push_back(d);
  }
  return out;
}

TEST(CohortSampling, SameSeedSameCohortOtherSeedAnother) {
  const auto d = wideDistributions();
  const auto a = drawCohort(d, 50, 7), b = drawCohort(d, 50, 7), c = drawCohort(d, 50, 8);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  // Participant i depends only on the seed and i: a larger cohort starts with the same ones.
  const auto longer = drawCohort(d, 80, 7);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], longer[i]) << "participant " << i;
}

TEST(CohortSampling, EveryValueInsideItsRange) {
  const auto d = wideDistributions();
  const auto values = drawCohort(d, 2000, 3);
  ASSERT_EQ(values.size(), 2000u);
  for (const auto& row : values) {
    ASSERT_EQ(row.size(), d.size());
    for (std::size_t k = 0; k < d.size(); ++k) {
      EXPECT_GE(row[k], d[k].min) << cohortProperties()[k].key;
      EXPECT_LE(row[k], d[k].max) << cohortProperties()[k].key;
    }
  }
  // The ends of the unit interval map to the ends of the range.
  for (const auto& dist : d) {
    EXPECT_NEAR(calcCohortValue(dist, 0.0), dist.min, 1e-9 * (dist.max - dist.min));
    EXPECT_LE(calcCohortValue(dist, std::nextafter(1.0, 0.0)), dist.max);
  }
}

TEST(CohortSampling, TruncatedNormalHasTheNormalsMedianWhenSymmetric) {
  CohortDistribution n;
  n.kind = CohortDistribution::Kind::kNormal;
  n.mean = 1.759;
  n.sd = 0.067;
  n.min = n.mean - 0.11;
  n.max = n.mean + 0.11;
  n.source = "test";
  EXPECT_NEAR(calcCohortValue(n, 0.5), n.mean, 1e-12);
  // Inside a symmetric truncation at +-1.64 sd, u = 0.75 is the quantile at
  // Phi(-1.64) + 0.75 (Phi(1.64) - Phi(-1.64)), computed independently with erfc.
  const double a = (n.min - n.mean) / n.sd;
  const double pa = 0.5 * std::erfc(-a / std::sqrt(2.0)), pb = 1 - pa;
  const double p = pa + 0.75 * (pb - pa);
  const double x = calcCohortValue(n, 0.75);
  EXPECT_NEAR(0.5 * std::erfc(-((x - n.mean) / n.sd) / std::sqrt(2.0)), p, 1e-12);
}

TEST(CohortSampling, BadDistributionsNameTheKeyExpectedAndFound) {
  const CohortProperty& stature = cohortProperties()[findCohortProperty("stature_m")];
  CohortDistribution d;
  d.min = 1.6;
  d.max = 1.9;
  d.source = "Huston 2009";
  EXPECT_TRUE(checkCohortDistribution(stature, d).key.empty());
  d.max = 3.0;
  auto problem = checkCohortDistribution(stature, d);
  EXPECT_EQ(problem.key, "max");
  EXPECT_EQ(problem.found, "3");
  d.max = 1.5;
  EXPECT_EQ(checkCohortDistribution(stature, d).key, "max");  // not above min
  d.max = 1.9;
  d.kind = CohortDistribution::Kind::kNormal;
  d.mean = 1.75;
  d.sd = 0;
  EXPECT_EQ(checkCohortDistribution(stature, d).key, "sd");
  d.sd = 0.07;
  d.mean = 2.0;
  problem = checkCohortDistribution(stature, d);
  EXPECT_EQ(problem.key, "mean");
  EXPECT_EQ(problem.expected, "a mean inside [1.6, 1.9]");
  d.mean = 1.75;
  d.source = "  ";
  EXPECT_EQ(checkCohortDistribution(stature, d).key, "source");
  EXPECT_THROW(drawCohort({d}, 3, 1), std::invalid_argument);
}

TEST(CohortSampling, DrawnLegAddsUp) {
  Participant templ;
  templ.name = "template";
  std::vector<double> v(cohortProperties().size());
  auto set = [&](const char* key, double value) { v[findCohortProperty(key)] = value; };
  set("stature_m", 1.80);
  set("body_mass_index_kg_m2", 22);
  set("residual_limb_fraction", 0.8);
  set("socket_mass_kg", 1.0);
  set("knee_mass_kg", 1.0);
  set("knee_com_below_axis_m", 0.05);
  set("knee_radius_of_gyration_m", 0.04);
  set("pylon_mass_kg", 0.2);
  set("foot_mass_kg", 0.7);
  set("foot_com_from_toe_fraction", 0.6);
  set("foot_radius_of_gyration_fraction", 0.4);
  set("knee_friction_Nm", 10);
  set("swing_time_s", 0.45);
  const Participant p = makeCohortParticipant(templ, v, "C001");
  EXPECT_EQ(p.name, "C001");
  EXPECT_NEAR(p.bodyMass, 22 * 1.8 * 1.8, kRound);
  EXPECT_NEAR(p.thigh.length + p.shank.length, (0.530 - 0.039) * 1.80, kRound);  // hip to ankle, Winter Fig. 4.1
  EXPECT_NEAR(p.thigh.mass, 0.100 * p.bodyMass * 0.8 + 1.0, kRound);
  EXPECT_NEAR(p.shank.mass, 1.2, kRound);
  // Shank COM from the knee by moments: 1.0 kg at 0.05 m and 0.2 kg at half the shank.
  const double com = (1.0 * 0.05 + 0.2 * 0.5 * p.shank.length) / 1.2;
  EXPECT_NEAR(p.shank.length - p.shank.comFromDistal, com, kRound);
  EXPECT_NEAR(p.foot.comFromDistal, 0.6 * 0.152 * 1.8, kRound);
  EXPECT_EQ(p.kneeFriction, 10);
  EXPECT_NO_THROW(calcLegGeometry(p, 0.1));
  set("knee_com_below_axis_m", 0.6);  // below the ankle
  EXPECT_THROW(makeCohortParticipant(templ, v, "C002"), InputError);
}

TEST(CohortSampling, NamesArePaddedToTheCohortsWidth) {
  EXPECT_EQ(cohortParticipantName(0, 120), "C001");
  EXPECT_EQ(cohortParticipantName(119, 120), "C120");
  EXPECT_EQ(cohortParticipantName(41, 5000), "C0042");
}

}  // namespace
}  // namespace swingsim
