#pragma once
// The participants of a cohort study (docs/cohort.md): N prosthesis users drawn from
// documented distributions of stature, body mass index, residual-limb length, socket, knee
// unit, pylon and foot masses and inertias, knee friction and the swing time their hip drive
// is calibrated to. Each property is one row of a fixed table (its key, unit and the values
// that are physically possible); the study gives each row its distribution and source.
//
// Reproducible: one std::mt19937_64(seed), each uniform u in [0, 1) as (engine() >> 11) *
// 2^-53 (53 random bits, the same on every standard library, as the uncertainty analysis),
// participant by participant in table order, so participant i's values depend only on the
// seed and i, never on shards or threads.
//
// A drawn participant's leg (makeCohortParticipant): segment lengths from stature (Winter
// 2009 Fig. 4.1), the thigh link = residual limb (Winter 2009 Table 4.1's thigh mass and
// radius of gyration, scaled by the residual-limb fraction: Burkett 2004's residual limb is a
// cylinder of tissue) + socket; the shank link = knee unit + pylon; the foot link = foot unit.
#include <cstdint>
#include <string>
#include <vector>

#include "model/leg_parameters.h"

namespace swingsim {

/// One drawn property of a cohort participant.
struct CohortProperty {
  std::string key;                  ///< YAML key under `distributions:`, unit in the name (stature_m)
  std::string what;                 ///< for tables and figures
  double physicalMin, physicalMax;  ///< a distribution's range must lie inside [min, max]
};

/// The table, in draw order.
const std::vector<CohortProperty>& cohortProperties();
/// Index of `key` in cohortProperties(); throws std::out_of_range if unknown.
std::size_t findCohortProperty(const std::string& key);

/// A distribution over [min, max]: uniform, or a normal(mean, sd) truncated to [min, max].
struct CohortDistribution {
  enum class Kind { kUniform, kNormal };
  Kind kind = Kind::kUniform;
  double min = 0, max = 0;
  double mean = 0, sd = 0;  ///< kNormal only
  std::string source;       ///< the published source of the range, or the stated assumption
};

/// What is wrong with a distribution: the key at fault, what was expected and what was found.
struct CohortDistributionProblem {
  std::string key;  ///< "" if nothing is wrong; else min, max, mean, sd or source
  std::string expected, found;
};

/// Checks `d` for `property`: a range inside the physical one with min < max, a normal's mean
/// inside its range and an sd from 0.001 to 10 x (max - min) (narrower, every draw is the
/// mean; wider, the truncated normal is a uniform), a non-empty source.
CohortDistributionProblem checkCohortDistribution(const CohortProperty& property, const CohortDistribution& d);

/// The value at u in [0, 1): min + u (max - min), or the normal's quantile at u inside its
/// truncation; always inside [min, max].
double calcCohortValue(const CohortDistribution& d, double u);

/// Values [participant][property] of `count` participants (property order of the table),
/// from `distributions` (one per table row). Throws std::invalid_argument if the sizes differ.
std::vector<std::vector<double>> drawCohort(const std::vector<CohortDistribution>& distributions, int count,
                                            std::uint64_t seed);

/// Body mass from stature and BMI, kg.
double calcCohortBodyMass(const std::vector<double>& values);

/// A participant: `templ` (knee model, friction law, initial pose, swing-end rule, hip-moment
/// profile) with the drawn stature, body mass, segments and knee friction (`values` in table
/// order). Its shank keeps at least the knee unit's COM distance (minShankLength), so no
/// lowering puts the knee unit's COM below the ankle. Throws InputError (naming `name` and
/// the key) if the drawn leg is impossible: a knee centre of mass below the ankle, or a
/// shank shorter than the template's min_shank_length_m.
Participant makeCohortParticipant(const Participant& templ, const std::vector<double>& values, const std::string& name);

/// "C001", "C002", ...: participant i of `count`, zero-padded to count's width (at least 3).
std::string cohortParticipantName(std::size_t index, std::size_t count);

}  // namespace swingsim
