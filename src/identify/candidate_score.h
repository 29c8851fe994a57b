#pragma once
// Scoring one candidate effect on top of the current model (runDiagnosis scores every
// candidate of a step with it): its refit with its grid parameter profiled, the test against
// the current model, its parameters with intervals, whether the records carry information on
// it, its physical sign and where the error fell.
#include <vector>

#include "identify/diagnosis_engine.h"

namespace swingsim {

/// The standard errors `fit` reports for `id`'s fitted parameters; nullptr if none.
const std::vector<double>* findErrors(const PlantFit& fit, EffectId id);

/// The effect's parameters at `fit`, with 95 % intervals from the fit's standard errors
/// inflated by `inflate` (sqrt(n / n_eff) for autocorrelated residuals).
std::vector<EffectParameter> parametersWithIntervals(const DiagnosisPlant& plant, const PlantFit& fit, EffectId id,
                                                     double inflate);

/// Whether the candidate fit `fit` of effect `id` (likelihood ratio `lr` against `current`)
/// carries information in these records. It does not when no fitted parameter's 95 % interval
/// (`wald`, before the grid's union) excludes a value of its physical range (the interval is
/// degenerate or covers the whole range) and its fit moves no residual: every
/// fitted value stays at the neutral value it started from (what moved was the base model's
/// refit), or the fit gains no likelihood, or every interval is enormous (kEnormousRanges).
bool carriesInformation(const DiagnosisPlant& plant, const PlantFit& current, const PlantFit& fit, EffectId id,
                        double gridValue, double lr, const std::vector<EffectParameter>& wald, double inflate);

/// Scores candidate `id` on top of `current`: every parameter refitted with it, its grid
/// parameter (if any) profiled on the descriptor's fixed grid (best training RSS). A
/// candidate the plant refuses, or whose refit fails (RunError), comes back with
/// notApplicable set. `bestOut`: the candidate's best fit.
CandidateScore scoreCandidate(const DiagnosisPlant& plant, const PlantFit& current, EffectId id,
                              const EffectSelectionSettings& settings, PlantFit* bestOut);

}  // namespace swingsim
