#pragma once
// The one model-vs-measurement engine of `swingsim compare` and `swingsim diagnose`, for
// every plant (the Mauch cylinder on a bench, the swing of a leg): fit the base model ->
// compare (residual per phase and state) -> score every candidate effect of the library on
// top of the current model -> the acceptance rule (identify/effect_selection.h) -> add the
// best accepted one -> refit -> validate on held-out records -> repeat. The plants differ only
// in the DiagnosisPlant they implement; docs/diagnosis.md explains the statistics.
#include <Eigen/Dense>

#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "identify/comparison.h"
#include "identify/effect_selection.h"
#include "identify/effect_table.h"
#include "identify/missing_force.h"
#include "identify/missing_moment.h"
#include "numerics/noise_estimate.h"
#include "numerics/residual_analysis.h"

namespace swingsim {

/// A model of one plant with its parameter values; only its plant looks inside.
class PlantModel {
 public:
  virtual ~PlantModel() = default;
};
using PlantModelPtr = std::shared_ptr<const PlantModel>;

/// A plant's model that is its parameter struct and nothing else (the swing's, the sweep's).
template <class Params>
class PlantModelOf final : public PlantModel {
 public:
  explicit PlantModelOf(Params params) : params(std::move(params)) {}
  Params params;
};
/// The parameters inside `model`, a PlantModelOf<Params> (std::bad_cast for another plant's).
template <class Params>
const Params& plantModelParams(const PlantModel& model) {
  return dynamic_cast<const PlantModelOf<Params>&>(model).params;
}

/// A model with all its free parameters fitted to the training records and run along the
/// held-out ones.
struct PlantFit {
  PlantModelPtr model;
  ResidualSegments likelihoodResidual;  ///< every training residual the likelihood uses
  double rss = 0;                       ///< sum of squares of likelihoodResidual
  std::size_t samples = 0;              ///< its length
  /// Per training record, the residual of the compared quantity (N; knee deg), and the
  /// phase of each sample under this model.
  std::vector<std::vector<double>> trainResidual;
  std::vector<std::vector<int>> trainPhase;
  double trainRmse = 0;                ///< of trainResidual
  std::vector<double> validationRmse;  ///< per held-out record
  /// Cross-validated plants (the sweep: leave one participant out): per fold, the RSS and
  /// the residual of that fold's training rows at that fold's own fit. Empty for a plant with
  /// one fixed training/held-out split. When set, a candidate must be significant on the
  /// training rows of every fold (the engine tests each fold and keeps the largest p).
  std::vector<double> foldRss;
  std::vector<ResidualSegments> foldResidual;
  /// The held-out RMSE pooled over every held-out row of every fold (unit of the data); NaN:
  /// the plant has no pooled rule, and a candidate must lower every held-out RMSE instead.
  double pooledValidationRmse = std::numeric_limits<double>::quiet_NaN();
  /// Standard errors (unit of the reported parameter, before inflation for autocorrelation)
  /// of the fitted parameters of every effect in the model, by effect, in the order of the
  /// descriptor's parameters; and of the base model's own free parameters.
  std::vector<std::pair<EffectId, std::vector<double>>> effectErrors;
  /// The physical bounds (lower, upper; reported unit) of the same parameters, in the same
  /// order; an effect missing here has bounds the engine cannot judge an interval against.
  std::vector<std::pair<EffectId, std::vector<std::pair<double, double>>>> effectBounds;
  /// The base model's own free parameters (the swing's knee model scale), with standard errors.
  struct FreeParameter {
    std::string name;  ///< with unit
    double value = 0, standardError = 0;
    /// Physical bounds of the parameter in the fit (reported unit).
    double lower = -std::numeric_limits<double>::infinity(), upper = std::numeric_limits<double>::infinity();
  };
  std::vector<FreeParameter> baseParameters;
  /// Notes on the fit itself: stopped at its budget, a parameter on a physical bound.
  std::vector<std::string> notes;
  /// Every fitted parameter (name with unit; per-record nuisance parameters left out) and
  /// their correlation matrix from the fit's covariance: confounds show as |r| near 1.
  std::vector<std::string> parameterNames;
  Eigen::MatrixXd correlation;
};

/// What the engine needs from a plant.
class DiagnosisPlant {
 public:
  virtual ~DiagnosisPlant() = default;
  virtual PlantKind kind() const = 0;
  /// The base model, before any fit.
  virtual PlantModelPtr baseModel() const = 0;
  /// Fits every free parameter of `model` (base and effects; grid parameters as given) to the
  /// training records and runs it along the held-out ones. Throws RunError if it cannot run.
  virtual PlantFit fit(const PlantModel& model) const = 0;
  /// Why `effect` cannot be added to `model` ("" if it can).
  virtual std::string checkApplicable(const PlantModel& model, EffectId effect) const = 0;
  /// `model` with `effect` switched on (fitted parameters zero or neutral; the grid
  /// parameter, if any, at `gridValue`).
  virtual PlantModelPtr addEffect(const PlantModel& model, EffectId effect, double gridValue) const = 0;
  /// `a` with the effect `effectOfB` of `b` added at `b`'s values.
  virtual PlantModelPtr combine(const PlantModel& a, const PlantModel& b, EffectId effectOfB) const = 0;
  /// The reported values of an effect's parameters (descriptor order, reported units).
  virtual std::vector<double> effectValues(const PlantModel& model, EffectId effect) const = 0;
  /// Whether the fitted effect has its physical sign; `note` says the rule and the value.
  virtual bool checkPhysical(const PlantModel& model, EffectId effect, std::string& note) const = 0;
  /// Phase names of `model` (phase indices of PlantFit::trainPhase).
  virtual std::vector<std::string> phaseNames(const PlantModel& model) const = 0;
  /// `model` run along every record, training first.
  virtual Comparison compare(const PlantModel& model) const = 0;
  /// Stems of the held-out records, in order.
  virtual std::vector<std::string> validationStems() const = 0;
  /// Measurement noise of the compared quantity in every record (training first),
  /// estimated from the measured signal alone.
  virtual std::vector<NoiseEstimate> estimateRecordNoise() const = 0;
  /// The refit after `effect` was accepted, from its candidate fit `candidate`: a plant
  /// whose candidates are scored with some parameters held (the cylinder's switch constants)
  /// frees here what the effect touches and couples to. The default keeps the candidate fit.
  virtual PlantFit refitAccepted(const PlantFit& candidate, EffectId /*effect*/) const { return candidate; }
  /// Warnings of the base fit (e.g. a switch constant at the edge of its range).
  virtual std::vector<std::string> warnings() const { return {}; }
  /// The residual the whiteness test reads, from a fit's likelihood residual: by default its
  /// records as they are. A plant whose records are too short for lags of their own (the
  /// sweep: 2-5 rows a participant) joins them, so that a residual that keeps its sign
  /// along a record shows as correlation at short lags.
  virtual ResidualSegments whitenessResidual(const ResidualSegments& likelihoodResidual) const {
    return likelihoodResidual;
  }
  /// An independent check of a fitted model, one line for the report ("" if the plant has
  /// none): the swing reruns the model with Simbody, since its refits use the reference
  /// integrator.
  virtual std::string verify(const PlantModel&) const { return ""; }
  /// Where the force the measurements need and the model lacks acts in the measured state
  /// (the swing's missing knee moment, identify/missing_moment.h; its note says why it was not
  /// computed); nullopt if the plant cannot say.
  virtual std::optional<MissingMoment> calcMissing(const PlantModel&) const { return std::nullopt; }
  /// Where the missing quantity acts, for a plant that measures it directly (the cylinder's
  /// force on a bench: identify/missing_force.h); nullopt if the plant does not.
  virtual std::optional<MissingForce> calcMissingForce(const PlantModel&) const { return std::nullopt; }
  /// A quantity the model applies against an independent measurement the fit never sees
  /// (the swing's knee moment against inverse dynamics); nullopt if the data have none.
  virtual std::optional<HeldBackComparison> compareHeldBack(const PlantModel&) const { return std::nullopt; }
  /// The training RSS (PlantFit::rss) of `fitted` refitted with its base parameter
  /// `parameter` (a PlantFit::FreeParameter name) held at `value`, every other parameter
  /// free: one point of its profile likelihood. nullopt if the plant cannot hold it. May
  /// throw RunError where the model cannot run at that value.
  virtual std::optional<double> calcHeldParameterRss(const PlantModel& /*fitted*/, const std::string& /*parameter*/,
                                                     double /*value*/) const {
    return std::nullopt;
  }
  /// Every record the plant holds (training, then held out) by its stem; and the same plant
  /// with record `index` of that list as its only training record and none held out, for the
  /// record-agreement rule (identify/record_agreement.h). Empty / nullptr: the plant does not
  /// take part in that rule.
  virtual std::vector<std::string> recordStems() const { return {}; }
  virtual std::unique_ptr<DiagnosisPlant> withOnlyRecord(std::size_t /*index*/) const { return nullptr; }
};

/// One candidate scored on top of the current model.
struct CandidateScore : EffectScore {
  EffectId id{};
  bool added = false;   ///< passed the rule and was the one added to the model in its step
  PlantModelPtr model;  ///< current model + the effect, every parameter refitted
};

struct DiagnosisStep {
  double currentTrainRmse = 0;
  std::vector<double> currentValidationRmse;
  std::vector<CandidateScore> candidates;
  int chosen = -1;                 ///< index into candidates, -1 if none accepted
  std::vector<std::string> group;  ///< the chosen effect and those the data cannot tell from it
};

/// Correlation of two fitted parameters above which they count as one confounded group.
constexpr double kConfoundLimit = 0.95;

/// The closest candidate of a step: of the candidates that were scored and carry information
/// in these records (EffectScore::informative), the one with the largest likelihood ratio on
/// the training records; nullptr if there is none. The one definition the verdict and the
/// power advice use (docs/diagnosis.md, "The closest candidate").
const CandidateScore* findClosestCandidate(const DiagnosisStep& step);

/// When no candidate is significant: how many swings (records) like the training ones the
/// closest candidate (findClosestCandidate) would need, at its fitted size, for
/// kPowerTarget power at the acceptance rule's level. The likelihood ratio is taken to
/// grow in proportion to the number of training records (docs/diagnosis.md).
struct PowerAdvice {
  std::string effect;
  double likelihoodRatio = 0;  ///< on the training records
  int dof = 1;
  double level = 0;                ///< the rule's alpha, Bonferroni-corrected over the candidates
  int recordsNow = 0;              ///< training records
  int recordsNeeded = 0;           ///< in all; 0: no number of records would do (no effect at all)
  std::string records = "swings";  ///< what a record is, for the advice ("participants" for the sweep)
  /// Whether the closest lowers the held-out error on every held-out record (true without
  /// any): more records are advised only for a candidate that does.
  bool lowersHeldOut = true;
  std::string heldOutNote;  ///< where it does not: "slow 0.80 -> 0.82"
};
constexpr double kPowerTarget = 0.8;

/// Result of a diagnosis.
struct Diagnosis {
  PlantKind plant{};
  PlantFit baseline;                                                 ///< base model fitted
  PlantFit final;                                                    ///< with the accepted effects, refitted
  std::vector<EffectParameter> baselineParameters, finalParameters;  ///< base model's own, 95 % intervals
  std::vector<DiagnosisStep> steps;
  std::vector<std::string> accepted;  ///< names, in order of acceptance
  std::vector<CandidateScore> acceptedScores;
  std::vector<std::vector<std::string>> ambiguous;
  std::vector<std::string> ambiguityAdvice;  ///< one per ambiguous group
  /// Effects not stacked because their parameter moves with one already in the model (a
  /// confound: |correlation| > kConfoundLimit), each a sentence naming the pair and the
  /// measurement that would separate them.
  std::vector<std::string> confounds;
  WhitenessTest baselineWhiteness, finalWhiteness;
  /// The Ljung-Box test's level: the residual counts as white when its p is at least this
  /// (the acceptance rule's alpha, EffectSelectionSettings::alpha).
  double whitenessLevel = 0.01;
  bool finalResidualWhite = true;
  std::string structureNote;  ///< where the remaining structure is, if not explained
  std::string missingNote;    ///< where the missing force acts in the measured state, if not explained
  /// The missing moment itself (the map a figure draws), where the plant computes one.
  std::optional<MissingMoment> missing;
  /// The missing force itself (the cylinder's map a figure draws), where the plant computes one.
  std::optional<MissingForce> missingForce;
  std::vector<std::string> warnings;
  /// The noise each record's held-out error is judged against (unit of the data), and where
  /// it comes from ("estimated from the data" or "set in the study").
  std::vector<double> recordNoise;
  NoiseEstimate pooledNoise;
  std::string noiseSource;
  /// Whether the final model explains the data: every held-out RMSE within
  /// explainedNoiseRatio x its record's noise and a white final residual. If not, `verdict`
  /// says in words what remains, what was tried and how close the best candidate came.
  bool explained = false;
  std::string verdict;
  std::optional<PowerAdvice> power;  ///< set when no candidate was significant
};

/// Forward stepwise diagnosis with the acceptance rule of `settings`. Throws InputError for
/// an unknown candidate name (listing the plant's effects) or no held-out record (the rule
/// needs held-out data), RunError if the base model cannot run.
/// `progress` (optional) is called before a step's first candidate and after each, with the
/// step (0-based) and the candidates scored of the step's total: a progress bar's feed.
using DiagnosisProgress = std::function<void(int step, int done, int total)>;
Diagnosis runDiagnosis(const DiagnosisPlant& plant, const EffectSelectionSettings& settings,
                       const DiagnosisProgress& progress = {});

/// The base model fitted (no candidate): what `swingsim compare` shows. Whiteness of its
/// likelihood residual with `whitenessLags` lags.
struct BaselineComparison {
  PlantFit fit;
  std::vector<EffectParameter> parameters;  ///< base model's own, 95 % intervals
  Comparison comparison;
  WhitenessTest whiteness;
};
BaselineComparison compareBaseline(const DiagnosisPlant& plant, int whitenessLags);

}  // namespace swingsim
