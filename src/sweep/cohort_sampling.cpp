#include "sweep/cohort_sampling.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "core/input_error.h"
#include "numerics/residual_analysis.h"

namespace swingsim {

namespace {

// Winter, Biomechanics and Motor Control of Human Movement (4th ed. 2009), Fig. 4.1: joint
// heights as fractions of stature H: hip 0.530, knee 0.285, ankle 0.039; foot length 0.152.
constexpr double kThighLengthPerStature = 0.530 - 0.285;
constexpr double kShankLengthPerStature = 0.285 - 0.039;
constexpr double kFootLengthPerStature = 0.152;
// Winter 2009 Table 4.1, thigh: mass 0.100 of body mass, radius of gyration about its
// centre of mass 0.323 of its length.
constexpr double kThighMassPerBodyMass = 0.100;
constexpr double kThighGyrationPerLength = 0.323;

enum Property : std::size_t {
  kStature,
  kBmi,
  kResidualFraction,
  kSocketMass,
  kKneeMass,
  kKneeComBelowAxis,
  kKneeGyration,
  kPylonMass,
  kFootMass,
  kFootComFromToe,
  kFootGyration,
  kKneeFriction,
  kSwingTime,
  kPropertyCount
};

double calcNormalCdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

// A normal truncated to [min, max] is a normal only between two limits on its sd, as
// fractions of the truncation's width. Wider than kMaxSdPerWidth, its density across [min,
// max] varies by at most exp(-0.1^2 / 2), 0.5 %: a uniform by another name (and from ~1e16
// widths both truncation ends round to the same CDF value and every draw is the mean).
// Narrower than kMinSdPerWidth, every draw lies within 0.4 % of the width of the mean
// (3.7 sd hold 99.98 % of draws): a constant by another name.
constexpr double kMaxSdPerWidth = 10;
constexpr double kMinSdPerWidth = 1e-3;

// A limit on sd as a message shows it: 3 significant digits (2.2, not 2.1999999999999997).
std::string formatSdLimit(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace

const std::vector<CohortProperty>& cohortProperties() {
  static const std::vector<CohortProperty> table = {
      {"stature_m", "stature (m)", 1.2, 2.3},
      {"body_mass_index_kg_m2", "body mass index (kg/m^2)", 14, 45},
      {"residual_limb_fraction", "residual limb / intact thigh length", 0.2, 1.0},
      {"socket_mass_kg", "socket mass (kg)", 0, 5},
      {"knee_mass_kg", "knee unit mass (kg)", 0.1, 5},
      {"knee_com_below_axis_m", "knee unit COM below its axis (m)", 0, 0.2},
      {"knee_radius_of_gyration_m", "knee unit radius of gyration (m)", 0, 0.2},
      {"pylon_mass_kg", "pylon mass (kg)", 0, 3},
      {"foot_mass_kg", "foot unit mass (kg)", 0.1, 5},
      {"foot_com_from_toe_fraction", "foot COM from the toe / foot length", 0.05, 0.95},
      {"foot_radius_of_gyration_fraction", "foot radius of gyration / foot length", 0.05, 0.6},
      {"knee_friction_Nm", "knee friction Tc (N m)", 0, 50},
      {"swing_time_s", "calibrated swing time (s)", 0.2, 1.2},
  };
  return table;
}

std::size_t findCohortProperty(const std::string& key) {
  const auto& table = cohortProperties();
  for (std::size_t i = 0; i < table.size(); ++i)
    if (table[i].key == key) return i;
  throw std::out_of_range("no cohort property " + key);
}

CohortDistributionProblem checkCohortDistribution(const CohortProperty& property, const CohortDistribution& d) {
  const std::string range = "[" + formatNumber(d.min) + ", " + formatNumber(d.max) + "]";
  const std::string physical = formatNumber(property.physicalMin) + " .. " + formatNumber(property.physicalMax);
  if (!(d.min >= property.physicalMin && d.min <= property.physicalMax))
    return {"min", "a value inside " + physical + " (" + property.what + ")", formatNumber(d.min)};
  if (!(d.max >= property.physicalMin && d.max <= property.physicalMax))
    return {"max", "a value inside " + physical + " (" + property.what + ")", formatNumber(d.max)};
  if (!(d.min < d.max)) return {"max", "a value above min " + formatNumber(d.min), formatNumber(d.max)};
  if (d.kind == CohortDistribution::Kind::kNormal) {
    if (!(d.sd > 0 && std::isfinite(d.sd))) return {"sd", "a positive standard deviation", formatNumber(d.sd)};
    if (!(d.mean >= d.min && d.mean <= d.max)) return {"mean", "a mean inside " + range, formatNumber(d.mean)};
    const double width = d.max - d.min;
    if (d.sd > kMaxSdPerWidth * width)
      return {"sd",
              "a standard deviation of at most " + formatNumber(kMaxSdPerWidth) +
                  " x (max - min) = " + formatSdLimit(kMaxSdPerWidth * width) + " (a wider normal is flat across " +
                  range + ": its truncation draws a uniform, so write distribution: uniform)",
              formatNumber(d.sd)};
    if (d.sd < kMinSdPerWidth * width)
      return {"sd",
              "a standard deviation of at least " + formatNumber(kMinSdPerWidth) +
                  " x (max - min) = " + formatSdLimit(kMinSdPerWidth * width) +
                  " (a narrower normal draws every participant at the mean " + formatNumber(d.mean) + ")",
              formatNumber(d.sd)};
  }
  if (d.source.find_first_not_of(" \t") == std::string::npos)
    return {"source", "the published source of the range (paper and table) or \"assumption: ...\"", "an empty text"};
  return {};
}

double calcCohortValue(const CohortDistribution& d, double u) {
  double x = d.min + u * (d.max - d.min);
  if (d.kind == CohortDistribution::Kind::kNormal) {
    // Inverse CDF inside the truncation: one uniform per value, as for the uniform.
    const double pa = calcNormalCdf((d.min - d.mean) / d.sd), pb = calcNormalCdf((d.max - d.mean) / d.sd);
    const double p = std::clamp(pa + u * (pb - pa), 1e-300, 1 - 1e-16);
    x = d.mean + d.sd * calcNormalQuantile(p);
  }
  return std::clamp(x, d.min, d.max);
}

std::vector<std::vector<double>> drawCohort(const std::vector<CohortDistribution>& distributions, int count,
                                            std::uint64_t seed) {
  if (distributions.size() != cohortProperties().size())
    throw std::invalid_argument("drawCohort: " + std::to_string(distributions.size()) + " distributions for " +
                                std::to_string(cohortProperties().size()) + " properties");
  std::mt19937_64 engine(seed);
  std::vector<std::vector<double>> values(static_cast<std::size_t>(std::max(count, 0)));
  for (auto& participant : values)
    for (const auto& d : distributions) {
      const double u = static_cast<double>(engine() >> 11) * 0x1.0p-53;
      participant.push_back(calcCohortValue(d, u));
    }
  return values;
}

double calcCohortBodyMass(const std::vector<double>& values) {
  return values[kBmi] * values[kStature] * values[kStature];
}

Participant makeCohortParticipant(const Participant& templ, const std::vector<double>& v, const std::string& name) {
  if (v.size() != kPropertyCount)
    throw std::invalid_argument("makeCohortParticipant: " + std::to_string(v.size()) + " values");
  Participant p = templ;
  p.name = name;
  p.height = v[kStature];
  p.bodyMass = calcCohortBodyMass(v);
  p.kneeFriction = v[kKneeFriction];

  // Thigh link, hip to knee axis: the residual limb (a cylinder from the hip, Burkett 2004)
  // with its share of Winter's thigh, and the socket around it (its COM assumed with the limb's).
  const double thighLength = kThighLengthPerStature * p.height;
  const double limbLength = v[kResidualFraction] * thighLength;
  p.thigh.length = thighLength;
  p.thigh.mass = kThighMassPerBodyMass * p.bodyMass * v[kResidualFraction] + v[kSocketMass];
  p.thigh.comFromDistal = thighLength - 0.5 * limbLength;
  p.thigh.inertia = p.thigh.mass * std::pow(kThighGyrationPerLength * limbLength, 2);

  // Shank link, knee axis to ankle: the knee unit at its COM and a uniform pylon over the link.
  const double shankLength = kShankLengthPerStature * p.height;
  const double km = v[kKneeMass], kd = v[kKneeComBelowAxis], pm = v[kPylonMass];
  if (kd >= shankLength)
    throw InputError(name + ": knee_com_below_axis_m: expected a knee centre of mass above the ankle (shank " +
                     formatNumber(shankLength) + " m), found " + formatNumber(kd) + " m");
  const double com = (km * kd + pm * 0.5 * shankLength) / (km + pm);  // below the knee axis
  p.shank.length = shankLength;
  p.shank.mass = km + pm;
  p.shank.comFromDistal = shankLength - com;
  p.shank.inertia = km * (std::pow(v[kKneeGyration], 2) + std::pow(kd - com, 2)) +
                    pm * (shankLength * shankLength / 12 + std::pow(0.5 * shankLength - com, 2));
  // The knee unit moves down with the axis (ComRule::kFixedFromProximal): lowered by d, its
  // COM is kd below the axis on a shank of shankLength - d, so the shank must keep at least
  // kd and the lowering sweep stops where the COM reaches the ankle (calcMaxLowering).
  if (p.comRule == ComRule::kFixedFromProximal) p.minShankLength = std::max(templ.minShankLength, kd);
  // The participant file's own check (min_shank_length_m below the shank's length).
  if (!(templ.minShankLength < shankLength))
    throw InputError(name + ": min_shank_length_m: must be shorter than the shank (" + formatNumber(shankLength) +
                     " m, from stature " + formatNumber(p.height) + " m) (got " + formatNumber(templ.minShankLength) +
                     ", the template's)");

  // Foot link: the foot unit; its COM distance measured from the toe (Burkett Table 2's reading).
  const double footLength = kFootLengthPerStature * p.height;
  p.foot.length = footLength;
  p.foot.mass = v[kFootMass];
  p.foot.comFromDistal = v[kFootComFromToe] * footLength;
  p.foot.inertia = p.foot.mass * std::pow(v[kFootGyration] * footLength, 2);
  p.footComFrom = FootComFrom::kToe;
  return p;
}

std::string cohortParticipantName(std::size_t index, std::size_t count) {
  const std::size_t width = std::max<std::size_t>(3, std::to_string(count).size());
  std::string number = std::to_string(index + 1);
  return "C" + std::string(width - std::min(width, number.size()), '0') + number;
}

}  // namespace swingsim
