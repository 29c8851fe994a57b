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

/// `hidden_effects:`: effects the truth has and the base model lacks; a flag per block
/// (present in the file) and its values.
struct SwingHiddenEffects {
  bool kneeCoulombFriction = false;
  double coulombMoment = 0;         ///< N m
  double coulombSmoothingRate = 1;  ///< rad/s (smoothing_deg_s in the file)
  bool kneeViscousDamping = false;
  double viscousDamping = 0;        ///< N m s/rad
  bool extensionAssistSpring = false;
  double assistStiffness = 0;       ///< N m/rad
  bool toeOffVelocity = false;
  double toeOffHipRate = 0, toeOffKneeRate = 0;  ///< rad/s (deg/s in the file)
  bool hipMomentScale = false;
  double hipScale = 1;
  bool shankMassScale = false;
  double shankScale = 1;
  bool belowKneeMassScale = false;
  double belowKneeScale = 1;
};

struct SwingKinematicsStudy {
  std::string path;
  std::string name, description;   ///< free text, not used
  std::string participantPath, modelPath;  ///< resolved
  SwingBase base;                  ///< the participant and knee model, loaded
  double noiseDeg = 0;             ///< angle noise standard deviation, deg (makeSyntheticSwing's unit)
  std::uint64_t seed = 1;          ///< condition i uses seed + i
  double sampleInterval = 0.002;   ///< s
  std::string outputDir;           ///< resolved
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
