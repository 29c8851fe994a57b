#include "io/knee_model_loader.h"
#include "core/units.h"

#include <cmath>

#include "core/output_files.h"
#include "io/yaml_reader.h"
#include "knee/damping_table.h"
#include "knee/knee_added_effects.h"
#include "knee/mauch_cylinder.h"

namespace swingsim {

namespace {


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

std::string mustBeDialSetting(double v) {
  return (v == 0 || v == 90 || v == 180) ? "" : "must be a dial setting: 0, 90 or 180";
}

}  // namespace

MauchAddedEffects readMauchAddedEffects(YamlMap& m, int phases) {
  MauchAddedEffects e;
  if (m.has("hyperextension_phase")) {
    if (phases != 2 && phases != 0)
      m.fail("hyperextension_phase", "only a 2-phase model can add a hyperextension phase (the 4-phase model has one)",
             std::to_string(phases) + " phases");
    YamlMap h = m.getMap("hyperextension_phase");
    e.hyperextensionPhase = true;
    e.hyperextension.f = h.getDouble("f_N");
    e.hyperextension.k = h.getDouble("k_N_per_m");
    e.hyperextension.c = h.getDouble("c_Ns_per_m");
    h.finish();
  }
  if (m.has("coulomb_friction")) {
    YamlMap c = m.getMap("coulomb_friction");
    e.coulombFriction = true;
    e.coulombForce = c.getDouble("force_N");
    e.coulombWidth = c.getDouble("width_m_per_s", e.coulombWidth, mustBePositive);
    c.finish();
  }
  if (m.has("orifice_quadratic")) {
    YamlMap c = m.getMap("orifice_quadratic");
    e.orificeQuadratic = true;
    e.orificeCoefficient = c.getDouble("coefficient_Ns2_per_m2");
    c.finish();
  }
  if (m.has("inertia")) {
    YamlMap c = m.getMap("inertia");
    e.inertia = true;
    e.pistonMass = c.getDouble("mass_kg");
    c.finish();
  }
  if (m.has("position_dependent_damping")) {
    YamlMap c = m.getMap("position_dependent_damping");
    e.positionDependentDamping = true;
    e.positionDamping = c.getDouble("coefficient_Ns_per_m2");
    c.finish();
  }
  m.finish();
  return e;
}

MauchCylinderParams readMauchCylinder(YamlMap& yaml) {
  MauchCylinderParams p;
  p.phases = yaml.getInt("phases", 0);
  if (p.phases != 2 && p.phases != 4) {
    if (!yaml.has("phases")) yaml.getDouble("phases");  // throws "required key is missing"
    yaml.fail("phases", "must be 2 or 4 (Chien 2014 2-phase or 4-phase model)", std::to_string(p.phases));
  }
  if (yaml.has("geometry")) {
    YamlMap g = yaml.getMap("geometry");
    p.geometry.ab = g.getDouble("ab_m", p.geometry.ab, mustBePositive);
    p.geometry.ac = g.getDouble("ac_m", p.geometry.ac, mustBePositive);
    if (p.geometry.ab == p.geometry.ac) g.fail("ac_m", "must differ from ab_m", formatNumber(p.geometry.ac));
    g.finish();
  }
  YamlMap sw = yaml.getMap("switches");
  p.switches.velocityWidth = sw.getDouble("velocity_width_m_per_s", mustBePositive);
  p.switches.positionWidth = sw.getDouble("position_width_m", mustBePositive);
  p.switches.hyperextensionPosition = sw.getDouble("hyperextension_position_m");
  p.switches.latchRate = sw.getDouble("latch_rate_per_s", mustBePositive);
  p.initialLatch = sw.getDouble("initial_latch", 1.0, [](double v) {
    return v >= 0 && v <= 1 ? "" : "must be in [0, 1]";
  });
  sw.finish();

  const double flexionDial = yaml.getDouble("flexion_dial_deg", mustBeDialSetting);
  const double extensionDial = yaml.getDouble("extension_dial_deg", mustBeDialSetting);
  bool found = false;
  std::vector<std::pair<double, double>> seen;
  for (YamlMap& setting : yaml.getMapList("settings")) {
    const double f = setting.getDouble("flexion_dial_deg", mustBeDialSetting);
    const double e = setting.getDouble("extension_dial_deg", mustBeDialSetting);
    for (const auto& fe : seen) {
      if (fe.first == f && fe.second == e)
        setting.fail("flexion_dial_deg", "dial setting appears twice", "F" + formatNumber(f) + "E" + formatNumber(e));
    }
    seen.emplace_back(f, e);
    std::vector<YamlMap> rows = setting.getMapList("coefficients");
    std::vector<MauchPhaseCoefficients> coefficients(static_cast<std::size_t>(p.phases));
    std::vector<bool> have(static_cast<std::size_t>(p.phases), false);
    for (YamlMap& row : rows) {
      const int phase = row.getInt("phase", 0);
      if (phase < 1 || phase > p.phases)
        row.fail("phase", "must be a phase number from 1 to " + std::to_string(p.phases), std::to_string(phase));
      if (have[static_cast<std::size_t>(phase - 1)]) row.fail("phase", "phase appears twice", std::to_string(phase));
      have[static_cast<std::size_t>(phase - 1)] = true;
      auto& c = coefficients[static_cast<std::size_t>(phase - 1)];
      c.f = row.getDouble("f_N");
      c.k = row.getDouble("k_N_per_m");
      c.c = row.getDouble("c_Ns_per_m");
      row.finish();
    }
    for (int i = 0; i < p.phases; ++i) {
      if (!have[static_cast<std::size_t>(i)])
        setting.fail("coefficients", "phase " + std::to_string(i + 1) + " is missing; a " +
                     std::to_string(p.phases) + "-phase model needs phases 1 to " + std::to_string(p.phases),
                     std::to_string(rows.size()) + " phases");
    }
    setting.finish();
    if (f == flexionDial && e == extensionDial) {
      p.coefficients = coefficients;
      found = true;
    }
  }
  if (!found)
    yaml.fail("flexion_dial_deg", "no coefficient set in settings for this dial setting",
              "F" + formatNumber(flexionDial) + "E" + formatNumber(extensionDial));
  if (yaml.has("effects")) {
    YamlMap effects = yaml.getMap("effects");
    p.effects = readMauchAddedEffects(effects, p.phases);
  }
  return p;
}

MauchCylinderParams loadMauchCylinder(const std::string& path) {
  YamlMap yaml = YamlMap::loadFile(path);
  const std::string kind = yaml.getChoice("kind", {"damping_table", "mauch"}, "");
  if (kind != "mauch") yaml.fail("kind", "expected a Mauch cylinder model (kind: mauch)", kind);
  yaml.getString("name", "");
  yaml.getString("description", "");
  yaml.getString("source", "");
  MauchCylinderParams p = readMauchCylinder(yaml);
  readHyperextensionStop(yaml);
  if (yaml.has("knee_effects")) {
    YamlMap e = yaml.getMap("knee_effects");
    readKneeAddedEffects(e);
  }
  yaml.finish();
  return p;
}

KneeAddedEffectsParams readKneeAddedEffects(YamlMap& m) {
  KneeAddedEffectsParams p;
  p.modelScale = m.getDouble("model_scale", 1.0, mustBePositive);
  if (m.has("coulomb_friction")) {
    YamlMap c = m.getMap("coulomb_friction");
    p.coulombMoment = c.getDouble("moment_Nm", mustBeNonNegative);
    p.coulombSmoothingRate = c.getDouble("smoothing_deg_s", p.coulombSmoothingRate / kDegToRad, mustBePositive) * kDegToRad;
    c.finish();
  }
  if (m.has("viscous_damping")) {
    YamlMap c = m.getMap("viscous_damping");
    p.viscousDamping = c.getDouble("damping_Nm_s_per_rad", mustBeNonNegative);
    c.finish();
  }
  if (m.has("extension_assist_spring")) {
    YamlMap c = m.getMap("extension_assist_spring");
    p.assistStiffness = c.getDouble("stiffness_Nm_per_rad", mustBeNonNegative);
    c.finish();
  }
  m.finish();
  return p;
}

JointStopParams readHyperextensionStop(YamlMap& yaml) {
  JointStopParams p;
  p.lower = 0.0;
  if (!yaml.has("hyperextension_stop")) return p;
  YamlMap s = yaml.getMap("hyperextension_stop");
  // A hyperextension stop engages near full extension; outside this band JointStop would
  // also reject it (lower limit above its upper one) without naming the file.
  p.lower = s.getDouble("engage_flexion_deg", 0.0, [](double v) {
    return v >= -30 && v <= 30 ? "" : "expected an angle near full extension, -30 to 30 deg";
  }) * kDegToRad;
  p.stiffness = s.getDouble("stiffness_Nm_per_rad1p5", p.stiffness, mustBePositive);
  p.dissipation = s.getDouble("dissipation_s_per_rad", p.dissipation, mustBeNonNegative);
  s.finish();
  return p;
}

namespace {

KneeModel readKneeModel(YamlMap& yaml, const std::string& path) {
  KneeModel model;
  model.path = path;
  model.kind = yaml.getChoice("kind", {"damping_table", "mauch"}, "");
  model.name = yaml.getString("name", fileStem(path));
  yaml.getString("description", "");
  yaml.getString("source", "");
  if (model.kind == "damping_table") model.law.add(readDampingTable(yaml));
  if (model.kind == "mauch") {
    try {
      model.law.add(std::make_unique<MauchCylinder>(readMauchCylinder(yaml)));
    } catch (const std::invalid_argument& e) {
      throw InputError(yaml.where() + e.what());
    }
  }
  if (yaml.has("knee_effects")) {
    YamlMap e = yaml.getMap("knee_effects");
    const KneeAddedEffectsParams added = readKneeAddedEffects(e);
    if (added.modelScale != 1.0) {
      KneeLawSum scaled;
      for (std::size_t i = 0; i < model.law.size(); ++i)
        scaled.add(std::make_unique<ScaledKneeLaw>(model.law.part(i), added.modelScale));
      model.law = scaled;
    }
    model.law.add(std::make_unique<KneeAddedEffects>(added));
  }
  model.law.add(std::make_unique<JointStop>(readHyperextensionStop(yaml)));
  yaml.finish();
  return model;
}

}  // namespace

KneeModel loadKneeModel(const std::string& path) {
  YamlMap yaml = YamlMap::loadFile(path);
  return readKneeModel(yaml, path);
}

KneeModel parseKneeModel(const std::string& text, const std::string& path) {
  YamlMap yaml = YamlMap::loadString(text, path);
  return readKneeModel(yaml, path);
}

}  // namespace swingsim
