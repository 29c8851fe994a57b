#pragma once
// Model vs measurement for the swing (issue 5, docs/diagnosis.md "The swing"): measured hip
// and knee angles after toe-off, driven by the measured hip moment. `compareSwing` says where
// the model fails (knee RMSE per swing phase), `diagnoseSwing` ranks candidate missing
// effects with the shared statistics of fit/effect_selection.h. Every refit runs the fast
// independent reference integrator (ReferenceSwing); docs/diagnosis.md lists the decisions.
#include <string>
#include <vector>

#include "identify/effect_selection.h"
#include "numerics/metrics.h"
#include "model/knee_model.h"
#include "model/swing_record.h"
#include "knee/knee_added_effects.h"
#include "model/leg_parameters.h"

namespace swingsim {


/// One candidate effect of the swing library.
struct SwingEffectInfo {
  std::string name, sentence, mechanism, separatedBy;
  bool participantLevel = false;  ///< belongs to the participant (saved in a participant YAML), not the knee
};
/// knee_coulomb_friction, knee_viscous_damping, extension_assist_spring, toe_off_velocity,
/// hip_moment_scale, shank_mass_scale.
const std::vector<SwingEffectInfo>& swingEffectLibrary();
/// Throws std::invalid_argument for a name not in the library.
const SwingEffectInfo& findSwingEffect(const std::string& name);
/// Friction tanh smoothing grid (rad/s), fixed before any data; profiled, never optimised.
const std::vector<double>& kneeFrictionSmoothingGrid();

/// The swing effects of a model (off = absent).
struct SwingEffects {
  bool coulomb = false, viscous = false, assist = false, toeOff = false, hipScale = false, shankScale = false;
  KneeAddedEffectsParams knee;                   ///< friction, damping, spring values
  double toeOffHipRate = 0, toeOffKneeRate = 0;  ///< rad/s at toe-off
  double hipMomentScale = 1;                     ///< multiplies the measured hip moment
  double shankMassScale = 1;                     ///< multiplies shank mass and inertia
  bool has(const std::string& effect) const;
};

/// The swing model: participant + knee model, with its free parameters.
struct SwingModelParams {
  /// The base model's free parameter: a scale on the knee model's resisting law (the
  /// damping table or cylinder; not the stop, not Tc). Burkett's damping table is an
  /// assumption, so a user rarely knows it; refitted with every candidate.
  double kneeModelScale = 1.0;
  SwingEffects effects;
};

/// Everything fixed: the participant (geometry, Tc, hip range, zone of stability) and the
/// knee model.
struct SwingBase {
  Participant participant;
  KneeModel knee;
};

/// `params` with `effect` switched on (value 0 or scale 1; `nonlinear`: the friction
/// smoothing, rad/s).
SwingModelParams addSwingEffect(const SwingModelParams& params, const std::string& effect, double nonlinear);
/// The named parameters of an effect (deg/s for rates).
std::vector<EffectParameter> getSwingEffectParameters(const SwingModelParams& params, const std::string& effect);

/// Knee law of the model: scaled model law + added effects + stop + participant Tc.
KneeLawSum makeSwingKneeLaw(const SwingBase& base, const SwingModelParams& params);
/// The participant with the participant-level effects applied (shank mass and inertia,
/// toe-off rates, hip moment profile amplitude).
Participant applyParticipantEffects(const Participant& participant, const SwingEffects& effects);

/// Model hip and knee flexion (rad) at the record's times from toe-off pose `pose`
/// (hip, knee rad), driven by the record's hip moment. Throws RunError if the integration fails.
struct SwingPrediction {
  std::vector<double> hipFlexion, kneeFlexion, kneeFlexionRate;
};
/// `tolerance`: the reference integrator's relative and absolute tolerance.
SwingPrediction predictSwing(const SwingBase& base, const SwingModelParams& params, const SwingRecord& record,
                             double hipPose, double kneePose, double tolerance = 1e-8);

/// Phases from the swing events of the model's knee: early flexion (toe-off to peak knee
/// flexion), late extension (peak to entering the zone of stability), terminal/stop contact.
std::vector<std::string> swingPhaseNames();

struct SwingRecordComparison {
  const SwingRecord* data = nullptr;
  bool training = false;
  double hipPose = 0, kneePose = 0;            ///< fitted toe-off pose, rad
  std::vector<double> predictedKnee, predictedHip;  ///< rad
  std::vector<double> kneeResidual, hipResidual;    ///< measured - model, deg
  std::vector<double> kneeRate;                ///< model knee flexion rate, deg/s
  std::vector<int> phase;
  ErrorMetrics knee, hip;                      ///< deg
  std::vector<ErrorMetrics> perPhase;          ///< knee, deg
  std::vector<double> phaseShare, sampleShare;
};
struct SwingComparison {
  std::vector<std::string> phaseNames;
  std::vector<SwingRecordComparison> records;  ///< training files first
};

/// Runs `params` along every file; the toe-off pose of each file is fitted (the only thing
/// fitted here: a nuisance, measured with noise).
SwingComparison compareSwing(const SwingBase& base, const SwingModelParams& params, const std::vector<SwingRecord>& train,
                             const std::vector<SwingRecord>& validate);

struct SwingDiagnosisSettings : EffectSelectionSettings {
  double integratorTolerance = 1e-8;  ///< reference integrator relative and absolute tolerance
};

struct SwingCandidateScore : EffectScore {
  SwingModelParams params;
};
struct SwingDiagnosisStep {
  double currentTrainRmse = 0;
  std::vector<double> currentValidationRmse;
  std::vector<SwingCandidateScore> candidates;
  int chosen = -1;
  std::vector<std::string> group;
};

struct SwingDiagnosis {
  SwingModelParams baseline, final;
  double baselineScaleLower = 0, baselineScaleUpper = 0;  ///< 95 % CI of the knee model scale
  std::vector<SwingDiagnosisStep> steps;
  std::vector<std::string> accepted;
  std::vector<SwingCandidateScore> acceptedScores;
  std::vector<std::vector<std::string>> ambiguous;
  std::vector<std::string> ambiguityAdvice;
  WhitenessTest baselineWhiteness, finalWhiteness;
  bool finalResidualWhite = true;
  std::string structureNote;
};

/// Forward stepwise diagnosis (knee model scale and every accepted effect refitted with
/// each candidate, toe-off poses per file as nuisance parameters). The likelihood uses the
/// hip and knee residuals (deg) of the training files; validation RMSE is knee flexion.
/// Throws InputError (unknown candidate, no validation file), RunError (a swing fails).
SwingDiagnosis diagnoseSwing(const SwingBase& base, const std::vector<SwingRecord>& train,
                             const std::vector<SwingRecord>& validate, const SwingDiagnosisSettings& settings = {});

/// Knee flexion RMS (deg) of `effect` in `truth` along a record: truth minus truth without
/// it, same pose. The "effect size" of issue 5.
double calcSwingEffectRms(const SwingBase& base, const SwingModelParams& truth, const std::string& effect,
                          const SwingRecord& record);

}  // namespace swingsim
