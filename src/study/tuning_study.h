#pragma once
// `kind: knee-tuning` study files (swingsim tune, Python swingsim.tune): a participant, a
// knee model, the knobs with their ranges and the targets; docs/formats.md, docs/tuning.md.
#include <string>
#include <vector>

#include "model/leg_parameters.h"
#include "sweep/knee_tuning.h"
#include "sweep/tuning_chance.h"

namespace swingsim {

/// Knob keys that are not knee model keys: the knee-axis lowering (m), the added shank mass
/// (kg) and its distance below the knee (m).
constexpr const char* kLoweringKnob = "lowering_m";
constexpr const char* kAddedMassKnob = "added_mass_kg";
constexpr const char* kAddedMassDistanceKnob = "added_mass_below_knee_m";

struct TuningStudy {
  std::string path;
  std::string name;             ///< `name:`, the file stem if not given
  std::string description;      ///< free text, not used
  std::string participantPath;  ///< resolved
  std::string kneeModelPath;    ///< resolved; the participant's knee_model if not given
  double lowering = 0;          ///< m, `lowering_m:` where it is not a knob
  AddedMass added;              ///< `added_mass: {mass_kg, below_knee_m}` where not knobs
  std::vector<TuningKnob> knobs;
  std::vector<TuningTarget> targets;
  TuningSettings settings;  ///< start_points, seed (jobs from the caller)
  /// Where the swing-time target came from: "" (a number), or the participant's file and key.
  std::string swingTimeSource;
  /// `uncertainty: {samples, seed}`: the chance of the result meeting every hard limit over the
  /// sweep's assumption ranges (sweep/tuning_chance.h); samples 0 when not asked for.
  TuningChanceOptions chance;
};

/// Reads a `kind: knee-tuning` study: every key checked, each knob tried at both ends of
/// its range through the knee model loader and the leg geometry. Throws InputError
/// (`file:line: key: ...`).
TuningStudy loadTuningStudy(const std::string& path);

}  // namespace swingsim
