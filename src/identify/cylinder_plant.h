#pragma once
// The Mauch cylinder on a bench as a plant of the diagnosis engine (identify/diagnosis_engine.h):
// the model is a MauchCylinderParams; its free parameters are the regression coefficients
// (identify/cylinder_fit.h), refitted with every candidate effect, and the parameters of users'
// expressions (identify/user_cylinder_effect.h), fitted around the regression; the compared quantity is
// the cylinder force (N); phases are the model's dominant gates (Chien 2014 Eqs. 2-11).
#include <string>
#include <vector>

#include "identify/bench_data.h"
#include "identify/cylinder_fit.h"
#include "identify/diagnosis_engine.h"
#include "knee/mauch_cylinder.h"
#include "numerics/bounded_least_squares.h"

namespace swingsim {

/// A cylinder model as the engine carries it.
class CylinderModel final : public PlantModel {
 public:
  explicit CylinderModel(MauchCylinderParams params) : params(std::move(params)) {}
  CylinderModel(MauchCylinderParams params, bool switchesFree, bool latchFree)
      : params(std::move(params)), switchesFree(switchesFree), latchFree(latchFree) {}
  MauchCylinderParams params;
  /// Set by CylinderPlant::refitAccepted: every later fit of this model (and of the models
  /// built on it) keeps the switch widths and xhy, and with latchFree the latch rate, free.
  bool switchesFree = false;
  bool latchFree = false;
};
/// The parameters inside an engine model of the cylinder plant.
const MauchCylinderParams& cylinderParams(const PlantModel& model);

/// `params` with `effect` switched on (its linear coefficients 0 until fitted) and its grid
/// parameter (Coulomb width m/s, latch time constant s) set to `gridValue`.
MauchCylinderParams addCylinderEffect(const MauchCylinderParams& params, EffectId effect, double gridValue);
/// Whether `effect` can be added to `params` ("" if so, else why not).
std::string checkCylinderEffectApplicable(const MauchCylinderParams& params, EffectId effect);
/// Names of a model's phases, by gate index ("stance flexion", ..., "hyperextension").
std::vector<std::string> cylinderPhaseNames(const MauchCylinderParams& params);
/// Force RMS (N) of `effect` in `truth` along a record: truth minus truth without the effect
/// (switch_delay: minus the model with Chien's k = 1e4 /s). The "effect size" of a hidden effect.
double calcCylinderEffectRms(const MauchCylinderParams& truth, EffectId effect, const BenchData& record);

class CylinderPlant final : public DiagnosisPlant {
 public:
  /// `fitSwitches`: refit the switch widths and xhy before the baseline (as `swingsim fit`).
  /// `plotSeconds`: span of each record shown in residual-vs-time plots. Throws RunError as
  /// fitCylinder.
  CylinderPlant(const MauchCylinderParams& base, std::vector<BenchData> train, std::vector<BenchData> validate,
                bool fitSwitches = false, double plotSeconds = 2.0);

  PlantKind kind() const override { return PlantKind::kCylinder; }
  PlantModelPtr baseModel() const override;
  PlantFit fit(const PlantModel& model) const override;
  std::string checkApplicable(const PlantModel& model, EffectId effect) const override;
  PlantModelPtr addEffect(const PlantModel& model, EffectId effect, double gridValue) const override;
  PlantModelPtr combine(const PlantModel& a, const PlantModel& b, EffectId effectOfB) const override;
  std::vector<double> effectValues(const PlantModel& model, EffectId effect) const override;
  bool checkPhysical(const PlantModel& model, EffectId effect, std::string& note) const override;
  std::vector<std::string> phaseNames(const PlantModel& model) const override;
  Comparison compare(const PlantModel& model) const override;
  std::vector<std::string> validationStems() const override;
  /// Noise of the measured force of every record (N).
  std::vector<NoiseEstimate> estimateRecordNoise() const override;
  std::vector<std::string> warnings() const override { return warnings_; }
  /// Every record's stem, training then held out; a plant with one of them as its only
  /// training record (from this plant's start model, its switch constants as fitted), for the
  /// record-agreement rule.
  std::vector<std::string> recordStems() const override;
  std::unique_ptr<DiagnosisPlant> withOnlyRecord(std::size_t index) const override;
  /// The missing force along every record, training and held out (identify/missing_force.h).
  std::optional<MissingForce> calcMissingForce(const PlantModel& model) const override;
  /// After switch_delay or hyperextension_phase is accepted: one joint fit of every
  /// coefficient, the switch widths, xhy and (with a slow latch) the latch rate, within their
  /// ranges, from the candidate's solution and from the multi-start grid (the better one);
  /// whatever the study's fit_switches. hyperextension_phase on a 2-phase model is also
  /// refitted as the model it produces, Chien's 4-phase model (the low-force phase split
  /// into swing flexion and extension), kept if the split passes the acceptance rule's test
  /// (3 more coefficients) and lowers every held-out RMSE. The freed switch constants are
  /// reported as the fit's base parameters, with the joint covariance's standard errors.
  /// Other effects are linear: their candidate fit is already joint.
  PlantFit refitAccepted(const PlantFit& candidate, EffectId effect) const override;
  /// The training RSS of `fitted` refitted with the switch constant `parameter` (a
  /// base-parameter name of refitAccepted) held at `value`, the other constants polished.
  std::optional<double> calcHeldParameterRss(const PlantModel& fitted, const std::string& parameter,
                                             double value) const override;

 private:
  /// A fitted model as the engine takes it: residuals, held-out RMSE, named constants.
  PlantFit summarize(const CylinderFit& fitted) const;
  /// The joint fit of refitAccepted for one model structure.
  PlantFit fitJointly(const MauchCylinderParams& params, bool fitLatchRate) const;

  MauchCylinderParams start_;
  std::vector<BenchData> train_, validate_;
  double plotSeconds_;
  bool fitSwitches_ = false;
  std::vector<std::string> warnings_;
};

}  // namespace swingsim
