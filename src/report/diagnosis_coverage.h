#pragma once
// How far a diagnosis' intervals can be trusted: the measured coverage of the 95 % interval
// of each candidate effect's parameter, from the calibration study of the diagnosis
// (docs/diagnosis.md, "How far the intervals can be trusted (calibration)"), compiled in so
// that the report of an accepted effect can quote it.
#include <optional>
#include <string>

namespace swingsim {

/// The measured behaviour of one effect's interval on independent data.
struct MeasuredCoverage {
  const char* effect;     ///< library name, "knee_coulomb_friction"
  const char* parameter;  ///< the parameter held against the truth; "" when none was
  int seeds;              ///< noise seeds the effect was hidden in; 0: not measured, the caveat says why
  int named;              ///< seeds in which it was the first effect accepted
  int scored;             ///< seeds in which the parameter had an estimate and an interval
  int covered;            ///< of those, seeds in which the 95 % interval held the truth
  double biasPercent;     ///< mean estimate - truth, % of the truth (NaN when not measured)
  double sdPercent;       ///< SD of the estimate, % of the truth (NaN when not measured)
  const char* caveat;     ///< why the interval cannot be trusted as 95 %; "" when it can
};

/// The calibration row of `effect`; nullopt for an effect the study did not measure.
std::optional<MeasuredCoverage> findMeasuredCoverage(const std::string& effect);

/// One line for the report of an accepted effect: "interval check: in the calibration study
/// ... the 95 % interval of moment_Nm held the truth in 19 of 20 seeds (bias +2 %, SD 8 %)".
/// "" for an effect the study has no row for; for a row without seeds, why it was not measured.
std::string formatMeasuredCoverage(const std::string& effect);

}  // namespace swingsim
