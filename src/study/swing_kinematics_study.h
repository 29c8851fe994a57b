#pragma once
// Study YAML `kind: swing-kinematics` (swingsim generate): synthetic swing measurements from
// a participant and knee model, with optional hidden effects and noise (docs/diagnosis.md),
// read and written through one description of its fields (io/yaml_archive.h).
#include <cstdint>
#include <string>
#include <vector>

#include "identify/swing_plant.h"
#include "identify/synthetic_swing.h"

namespace swingsim {

class YamlMap;

/// One block of `hidden_effects:`: a swing effect of the library (its key is the effect's
/// name) with its values, read and written by the effect's own record (identify/swing_effects.h):
/// the descriptor's parameters as keys, in their reported units, checked against the
/// record's physical bounds. An absent grid parameter takes the grid's middle value.
struct SwingHiddenEffect {
  bool present = false;
  std::vector<double> values;  ///< the descriptor's parameters, reported units (deg/s for a rate)
};

/// `hidden_effects:`: effects the truth has and the base model lacks, one block per library
/// swing effect, in the effect table's order.
struct SwingHiddenEffects {
  std::vector<SwingHiddenEffect> effects;  ///< as read: one per library swing effect (none before)
  /// The value of `parameter` (a descriptor's parameter name) of the effect `name`; NaN if
  /// that effect is not hidden. Throws std::invalid_argument for an unknown name or parameter.
  double value(const std::string& name, const std::string& parameter) const;
  /// Whether the effect `name` is hidden.
  bool has(const std::string& name) const;
};

struct SwingKinematicsStudy {
  std::string path;
  std::string name, description;           ///< free text, not used
  std::string participantPath, modelPath;  ///< resolved
  SwingBase base;                          ///< the participant and knee model, loaded
  double noiseDeg = 0;                     ///< angle noise standard deviation, deg (makeSyntheticSwing's unit)
  std::uint64_t seed = 1;                  ///< condition i uses seed + i
  double sampleInterval = 0.002;           ///< s
  std::string outputDir;                   ///< resolved
  std::vector<SwingCondition> conditions;
  bool hasHiddenEffects = false;
  SwingHiddenEffects hidden;
};

/// Reads the keys of a swing-kinematics study (`kind` already read), loading its participant
/// and knee model, and finishes the map. Throws InputError.
SwingKinematicsStudy readSwingKinematicsStudy(YamlMap& yaml);

/// The YAML text of a study; paths relative to `baseDir` where they lie below it.
std::string formatSwingKinematicsStudyYaml(const SwingKinematicsStudy& study, const std::string& baseDir);

/// The truth model: the hidden effects added in the file format's order; their names (the
/// YAML keys) into `names`.
SwingModelParams makeHiddenTruth(const SwingHiddenEffects& hidden, std::vector<std::string>& names);

}  // namespace swingsim
