#pragma once
// Model vs measurement for the Mauch cylinder (issue 5): `compareCylinder` says where the
// model fails (metrics per phase, residuals), `diagnoseCylinder` ranks candidate missing
// physical effects, adds the ones the data support and reports the error before and after.
// docs/diagnosis.md explains the statistics; every threshold is a setting with a default.
#include <string>
#include <vector>

#include "identify/bench_data.h"
#include "identify/cylinder_fit.h"
#include "identify/effect_selection.h"
#include "numerics/metrics.h"
#include "numerics/residual_analysis.h"
#include "knee/mauch_cylinder.h"

namespace swingsim {

/// One candidate effect of the cylinder library.
struct CylinderEffectInfo {
  std::string name;       ///< coulomb_friction, orifice_quadratic, ...
  std::string sentence;   ///< what it is, for a user
  std::string mechanism;  ///< where it comes from (Chien 2014)
  std::string separatedBy;  ///< data that tell it apart from the others
};

/// The library, in a fixed order: coulomb_friction, orifice_quadratic, inertia,
/// position_dependent_damping, hyperextension_phase, switch_delay.
const std::vector<CylinderEffectInfo>& cylinderEffectLibrary();
/// Throws std::invalid_argument for a name not in the library.
const CylinderEffectInfo& findCylinderEffect(const std::string& name);

/// Grids for the non-linear parameters, fixed before any data are seen (profiled, never
/// optimised continuously): the Coulomb tanh width (m/s) and the S2 latch time constant
/// 1/k (s; Chien 2014's balance-wheel delay is "about 0.1 s").
const std::vector<double>& coulombWidthGrid();
const std::vector<double>& latchTimeConstantGrid();

/// `params` with `effect` switched on (its linear coefficients 0 until fitted) and its
/// non-linear parameter (width or latch time constant, if any) set to `nonlinear`.
MauchCylinderParams addCylinderEffect(const MauchCylinderParams& params, const std::string& effect, double nonlinear);
/// Whether `effect` can be added to `params` ("" if so, else why not).
std::string checkCylinderEffectApplicable(const MauchCylinderParams& params, const std::string& effect);

/// Names of a model's phases, by gate index ("stance flexion", ..., "hyperextension").
std::vector<std::string> cylinderPhaseNames(const MauchCylinderParams& params);

/// A model run along one record, compared with the measurement.
struct RecordComparison {
  const BenchData* data = nullptr;
  bool training = false;
  std::vector<double> predicted;     ///< N
  std::vector<double> residual;      ///< measured - predicted, N
  std::vector<double> acceleration;  ///< piston acceleration estimate, m/s^2
  std::vector<int> phase;            ///< dominant phase gate per sample
  ErrorMetrics overall;
  std::vector<ErrorMetrics> perPhase;
  std::vector<double> phaseShare;    ///< share of the squared error in each phase (sums to 1)
  std::vector<double> sampleShare;   ///< share of the samples in each phase
};

struct CylinderComparison {
  std::vector<std::string> phaseNames;
  std::vector<RecordComparison> records;  ///< training files first
};

/// Runs `model` (coefficients as given) along every file.
CylinderComparison compareCylinder(const MauchCylinderParams& model, const std::vector<BenchData>& train,
                                   const std::vector<BenchData>& validate);

/// Thresholds of the acceptance rule (shared, fit/effect_selection.h) plus the cylinder's
/// switch refit.
struct CylinderDiagnosisSettings : EffectSelectionSettings {
  bool fitSwitches = false;   ///< refit switch widths and xhy before the baseline (as `fit`)
};

/// One candidate scored on top of the current model.
struct CandidateScore : EffectScore {
  MauchCylinderParams params;        ///< current model + effect, all coefficients refitted
};

struct DiagnosisStep {
  double currentTrainRmse = 0;
  std::vector<double> currentValidationRmse;
  std::vector<CandidateScore> candidates;
  int chosen = -1;                   ///< index into candidates, -1 if none accepted
  std::vector<std::string> group;    ///< the chosen effect and those the data cannot tell from it
};

struct CylinderDiagnosis {
  MauchCylinderParams baseline;      ///< base model refitted (and switches, if asked)
  MauchCylinderParams final;         ///< with the accepted effects, refitted
  std::vector<DiagnosisStep> steps;
  std::vector<std::string> accepted;
  std::vector<CandidateScore> acceptedScores;
  std::vector<std::vector<std::string>> ambiguous;
  std::vector<std::string> ambiguityAdvice;  ///< one per ambiguous group
  WhitenessTest baselineWhiteness, finalWhiteness;
  bool finalResidualWhite = true;
  std::string structureNote;         ///< where the remaining structure is, if not white
  std::vector<std::string> warnings;
};

/// Forward stepwise diagnosis. Throws InputError for an unknown candidate name or no
/// validation file (the acceptance rule needs held-out data), RunError as fitCylinder.
CylinderDiagnosis diagnoseCylinder(const MauchCylinderParams& base, const std::vector<BenchData>& train,
                                   const std::vector<BenchData>& validate, const CylinderDiagnosisSettings& settings = {});

/// The named effect parameters of a fitted model (empty if the effect is off).
std::vector<EffectParameter> getCylinderEffectParameters(const MauchCylinderParams& params, const std::string& effect);

/// Force RMS (N) of `effect` in `truth` along a record: truth minus truth without the
/// effect (switch_delay: minus the model with k = 1e4 /s). The "effect size" of issue 5.
double calcCylinderEffectRms(const MauchCylinderParams& truth, const std::string& effect, const BenchData& record);

}  // namespace swingsim
