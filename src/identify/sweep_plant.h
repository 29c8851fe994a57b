#pragma once
// The knee-axis sweep as a plant of the diagnosis engine (identify/diagnosis_engine.h): the
// measurement is a swing time per participant and lowering (Burkett 2004 Table 4, or a
// user's CSV: io/sweep_times_csv.h); the model is the sweep of a sweep study (its
// participants, knee models and swing options). The base model's free parameters are what
// the sweep fits today: one hip-moment time scale per participant, calibrated to that
// participant's standard-location row. A candidate effect is one of the sweep's unpublished
// assumptions (sweep/sweep_assumptions.h) or a lowering-dependent hip drive, fitted as ONE
// value shared by every participant, so that it predicts a participant it never saw.
//
// Held-out data are participants: leave one participant out. Each fold fits the shared values
// on the other participants' lowered rows; the held-out participant is calibrated on its own
// standard row only and predicted at its lowered rows. A participant whose standard-location
// time no time scale in range reaches is outside the model: reported (warnings), never in a
// fold or a fit. Compared quantity: swing time in ms; the likelihood uses the lowered rows'
// residuals over their standard errors (sd / sqrt(n)). docs/diagnosis.md, "The sweep".
#include <string>
#include <vector>

#include "identify/diagnosis_engine.h"
#include "identify/sweep_effects.h"
#include "identify/sweep_rows.h"
#include "model/measured_swing_time.h"
#include "sweep/sweep.h"
#include "sweep/sweep_assumptions.h"

namespace swingsim {

class SweepPlant final : public DiagnosisPlant {
 public:
  /// `rows` from `measuredPath`. `defaultStandardError` (s): the standard error of a row
  /// whose file has no sd_s (0: such a row is refused). `jobs`: threads (0 = all cores).
  /// Throws InputError for a row naming no participant of the study or a participant
  /// without a standard-location row; RunError when fewer than two participants are inside
  /// the model (leave-one-out needs two).
  SweepPlant(const SweepStudy& study, const std::vector<MeasuredSwingTime>& rows, const std::string& measuredPath,
             double defaultStandardError, int jobs = 0);

  PlantKind kind() const override { return PlantKind::kSweep; }
  PlantModelPtr baseModel() const override;
  PlantFit fit(const PlantModel& model) const override;
  std::string checkApplicable(const PlantModel& model, EffectId effect) const override;
  PlantModelPtr addEffect(const PlantModel& model, EffectId effect, double gridValue) const override;
  PlantModelPtr combine(const PlantModel& a, const PlantModel& b, EffectId effectOfB) const override;
  std::vector<double> effectValues(const PlantModel& model, EffectId effect) const override;
  bool checkPhysical(const PlantModel& model, EffectId effect, std::string& note) const override;
  std::vector<std::string> phaseNames(const PlantModel&) const override;
  /// Training records: the in-model participants at the full fit; then the same
  /// participants as held out ("P1-held-out"), each at the fit without it.
  Comparison compare(const PlantModel& model) const override;
  std::vector<std::string> validationStems() const override;
  /// Per in-model participant (train, then held out): the RMS standard error of its
  /// lowered rows' prediction errors, ms; `samples` the independent samples their RMS is worth
  /// (floor of SweepParticipantRows::effectiveRows), for the engine's few-sample limit.
  std::vector<NoiseEstimate> estimateRecordNoise() const override;
  std::vector<std::string> warnings() const override { return notes_; }
  /// The participants' whitened rows joined in study order, each in lowering order: a model
  /// that misses the trend with lowering leaves runs of one sign, seen at lag 1.
  ResidualSegments whitenessResidual(const ResidualSegments& likelihoodResidual) const override;

  const std::vector<SweepParticipantRows>& participants() const { return participants_; }
  /// Indices (into participants()) of the participants inside the model.
  const std::vector<std::size_t>& inModel() const { return inModel_; }

  /// Swing times (s) of participant `i` at `lowerings` under `params` (its time scale
  /// calibrated to its standard row first); `timeScale` receives it. NaN where no swing
  /// ended. Throws RunError if the calibration fails.
  std::vector<double> predictSwingTimes(std::size_t i, const SweepModelParams& params,
                                        const std::vector<double>& lowerings, double* timeScale = nullptr) const;

 private:
  struct Prediction {
    double timeScale = 0, swingTimePerScale = 0;
    std::vector<double> times;  ///< s, per lowered row
  };
  /// At the lowered rows (a swing without an end throws RunError), or at `lowerings`
  /// (NaN where a swing has no end).
  Prediction predict(std::size_t i, const SweepModelParams& params, double startScale,
                     const std::vector<double>* lowerings = nullptr) const;
  /// Predictions for every participant in `subset` (in parallel); throws RunError.
  std::vector<Prediction> predictAll(const std::vector<std::size_t>& subset, const SweepModelParams& params) const;
  struct SubsetFit {
    SweepModelParams params;
    std::vector<Prediction> predictions;  ///< by subset position
    Eigen::MatrixXd covariance;           ///< of the fitted shared values (reported units)
    std::vector<std::string> notes;
  };
  /// The fitted shared values of `model` on the participants in `subset`.
  SubsetFit fitSubset(const SweepModelParams& model, const std::vector<std::size_t>& subset) const;
  /// Leave one participant out, into `out` (foldRss, foldResidual, validationRmse,
  /// pooledValidationRmse, notes) and `fitted.heldOutValues`: each fold fits the shared values
  /// (`free`: indices of the fitted ones) on the others' rows; the held-out participant is
  /// calibrated on its own standard row and predicted.
  void addHeldOutFolds(const SubsetFit& full, const std::vector<std::size_t>& free, SweepModelParams& fitted,
                       const SweepModelParams& start, PlantFit& out) const;
  /// One fold's fit of the shared values on `others`: from the full fit's values (`fitted`),
  /// and again from the values the fit started from (`start`) when those fit the fold better;
  /// the better of the two.
  SubsetFit fitFold(const SweepModelParams& fitted, const SweepModelParams& start,
                    const std::vector<std::size_t>& others) const;
  /// The sum of squared whitened residuals of `predictions` (by position in `subset`).
  double calcSubsetRss(const std::vector<std::size_t>& subset, const std::vector<Prediction>& predictions) const;
  /// Participant i's lowered-row residuals (measured - model), whitened (dimensionless).
  std::vector<double> standardized(std::size_t i, const Prediction& p) const;

  std::vector<SweepParticipantRows> participants_;
  std::vector<std::size_t> inModel_;
  std::vector<std::string> notes_;
  std::string measuredPath_;
  int jobs_ = 0;
};

}  // namespace swingsim
