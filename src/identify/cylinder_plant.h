#pragma once
// The Mauch cylinder on a bench as a plant of the diagnosis engine (identify/diagnosis_engine.h):
// the model is a MauchCylinderParams; its free parameters are the regression coefficients
// (identify/cylinder_fit.h), refitted with every candidate effect; the compared quantity is
// the cylinder force (N); phases are the model's dominant gates (Chien 2014 Eqs. 2-11).
#include <string>
#include <vector>

#include "identify/bench_data.h"
#include "identify/cylinder_fit.h"
#include "identify/diagnosis_engine.h"
#include "knee/mauch_cylinder.h"

namespace swingsim {

/// A cylinder model as the engine carries it.
class CylinderModel final : public PlantModel {
 public:
  explicit CylinderModel(MauchCylinderParams params) : params(std::move(params)) {}
  MauchCylinderParams params;
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

 private:
  MauchCylinderParams start_;
  std::vector<BenchData> train_, validate_;
  double plotSeconds_;
  bool fitSwitches_ = false;
  std::vector<std::string> warnings_;
};

}  // namespace swingsim
