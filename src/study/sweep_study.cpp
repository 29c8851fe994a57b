#include "study/sweep_study.h"

#include "core/input_error.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "io/yaml_reader.h"

namespace swingsim {

namespace {

SweepStudy readSweepStudy(YamlMap& yaml, const std::string& path) {
  SweepStudy s;
  s.path = path;
  yaml.getChoice("kind", {"knee-axis-sweep"}, "");
  s.name = yaml.getString("name");
  yaml.getString("description", "");
  for (const auto& p : yaml.getStringList("participants")) s.participants.push_back(loadParticipant(yaml.resolvePath(p)));
  if (s.participants.empty()) yaml.fail("participants", "expected at least one participant file", "an empty list");
  if (yaml.has("knee_model")) s.kneeModelOverride = yaml.resolvePath(yaml.getString("knee_model"));
  if (yaml.has("com_rule")) {
    // A sensitivity study: the same participants under the other COM reading.
    const bool proportional = yaml.getChoice("com_rule", {"fixed_from_proximal", "proportional"}, "") == "proportional";
    for (auto& p : s.participants) p.comRule = proportional ? ComRule::kProportional : ComRule::kFixedFromProximal;
  }
  if (yaml.has("lowering")) {
    YamlMap m = yaml.getMap("lowering");
    // The grid is rounded to 1 um (sweepLowerings): a smaller step would never advance. With
    // lowerings capped by the shank (calcMaxLowering), this also bounds a sweep to a few
    // thousand swings per participant.
    s.loweringStep = m.getDouble("step_m", s.loweringStep, [](double v) {
      return v >= 1e-4 ? "" : "expected a step of at least 0.0001 m";
    });
    s.loweringMax = m.getDouble("max_m", s.loweringMax, mustBeNonNegative);
    s.includePublishedLowerings = m.getBool("include_published", s.includePublishedLowerings);
    m.finish();
  }
  if (yaml.has("added_mass")) {
    YamlMap m = yaml.getMap("added_mass");
    s.addedMasses = m.getDoubleList("mass_kg");
    s.addedMassDistances = m.getDoubleList("distance_below_knee_m");
    for (double v : s.addedMasses) if (v < 0) m.fail("mass_kg", "masses must not be negative", formatNumber(v));
    for (double v : s.addedMassDistances) if (v < 0) m.fail("distance_below_knee_m", "distances must not be negative", formatNumber(v));
    if (s.addedMassDistances.empty()) m.fail("distance_below_knee_m", "expected at least one distance", "an empty list");
    m.finish();
  }
  if (yaml.has("integrator")) {
    YamlMap m = yaml.getMap("integrator");
    const std::vector<std::string>& keys = integratorKeys();
    const std::string method = m.getChoice("method", keys, keys[static_cast<int>(s.swing.integrator)]);
    s.swing.integrator = *findIntegrator(method);  // getChoice allowed only known keys
    s.swing.accuracy = m.getDouble("accuracy", s.swing.accuracy, [](double v) { return checkAccuracy(v); });
    s.swing.sampleInterval = m.getDouble("sample_interval_s", s.swing.sampleInterval, [](double v) {
      return v >= 1e-5 && v <= 0.1 ? "" : "expected a sample interval from 0.00001 to 0.1 s";
    });
    m.finish();
  }
  s.outputDir = yaml.getString("output_dir", "");
  yaml.finish();
  for (const auto& p : s.participants) {
    const std::string modelPath = s.kneeModelOverride.empty() ? p.kneeModelPath : s.kneeModelOverride;
    if (!s.kneeModels.count(modelPath)) s.kneeModels.emplace(modelPath, loadKneeModel(modelPath));
  }
  return s;
}

}  // namespace

SweepStudy loadSweepStudy(const std::string& path) {
  YamlMap yaml = YamlMap::loadFile(path);
  return readSweepStudy(yaml, path);
}

SweepStudy parseSweepStudy(const std::string& text, const std::string& path) {
  YamlMap yaml = YamlMap::loadString(text, path);
  return readSweepStudy(yaml, path);
}

}  // namespace swingsim
