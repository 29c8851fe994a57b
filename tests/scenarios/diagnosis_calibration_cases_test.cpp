// The calibration study's cases name real candidates and parameters: a misspelled parameter
// would never be scored (its coverage silently "-"), a truth outside the candidate's range
// could never be covered; every sweep candidate the generator can hide is a case; the
// hyperextension phase is held against Chien Table 1's phase 4, term for term.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "../identify/diagnosis_calibration.h"
#include "identify/effect_table.h"
#include "identify/sweep_effects.h"

namespace swingsim {
namespace {

PlantKind plantOf(const std::string& plant) {
  if (plant == "swing") return PlantKind::kSwing;
  if (plant == "cylinder") return PlantKind::kCylinder;
  return PlantKind::kSweep;
}

TEST(CalibrationCases, EveryCaseNamesACandidateAndOneOfItsParameters) {
  for (const auto& c : calibration::calibrationCases()) {
    if (c.effect.empty() || calibration::isOutsideLibrary(c)) continue;
    const EffectDescriptor* d = findEffect(plantOf(c.plant), c.effect);
    ASSERT_NE(d, nullptr) << c.plant << "/" << c.effect;
    if (c.parameter.empty() || c.parameter == "latch_rate_per_s") continue;  // the latch rate: the joint refit's
    EXPECT_NE(std::find(d->parameters.begin(), d->parameters.end(), c.parameter), d->parameters.end())
        << c.effect << ": " << c.parameter;
  }
}

TEST(CalibrationCases, SweepTruthsLieInsideTheCandidatesRanges) {
  std::set<std::string> hidden;
  for (const auto& c : calibration::calibrationCases()) {
    if (c.plant != "sweep" || c.effect.empty()) continue;
    hidden.insert(c.effect);
    if (c.parameter.empty()) continue;
    const auto& law = findSweepEffectLaw(findEffect(PlantKind::kSweep, c.effect)->id);
    EXPECT_GT(c.truth, law.lower) << c.effect;
    EXPECT_LT(c.truth, law.upper) << c.effect;
  }
  // Every sweep candidate is hidden in one case.
  for (const auto& e : effectTable()) {
    if (e.plant == PlantKind::kSweep) {
      EXPECT_EQ(hidden.count(e.name), 1u) << e.name;
    }
  }
}

TEST(CalibrationCases, HyperextensionPhaseIsHeldAgainstChienPhaseFour) {
  const auto phase4 = independent::chienTable1(4)[3];
  int found = 0;
  for (const auto& c : calibration::calibrationCases()) {
    if (c.effect != "hyperextension_phase") continue;
    ++found;
    const double expected = c.parameter == "f_N" ? phase4.f : c.parameter == "k_N_per_m" ? phase4.k : phase4.c;
    EXPECT_EQ(c.truth, expected) << c.parameter;
  }
  EXPECT_EQ(found, 3);
}

}  // namespace
}  // namespace swingsim
