#pragma once
// Study YAML for the Mauch cylinder: `kind: cylinder-bench` (swingsim generate) and
// `kind: cylinder-fit` (swingsim fit), read and written through one description of their
// fields (io/yaml_archive.h). Paths are relative to the study file.
#include <cstdint>
#include <string>
#include <vector>

#include "knee/bench_profile.h"
#include "knee/mauch_cylinder.h"

namespace swingsim {

class YamlMap;

/// One bench condition (a walking speed).
struct BenchCondition {
  std::string name;             ///< output file stem: slow, normal, fast
  double strideTime = 0.987;    ///< s
  double amplitudeScale = 1.0;  ///< multiplies the knee angles
};

/// `kind: cylinder-bench`: synthetic bench records from a cylinder model.
struct CylinderBenchStudy {
  std::string path;
  std::string name;            ///< `name:`, the file stem if not given
  std::string description;     ///< free text, not used
  std::string modelPath;       ///< knee model YAML (kind: mauch): the truth
  std::string kneeAnglesPath;  ///< Winter-style CSV (frame, knee_deg)
  int strideFirstFrame = 28;   ///< heel strike
  int strideLastFrame = 97;    ///< next heel strike
  BenchProfileParams profile;  ///< shared settings (stride time and scale per condition)
  std::vector<BenchCondition> conditions;
  double noise = 0;        ///< force noise standard deviation, N
  std::uint64_t seed = 1;  ///< condition i uses seed + i
  std::string outputDir;   ///< where the CSVs go (absolute, resolved)
  /// Optional `hidden_effects:`: effects added to the truth model, in the model
  /// YAML's `effects:` format, plus `switch_delay: {time_constant_s}` (the S2 latch 1/k).
  MauchAddedEffects hiddenEffects;
  double hiddenLatchTimeConstant = 0;  ///< s; 0 = the model's own latch rate
};

/// Reads the keys of a cylinder-bench study (`kind` already read). Throws InputError.
CylinderBenchStudy readCylinderBenchStudy(YamlMap& yaml);

/// `kind: cylinder-fit`: fit cylinder models to bench files, validate on others.
struct CylinderFitStudy {
  std::string path;
  std::string name;                   ///< `name:`, the file stem if not given
  std::string description;            ///< free text, not used
  std::vector<std::string> models;    ///< model YAML paths (resolved)
  std::vector<std::string> train;     ///< bench CSV paths (resolved)
  std::vector<std::string> validate;  ///< bench CSV paths (resolved)
  bool fitSwitches = false;
  double plotSeconds = 2.0;  ///< time span shown in the force plots, s
};

/// Reads the keys of a cylinder-fit study (`kind` already read). Throws InputError.
CylinderFitStudy readCylinderFitStudy(YamlMap& yaml);
/// Reads a `kind: cylinder-fit` study file (`swingsim fit`, Python `swingsim.fit`): the
/// kind checked, every key read, unknown keys refused. Throws InputError.
CylinderFitStudy loadCylinderFitStudy(const std::string& path);

/// The YAML text of a study; paths relative to `baseDir` (the folder it will be saved in)
/// where they lie below it, else absolute.
std::string formatCylinderBenchStudyYaml(const CylinderBenchStudy& study, const std::string& baseDir);
std::string formatCylinderFitStudyYaml(const CylinderFitStudy& study, const std::string& baseDir);

}  // namespace swingsim
