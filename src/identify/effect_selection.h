#pragma once
// The statistics of `swingsim diagnose` shared by every plant
// (docs/diagnosis.md): the likelihood-ratio test on an effective sample size, BIC, the
// Bonferroni-corrected acceptance rule with held-out margin and sign rule, the choice of the
// best accepted candidate, ambiguity advice and parameter intervals. The cylinder and the
// swing diagnoses differ only in how a candidate model is fitted and run.
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "numerics/residual_analysis.h"

namespace swingsim {

/// Thresholds of the acceptance rule, fixed in the study (or these defaults) before it runs.
struct EffectSelectionSettings {
  /// Family-wise error rate of the likelihood-ratio test; Bonferroni over the candidates
  /// scored in a step.
  double alpha = 0.01;
  /// Held-out RMSE must fall by at least this fraction on every validation file.
  double minValidationImprovement = 0.02;
  int maxEffects = 4;                   ///< forward stepwise stops after this many
  std::vector<std::string> candidates;  ///< empty: the whole library
  int whitenessLags = 20;               ///< Ljung-Box lags for the final residual
  /// Measurement noise standard deviation in the unit of the compared quantity (N, deg);
  /// 0: estimated from each record (numerics/noise_estimate.h).
  double measurementNoise = 0;
  /// The data count as explained when every held-out RMSE is at most this many times the
  /// noise and the final residual is white.
  double explainedNoiseRatio = 1.2;
};

/// A parameter of an effect with its 95 % confidence interval.
struct EffectParameter {
  std::string name;  ///< with unit: "force_N"
  double value = 0, lower = 0, upper = 0;
  /// Empty for the Wald interval value +- 1.96 se; else how the interval was found (a
  /// profile-likelihood interval of a parameter at or near its physical bound).
  std::string intervalNote;
};

/// One candidate scored on top of the current model (model-kind independent part).
struct EffectScore {
  std::string effect;
  std::string notApplicable;           ///< non-empty: not scored, and why
  double trainRmse = 0;                ///< units of the data (N, deg)
  std::vector<double> validationRmse;  ///< per validation file
  /// Per training record (fixed-split plants): the RMSE at the candidate's fit and at the
  /// current model's, and n ln(RSS ratio) on the record's effective sample size, n_eff
  /// ln(RSS_candidate / RSS_current): positive where the pooled fit made the record worse.
  std::vector<double> trainRecordRmse, currentTrainRecordRmse, trainRecordWorsening;
  /// Cross-validated plants: the held-out RMSE pooled over all folds (NaN otherwise), and
  /// the likelihood-ratio p of each fold's training rows (empty otherwise; pValue is their
  /// largest, the least significant fold), and the p of the same test on every training row
  /// (NaN otherwise), which the rule does not use: where the two differ, one participant
  /// carries the evidence.
  double pooledValidationRmse = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> foldPValues;
  double allRowsPValue = std::numeric_limits<double>::quiet_NaN();
  double effectiveSamples = 0;       ///< n_eff of its training residual
  double likelihoodRatio = 0;        ///< n_eff ln(RSS_current / RSS_candidate)
  int dof = 0;                       ///< added parameters (a profiled grid parameter counts one)
  double pValue = 1, pAdjusted = 1;  ///< chi^2 tail; times the number of candidates
  double deltaBic = 0;               ///< -LR + dof ln(n_eff) (< 0: better)
  std::vector<EffectParameter> parameters;
  bool significant = false, bicImproves = false, validationImproves = false, physical = false;
  /// The pooled fit made no training record significantly worse (applyRecordRule); true
  /// where the plant has one training record or is cross-validated.
  bool noRecordWorse = true;
  /// The chosen candidate refitted on each record alone gave one value within the intervals
  /// (identify/record_agreement.h); true where not tested. `agreement`: what that test found.
  bool recordsAgree = true;
  std::string agreement;
  /// False: the candidate's fit moves no residual (its parameters' intervals say nothing
  /// within their physical range); reported as kNoInformation, without intervals, and never
  /// accepted or named as the closest candidate.
  bool informative = true;
  std::string physicalNote;  ///< the sign rule and whether it held
  bool accepted = false;
  std::string where;                  ///< phase where the squared error fell most, with its share
  std::vector<double> trainResidual;  ///< concatenated training files
};

/// What the report says of a candidate whose fit moves no residual (EffectScore::informative).
inline constexpr const char* kNoInformation = "no information in these records";

/// Likelihood-ratio statistics of a bigger model against a nested smaller one (`dof` more
/// parameters), with n_eff from the bigger model's own residual (docs/diagnosis.md).
struct LrTest {
  double nEff = 0, lr = 0, p = 1, deltaBic = 0;
};
LrTest calcLrTest(double rssSmaller, double rssBigger, const ResidualSegments& biggerResidual, int dof);

/// The near-miss rule (docs/diagnosis.md, "A near miss cannot pass"): a candidate fitted on
/// several training records must not buy its pooled gain by making one of them worse. For each
/// record, n_eff ln(RSS_candidate / RSS_current) on the record's own effective sample size (of
/// the candidate's residual) is held against the chi^2(dof) quantile at 1 - alpha: above it,
/// the record is significantly worse and the candidate fails (`noRecordWorse` false). With one
/// training record the rule is empty (the held-out rule judges each other record).
void applyRecordRule(EffectScore& score, const ResidualSegments& currentTrain, const ResidualSegments& candidateTrain,
                     int dof, double alpha);

/// Writes the test into `score` (n_eff, LR, dof, p, delta BIC, bicImproves) and whether the
/// held-out error fell by at least the settings' margin: every record's RMSE from
/// `currentValidationRmse`; or, for a cross-validated plant (leave one participant out: a
/// finite `currentPooledValidationRmse` or `score.pooledValidationRmse`), the pooled RMSE.
void applyTestAndValidation(EffectScore& score, const LrTest& test, int dof,
                            const std::vector<double>& currentValidationRmse, const EffectSelectionSettings& settings,
                            double currentPooledValidationRmse = std::numeric_limits<double>::quiet_NaN());

/// Standard error inflation for autocorrelated residuals: sqrt(n / n_eff).
double calcStandardErrorInflation(double samples, double effectiveSamples);
/// 95 % normal interval value +- 1.96 se.
void setNormalInterval(EffectParameter& p, double standardError);

/// Bonferroni over the applicable candidates, the four-part acceptance rule, and the index of
/// the accepted candidate with the lowest delta BIC (-1 if none). Only scores with an empty
/// notApplicable take part; one without information (informative false) is never accepted.
int applyAcceptanceRule(std::vector<EffectScore*> scores, double alpha);

/// The ambiguity group of the candidate `chosen` in one step: its name, then the name of
/// every other accepted candidate j on top of which the chosen effect adds nothing
/// significant, i.e. `pAddingChosenTo(j)` (the LR test's p of the joint refit of j plus the
/// chosen effect against j's own fit) is at least alpha: the data cannot say which of the
/// two is missing. A nullopt p (the joint refit failed) leaves j out.
std::vector<std::string> findAmbiguityGroup(const std::vector<EffectScore*>& scores,
                                            const std::vector<std::string>& names, std::size_t chosen, double alpha,
                                            const std::function<std::optional<double>(std::size_t)>& pAddingChosenTo);

/// Appends a group of more than one effect to `ambiguous`, with its advice
/// (formatAmbiguityAdvice, each effect's `separatedBy` text) to `advice`; a single effect is
/// not ambiguous and is ignored.
void recordAmbiguity(const std::vector<std::string>& group,
                     const std::function<std::string(const std::string&)>& separatedBy,
                     std::vector<std::vector<std::string>>& ambiguous, std::vector<std::string>& advice);

/// "the data cannot tell a from b apart; to separate them add for a: ...; for b: ...".
std::string formatAmbiguityAdvice(const std::vector<std::string>& group, const std::vector<std::string>& separatedBy);

/// The candidate names to score: `requested`, or the whole `library` if empty. Throws
/// InputError for a name not in the library (listing the known ones).
std::vector<std::string> resolveCandidates(const std::vector<std::string>& requested,
                                           const std::vector<std::string>& library);

}  // namespace swingsim
