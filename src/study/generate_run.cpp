#include "study/generate_run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <vector>

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/output_paths.h"
#include "core/units.h"
#include "identify/bench_data.h"
#include "identify/synthetic_swing.h"
#include "io/bench_csv.h"
#include "io/csv_table.h"
#include "io/knee_model_loader.h"
#include "io/swing_record_csv.h"
#include "io/yaml_reader.h"
#include "knee/bench_profile.h"
#include "study/cylinder_study.h"
#include "study/swing_kinematics_study.h"

namespace swingsim {

namespace {

// kind: cylinder-bench. Everything is computed before the first file is written. `outDir`:
// --out, if given.
void generateCylinderBench(YamlMap& yaml, const std::optional<std::string>& outDir) {
  CylinderBenchStudy study = readCylinderBenchStudy(yaml);
  yaml.finish();
  if (outDir)
    study.outputDir = *outDir;
  else
    checkOutputFolder(study.outputDir, study.path + ": output_dir");  // before any work
  MauchCylinderParams truthParams = loadMauchCylinder(study.modelPath);
  // Hidden effects: the truth gets them, the fitted models do not know.
  truthParams.effects = study.hiddenEffects;
  if (study.hiddenLatchTimeConstant > 0) truthParams.switches.latchRate = 1.0 / study.hiddenLatchTimeConstant;
  MauchCylinder truth = [&] {
    try {
      return MauchCylinder(truthParams);
    } catch (const std::invalid_argument& e) {
      throw InputError(study.path + ": hidden_effects: " + e.what());
    }
  }();
  const KneeAngleStride stride =
      readKneeAngleStride(study.kneeAnglesPath, study.strideFirstFrame, study.strideLastFrame);

  std::vector<std::pair<std::string, std::string>> files;
  const bool hidden = study.hiddenEffects.any() || study.hiddenLatchTimeConstant > 0;
  const MauchCylinder plain(loadMauchCylinder(study.modelPath));
  std::printf("%-8s %8s %9s %8s %10s %10s %10s%s\n", "file", "stride_s", "amplitude", "samples", "x_min_mm", "x_max_mm",
              "F_rms_N", hidden ? "  hidden_rms_N" : "");
  for (std::size_t i = 0; i < study.conditions.size(); ++i) {
    const auto& c = study.conditions[i];
    BenchProfileParams p = study.profile;
    p.strideTime = c.strideTime;
    p.amplitudeScale = c.amplitudeScale;
    BenchProfile profile;
    try {
      profile = makeBenchProfile(stride, p, truth.geometry());
    } catch (const std::invalid_argument& e) {
      throw InputError(study.path + ": conditions[" + std::to_string(i) + "] (" + c.name + "): " + e.what());
    }
    const auto velocity = estimatePistonVelocity(profile.time, profile.position);
    auto force = calcCylinderTrace(truth, profile.time, profile.position, velocity, 0.0).force;
    double hiddenSq = 0;  // force of the hidden effects: truth minus the model without them
    if (hidden) {
      const auto plainForce = calcCylinderTrace(plain, profile.time, profile.position, velocity, 0.0).force;
      for (std::size_t k = 0; k < force.size(); ++k)
        hiddenSq += (force[k] - plainForce[k]) * (force[k] - plainForce[k]);
    }
    NormalNoise noise(study.seed + i);
    double sumSq = 0;
    for (double& f : force) {
      f += study.noise * noise.next();
      sumSq += f * f;
    }
    files.emplace_back(study.outputDir + "/" + c.name + ".csv",
                       formatCsv({"time_s", "position_m", "force_N"}, {profile.time, profile.position, force}));
    double xmin = 1e9, xmax = -1e9;
    for (double x : profile.position) {
      xmin = std::min(xmin, x);
      xmax = std::max(xmax, x);
    }
    std::printf("%-8s %8.3f %9.3f %8zu %10.3f %10.3f %10.1f", c.name.c_str(), c.strideTime, c.amplitudeScale,
                profile.time.size(), 1e3 * xmin, 1e3 * xmax, std::sqrt(sumSq / static_cast<double>(force.size())));
    if (hidden) std::printf("  %12.1f", std::sqrt(hiddenSq / static_cast<double>(force.size())));
    std::printf("\n");
  }
  std::vector<CommandFile> outputs;
  for (const auto& file : files) outputs.push_back({"STUDY.yaml: output_dir (or --out)", file.first});
  checkOutputsAreNotInputs({{"STUDY.yaml", study.path}, {"STUDY.yaml: model", study.modelPath}}, outputs);
  for (const auto& [path, text] : files) writeFileAtomic(path, text);
  std::printf("wrote %zu bench files to %s (truth %s, noise %s N, seed %llu)\n", files.size(), study.outputDir.c_str(),
              truth.name().c_str(), formatNumber(study.noise).c_str(), static_cast<unsigned long long>(study.seed));
}

// kind: swing-kinematics: synthetic swing measurements from a participant and knee model,
// with optional hidden effects and noise (docs/diagnosis.md).
void generateSwingKinematics(YamlMap& yaml, const std::optional<std::string>& outDirGiven) {
  const SwingKinematicsStudy study = readSwingKinematicsStudy(yaml);
  const SwingBase& base = study.base;
  const std::vector<SwingCondition>& conditions = study.conditions;
  const double noise = study.noiseDeg, interval = study.sampleInterval;
  const std::string outDir = outDirGiven.value_or(study.outputDir);
  if (!outDirGiven) checkOutputFolder(outDir, study.path + ": output_dir");  // before any work
  std::vector<std::string> hiddenNames;
  const SwingModelParams truth = makeHiddenTruth(study.hidden, hiddenNames);
  const std::uint64_t seed = study.seed;
  std::vector<std::pair<std::string, std::string>> files;
  std::printf("%-8s %8s %9s %8s %10s %14s%s\n", "file", "tau_x", "amplitude", "samples", "swing_s", "peak_knee_deg",
              hiddenNames.empty() ? "" : "  hidden_knee_rms_deg");
  for (std::size_t i = 0; i < conditions.size(); ++i) {
    const auto& c = conditions[i];
    SwingRecord r = makeSyntheticSwing(base, truth, c, noise, seed + i, interval);
    // A synthetic record is sampled from toe-off on: never empty.
    const double peak = *std::max_element(r.kneeFlexion.begin(), r.kneeFlexion.end()) * kRadToDeg;
    std::printf("%-8s %8.3f %9.3f %8zu %10.3f %14.1f", c.name.c_str(), c.timeScale, c.amplitudeScale, r.time.size(),
                r.time.back(), peak);
    if (!hiddenNames.empty()) {
      // The hidden effects alone along this condition: noiseless truth minus the plain model.
      SwingModelParams plain;
      const SwingRecord clean = makeSyntheticSwing(base, truth, c, 0.0, 0, interval);
      const SwingRecord none = makeSyntheticSwing(base, plain, c, 0.0, 0, interval);
      double s = 0;
      const std::size_t n = std::min(clean.time.size(), none.time.size());
      for (std::size_t k = 0; k < n; ++k) s += std::pow((clean.kneeFlexion[k] - none.kneeFlexion[k]) * kRadToDeg, 2);
      std::printf("  %19.2f", std::sqrt(s / static_cast<double>(n)));
    }
    std::printf("\n");
    files.emplace_back(outDir + "/" + c.name + ".csv", formatSwingRecordCsv(r));
  }
  std::vector<CommandFile> outputs;
  for (const auto& file : files) outputs.push_back({"STUDY.yaml: output_dir (or --out)", file.first});
  checkOutputsAreNotInputs({{"STUDY.yaml", study.path}}, outputs);
  for (const auto& [path, text] : files) writeFileAtomic(path, text);
  std::printf("wrote %zu swing kinematics files to %s (participant %s, knee %s, noise %s deg, seed %llu)\n",
              files.size(), outDir.c_str(), base.participant.name.c_str(), base.knee.name.c_str(),
              formatNumber(noise).c_str(), static_cast<unsigned long long>(seed));
}

using Generator = std::function<void(YamlMap&, const std::optional<std::string>& outDir)>;

const std::map<std::string, Generator>& generators() {
  static const std::map<std::string, Generator> g = {{"cylinder-bench", generateCylinderBench},
                                                     {"swing-kinematics", generateSwingKinematics}};
  return g;
}

}  // namespace

void runGenerate(const std::string& studyPath, const std::optional<std::string>& outDir) {
  YamlMap yaml = YamlMap::loadFile(studyPath);
  std::vector<std::string> kinds;
  for (const auto& kv : generators()) kinds.push_back(kv.first);
  if (!yaml.has("kind")) yaml.getString("kind");  // "required key is missing"
  const std::string kind = yaml.getChoice("kind", kinds, "");
  generators().at(kind)(yaml, outDir);
}

}  // namespace swingsim
