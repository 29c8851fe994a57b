#pragma once
// The swing of a prosthetic leg as a plant of the diagnosis engine
// (identify/diagnosis_engine.h): measured hip and knee angles after toe-off, driven by the
// measured hip moment. The model is a SwingModelParams on a fixed SwingBase (participant and
// knee model); its free parameters are a scale on the knee model's law, every added effect's
// parameters and the toe-off pose of each training record (a nuisance, measured with noise).
// Every refit runs the fast independent reference integrator (swing/reference_swing.h);
// compared quantity: knee flexion (deg); the likelihood uses hip and knee residuals.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "identify/diagnosis_engine.h"
#include "identify/swing_model.h"
#include "knee/knee_added_effects.h"
#include "leg/hip_path.h"
#include "leg/thigh_motion.h"
#include "model/knee_model.h"
#include "model/leg_parameters.h"
#include "model/swing_record.h"
#include "numerics/bounded_least_squares.h"

namespace swingsim {

/// A swing model as the engine carries it.
using SwingModel = PlantModelOf<SwingModelParams>;
/// The parameters inside an engine model of the swing plant.
const SwingModelParams& swingParams(const PlantModel& model);

class SwingPlant final : public DiagnosisPlant {
 public:
  /// `tolerance`: the reference integrator's relative and absolute tolerance in every refit.
  SwingPlant(SwingBase base, std::vector<SwingRecord> train, std::vector<SwingRecord> validate,
             double tolerance = 1e-8);

  PlantKind kind() const override { return PlantKind::kSwing; }
  PlantModelPtr baseModel() const override;
  PlantFit fit(const PlantModel& model) const override;
  std::string checkApplicable(const PlantModel& model, EffectId effect) const override;
  PlantModelPtr addEffect(const PlantModel& model, EffectId effect, double gridValue) const override;
  PlantModelPtr combine(const PlantModel& a, const PlantModel& b, EffectId effectOfB) const override;
  std::vector<double> effectValues(const PlantModel& model, EffectId effect) const override;
  bool checkPhysical(const PlantModel& model, EffectId effect, std::string& note) const override;
  std::vector<std::string> phaseNames(const PlantModel&) const override { return swingPhaseNames(); }
  Comparison compare(const PlantModel& model) const override;
  std::vector<std::string> validationStems() const override;
  /// Noise of the measured knee flexion of every record (deg).
  std::vector<NoiseEstimate> estimateRecordNoise() const override;
  /// The model once more with Simbody (simulateSwing) along every record at its fitted pose:
  /// the largest knee difference to the reference integrator the refits used.
  std::string verify(const PlantModel& model) const override;
  /// The missing knee moment over every record (training and held out), each smoothed around
  /// the model's own swing along it (identify/missing_moment.h).
  std::optional<MissingMoment> calcMissing(const PlantModel& model) const override;
  /// The model's knee moment along every record that has a measured one (knee_moment_Nm,
  /// e.g. from inverse dynamics; never fitted) against it.
  std::optional<HeldBackComparison> compareHeldBack(const PlantModel& model) const override;
  /// The fit with knee_model_scale held at `value` (its profile likelihood); nullopt for any
  /// other parameter.
  std::optional<double> calcHeldParameterRss(const PlantModel& fitted, const std::string& parameter,
                                             double value) const override;
  std::vector<std::string> warnings() const override { return base_.notes; }
  std::vector<std::string> recordStems() const override;
  std::unique_ptr<DiagnosisPlant> withOnlyRecord(std::size_t index) const override;

  const SwingBase& base() const { return base_; }

 private:
  /// fit(), with the knee model scale held at `heldScale` when given (not a free parameter).
  PlantFit fitWith(const PlantModel& model, std::optional<double> heldScale) const;
  /// Toe-off state of one record with the model frozen: (hip angle, knee angle), or under
  /// the thigh drive (knee rate, knee angle); and the prediction there.
  struct PoseFit {
    double first = 0, knee = 0;
    SwingPrediction prediction;
  };
  PoseFit fitPose(const SwingModelParams& params, std::size_t record) const;
  const SwingRecord& record(std::size_t i) const {
    return i < train_.size() ? train_[i] : validate_[i - train_.size()];
  }
  const ThighMotion* thighOf(std::size_t i) const { return thighs_.empty() ? nullptr : &thighs_[i]; }
  const HipPath* hipOf(std::size_t i) const { return hips_.empty() || !hips_[i] ? nullptr : &*hips_[i]; }
  /// Free toe-off parameters of record i and their residual rows.
  std::vector<BoundedParameter> poseParameters(std::size_t i) const;
  void appendResiduals(const SwingRecord& r, const SwingPrediction& p, Eigen::VectorXd& res, Eigen::Index& row) const;
  std::size_t rowsPerSample() const { return base_.drive == SwingDrive::kThighKinematics ? 1 : 2; }

  SwingBase base_;
  std::vector<SwingRecord> train_, validate_;
  std::vector<ThighMotion> thighs_;           ///< thigh drive: each record's hip spline, train then validate
  std::vector<std::optional<HipPath>> hips_;  ///< thigh drive: each record's hip path (nullopt: fixed hip)
  double tolerance_;
};

}  // namespace swingsim
