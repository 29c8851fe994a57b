// `swingsim generate` for kind swing-kinematics: synthetic swing measurements from a
// participant and knee model, with optional hidden effects and noise (docs/diagnosis.md).
#include "cli/generate_swing_kinematics.h"

#include <cmath>
#include <cstdio>
#include <functional>

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/units.h"
#include "identify/synthetic_swing.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "io/swing_record_csv.h"
#include "io/yaml_reader.h"

namespace swingsim::cli {

int generateSwingKinematics(YamlMap& yaml, const std::optional<std::string>& outDirGiven) {
  SwingBase base;
  base.participant = loadParticipant(yaml.resolvePath(yaml.getString("participant")));
  base.knee = loadKneeModel(yaml.resolvePath(yaml.getString("model")));
  yaml.getString("name", "");
  yaml.getString("description", "");
  const double noise = yaml.getDouble("noise_deg", mustBeNonNegative);
  const double seedValue = yaml.getDouble("seed", 1.0, [](double v) {
    return v >= 0 && v < 9e15 && v == std::floor(v) ? "" : "must be a whole number >= 0";
  });
  const double interval = yaml.getDouble("sample_interval_s", 0.002, [](double v) {
    return v >= 1e-4 && v <= 0.02 ? "" : "must be in [0.0001, 0.02] s";
  });
  std::string outDir = yaml.resolvePath(yaml.getString("output_dir"));
  if (outDirGiven) outDir = *outDirGiven;
  std::vector<SwingCondition> conditions;
  for (YamlMap& c : yaml.getMapList("conditions")) {
    SwingCondition sc;
    sc.name = c.getString("name");
    sc.timeScale = c.getDouble("time_scale", 1.0, mustBePositive);
    sc.amplitudeScale = c.getDouble("amplitude_scale", 1.0, mustBePositive);
    c.finish();
    conditions.push_back(sc);
  }
  if (conditions.empty()) yaml.fail("conditions", "expected at least one condition", "an empty list");
  SwingModelParams truth;
  std::vector<std::string> hiddenNames;
  if (yaml.has("hidden_effects")) {
    YamlMap h = yaml.getMap("hidden_effects");
    auto& e = truth.effects;
    // One hidden effect: its block, read by `read` (which adds the effect to the truth),
    // then its name kept for the table below.
    auto hidden = [&](const char* name, const std::function<void(YamlMap&, const char*)>& read) {
      if (!h.has(name)) return;
      YamlMap m = h.getMap(name);
      read(m, name);
      m.finish();
      hiddenNames.push_back(name);
    };
    hidden("knee_coulomb_friction", [&](YamlMap& m, const char* name) {
      truth = addSwingEffect(truth, findEffect(PlantKind::kSwing, name)->id, m.getDouble("smoothing_deg_s", 57.29577951308232, mustBePositive) * kDegToRad);
      e.knee.coulombMoment = m.getDouble("moment_Nm", mustBeNonNegative);
    });
    hidden("knee_viscous_damping", [&](YamlMap& m, const char* name) {
      truth = addSwingEffect(truth, findEffect(PlantKind::kSwing, name)->id, 0);
      e.knee.viscousDamping = m.getDouble("damping_Nm_s_per_rad", mustBeNonNegative);
    });
    hidden("extension_assist_spring", [&](YamlMap& m, const char* name) {
      truth = addSwingEffect(truth, findEffect(PlantKind::kSwing, name)->id, 0);
      e.knee.assistStiffness = m.getDouble("stiffness_Nm_per_rad", mustBeNonNegative);
    });
    hidden("toe_off_velocity", [&](YamlMap& m, const char* name) {
      truth = addSwingEffect(truth, findEffect(PlantKind::kSwing, name)->id, 0);
      e.toeOffHipRate = m.getDouble("hip_rate_deg_s") * kDegToRad;
      e.toeOffKneeRate = m.getDouble("knee_rate_deg_s") * kDegToRad;
    });
    hidden("hip_moment_scale", [&](YamlMap& m, const char* name) {
      truth = addSwingEffect(truth, findEffect(PlantKind::kSwing, name)->id, 0);
      e.hipMomentScale = m.getDouble("scale", mustBePositive);
    });
    hidden("shank_mass_scale", [&](YamlMap& m, const char* name) {
      truth = addSwingEffect(truth, findEffect(PlantKind::kSwing, name)->id, 0);
      e.shankMassScale = m.getDouble("scale", mustBePositive);
    });
    hidden("below_knee_mass_scale", [&](YamlMap& m, const char* name) {
      truth = addSwingEffect(truth, findEffect(PlantKind::kSwing, name)->id, 0);
      e.belowKneeMassScale = m.getDouble("scale", mustBePositive);
    });
    h.finish();
  }
  yaml.finish();
  const auto seed = static_cast<std::uint64_t>(seedValue);
  std::vector<std::pair<std::string, std::string>> files;
  std::printf("%-8s %8s %9s %8s %10s %14s%s\n", "file", "tau_x", "amplitude", "samples", "swing_s", "peak_knee_deg",
              hiddenNames.empty() ? "" : "  hidden_knee_rms_deg");
  for (std::size_t i = 0; i < conditions.size(); ++i) {
    const auto& c = conditions[i];
    SwingRecord r = makeSyntheticSwing(base, truth, c, noise, seed + i, interval);
    double peak = -1e9;
    for (double k : r.kneeFlexion) peak = std::max(peak, k * kRadToDeg);
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
  for (const auto& [path, text] : files) writeFileAtomic(path, text);
  std::printf("wrote %zu swing kinematics files to %s (participant %s, knee %s, noise %s deg, seed %llu)\n", files.size(),
              outDir.c_str(), base.participant.name.c_str(), base.knee.name.c_str(), formatNumber(noise).c_str(),
              static_cast<unsigned long long>(seed));
  return 0;
}

}  // namespace swingsim::cli
