// `swingsim generate` for kind swing-kinematics: synthetic swing measurements from a
// participant and knee model, with optional hidden effects and noise (docs/diagnosis.md).
#include "cli/generate_swing_kinematics.h"

#include <cmath>
#include <cstdio>

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/output_paths.h"
#include "core/units.h"
#include "identify/synthetic_swing.h"
#include "io/swing_record_csv.h"
#include "study/swing_kinematics_study.h"

namespace swingsim::cli {

int generateSwingKinematics(YamlMap& yaml, const std::optional<std::string>& outDirGiven) {
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
  std::printf("wrote %zu swing kinematics files to %s (participant %s, knee %s, noise %s deg, seed %llu)\n", files.size(),
              outDir.c_str(), base.participant.name.c_str(), base.knee.name.c_str(), formatNumber(noise).c_str(),
              static_cast<unsigned long long>(seed));
  return 0;
}

}  // namespace swingsim::cli
