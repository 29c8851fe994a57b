#include "io/knee_model_loader.h"

#include <cmath>

#include "io/output_files.h"
#include "io/yaml_reader.h"
#include "knee/damping_table.h"

namespace swingsim {

namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

std::unique_ptr<KneeLaw> readDampingTable(YamlMap& yaml) {
  YamlMap t = yaml.getMap("damping_table");
  DampingTableParams p;
  p.referenceRate = t.getDouble("reference_speed_deg_s", 150.0, mustBePositive) * kDegToRad;
  std::string rule = t.getChoice("speed_rule", {"linear", "constant"}, "linear");
  p.speedRule = rule == "linear" ? DampingSpeedRule::kLinear : DampingSpeedRule::kConstant;
  p.extensionFactor = t.getDouble("extension_factor", 1.0, mustBeNonNegative);
  p.smoothingRate = t.getDouble("smoothing_speed_deg_s", 30.0, mustBePositive) * kDegToRad;
  std::vector<double> angles = t.getDoubleList("flexion_deg");
  p.moment = t.getDoubleList("moment_Nm");
  if (angles.size() < 2) t.fail("flexion_deg", "expected at least 2 angles", std::to_string(angles.size()));
  if (p.moment.size() != angles.size())
    t.fail("moment_Nm", "expected one moment per angle in flexion_deg (" + std::to_string(angles.size()) + ")",
           std::to_string(p.moment.size()) + " values");
  for (std::size_t i = 0; i < angles.size(); ++i) {
    if (i > 0 && !(angles[i] > angles[i - 1]))
      t.fail("flexion_deg", "angles must strictly increase", formatNumber(angles[i]) + " after " + formatNumber(angles[i - 1]));
    if (p.moment[i] < 0) t.fail("moment_Nm", "resisting moments must not be negative", formatNumber(p.moment[i]));
    p.flexion.push_back(angles[i] * kDegToRad);
  }
  t.finish();
  return std::make_unique<DampingTable>(p);
}

}  // namespace

JointStopParams readHyperextensionStop(YamlMap& yaml) {
  JointStopParams p;
  p.lower = 0.0;
  if (!yaml.has("hyperextension_stop")) return p;
  YamlMap s = yaml.getMap("hyperextension_stop");
  p.lower = s.getDouble("engage_flexion_deg", 0.0) * kDegToRad;
  p.stiffness = s.getDouble("stiffness_Nm_per_rad1p5", p.stiffness, mustBePositive);
  p.dissipation = s.getDouble("dissipation_s_per_rad", p.dissipation, mustBeNonNegative);
  s.finish();
  return p;
}

KneeModel loadKneeModel(const std::string& path) {
  YamlMap yaml = YamlMap::loadFile(path);
  KneeModel model;
  model.path = path;
  model.kind = yaml.getChoice("kind", {"damping_table"}, "");
  model.name = yaml.getString("name", fileStem(path));
  yaml.getString("description", "");
  yaml.getString("source", "");
  if (model.kind == "damping_table") model.law.add(readDampingTable(yaml));
  model.law.add(std::make_unique<JointStop>(readHyperextensionStop(yaml)));
  yaml.finish();
  return model;
}

}  // namespace swingsim
