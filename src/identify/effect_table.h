#pragma once
// The library of candidate physical effects that `swingsim diagnose` can add to a model,
// seen the same way for every plant: one descriptor per effect. A descriptor says which plant
// the effect belongs to, its parameters with units, the profiled grid of its non-linear
// parameter, and the sentences the report prints. Each descriptor is the first part of its
// effect's one record, beside what the plant needs of it (identify/cylinder_effects.cpp,
// identify/swing_effects.cpp, identify/sweep_effects.cpp); effectTable() gathers them, and
// everything else (CLI, report, JSON, study YAML) reads that table. Adding an effect: its id
// below, its record, its test (and its law, if the plant has no law it can reuse).
#include <string>
#include <vector>

namespace swingsim {

/// The kinds of model the diagnosis runs on.
enum class PlantKind {
  kCylinder,  ///< the Mauch hydraulic cylinder on a bench (force vs piston motion)
  kSwing,     ///< the swing of a prosthetic leg (knee and hip angles vs time)
  kSweep,     ///< the knee-axis sweep (swing time vs lowering, per participant)
};

/// Every effect of the library.
enum class EffectId {
  // Cylinder bench (Chien 2014 and its discussion).
  kCoulombFriction,
  kOrificeQuadratic,
  kInertia,
  kPositionDependentDamping,
  kHyperextensionPhase,
  kSwitchDelay,
  // Swing (Burkett 2004 and its assumptions).
  kKneeCoulombFriction,
  kKneeViscousDamping,
  kExtensionAssistSpring,
  kToeOffVelocity,
  kHipMomentScale,
  kShankMassScale,
  kBelowKneeMassScale,
  kSocketCompliance,
  // Sweep (Burkett 2004's unpublished assumptions, sweep/sweep_assumptions.h), each one
  // value shared by every participant.
  kHipEffortAdaptation,
  kHipTempoLowering,
  kComRuleProportional,
  kKneeFrictionScale,
  kStopRestitution,
  kStopStiffness,
  kHipExtensionRatio,
  kHipFlexionDuration,
  kHipExtensionDuration,
  kThighTargetFlexion,
};

/// One candidate effect.
struct EffectDescriptor {
  EffectId id;
  PlantKind plant;
  std::string name;         ///< key in study YAML, reports and JSON: "coulomb_friction"
  std::string sentence;     ///< what it is, for a user
  std::string mechanism;    ///< where it comes from (paper, or the assumption it relaxes)
  std::string separatedBy;  ///< data that tell it apart from the others
  /// Reported parameters, each name with its unit ("force_N"): the continuously fitted ones
  /// first, then the profiled grid parameter if the effect has one.
  std::vector<std::string> parameters;
  int fittedParameters = 0;  ///< continuously fitted parameters (the first ones above)
  /// Values of the non-linear parameter, fixed before any data are seen and profiled (best
  /// training fit); SI units. Empty: no grid parameter.
  std::vector<double> grid;
  double gridReportScale = 1.0;   ///< a grid value times this is its reported value
  bool participantLevel = false;  ///< saved into the participant, not the knee model
  /// Parameters the likelihood-ratio test counts: the fitted ones, plus one for a grid.
  int degreesOfFreedom() const { return fittedParameters + (grid.empty() ? 0 : 1); }
};

/// The first id of a user's effect (an expression, identify/user_swing_effect.h): ids from
/// here on are given out at run time by registerUserEffect.
constexpr int kFirstUserEffectId = 1000;
/// Whether `id` is a user's effect rather than the library's.
inline bool isUserEffect(EffectId id) { return static_cast<int>(id) >= kFirstUserEffectId; }
/// Registers a user's effect (its descriptor's id is ignored) and returns its id: the same
/// id for a descriptor registered before with the same name, sentence and parameters, a new
/// one otherwise. Thread-safe; registered descriptors live as long as the process.
EffectId registerUserEffect(EffectDescriptor descriptor);

/// The whole library, cylinder effects first, in a fixed order.
const std::vector<EffectDescriptor>& effectTable();
/// The descriptor of an effect (the library's or a registered user's).
const EffectDescriptor& describeEffect(EffectId id);
/// Names of the effects of one plant, in table order.
std::vector<std::string> effectNames(PlantKind plant);
/// The effect of `plant` called `name`: the library's, else the user's effect registered last
/// under that name; nullptr if there is none.
const EffectDescriptor* findEffect(PlantKind plant, const std::string& name);
/// Short name of a plant for messages and JSON: "cylinder", "swing".
std::string plantName(PlantKind plant);

}  // namespace swingsim
