#include "io/participant_loader.h"

#include "io/yaml_reader.h"

namespace swingsim {

namespace {

SegmentParams readSegment(YamlMap& segments, const std::string& key) {
  YamlMap m = segments.getMap(key);
  SegmentParams s;
  s.length = m.getDouble("length_m", mustBePositive);
  s.mass = m.getDouble("mass_kg", mustBePositive);
  s.comFromDistal = m.getDouble("com_from_distal_m", mustBeNonNegative);
  s.inertia = m.getDouble("inertia_kgm2", mustBePositive);
  if (s.comFromDistal > s.length) {
    m.fail("com_from_distal_m", "the COM must lie on the segment (0.." + formatNumber(s.length) + " m from its distal end)",
           formatNumber(s.comFromDistal));
  }
  m.finish();
  return s;
}

double readAngle(YamlMap& m, const std::string& key, double defaultRad) {
  return m.getDouble(key, defaultRad * kRadToDeg) * kDegToRad;
}

HipMomentProfile readHipMoment(YamlMap& yaml) {
  YamlMap m = yaml.getMap("hip_moment");
  HipMomentProfile h;
  const std::string kind = m.getChoice("profile", {"biphasic_sine", "table"}, "");
  if (kind == "table") {
    h.kind = HipMomentProfile::Kind::kTable;
    h.times = m.getDoubleList("time_s");
    h.moments = m.getDoubleList("moment_Nm");
    if (h.times.size() < 2) m.fail("time_s", "expected at least 2 times", std::to_string(h.times.size()) + " values");
    if (h.moments.size() != h.times.size())
      m.fail("moment_Nm", "expected one moment per time (" + std::to_string(h.times.size()) + ")",
             std::to_string(h.moments.size()) + " values");
    for (std::size_t i = 1; i < h.times.size(); ++i) {
      if (!(h.times[i] > h.times[i - 1]))
        m.fail("time_s", "times must strictly increase", formatNumber(h.times[i]) + " after " + formatNumber(h.times[i - 1]));
    }
  } else {
    h.flexionAmplitude = m.getDouble("flexion_amplitude_Nm", mustBeNonNegative);
    h.flexionDuration = m.getDouble("flexion_duration_s", mustBePositive);
    h.extensionAmplitude = m.getDouble("extension_amplitude_Nm", mustBeNonNegative);
    h.extensionDuration = m.getDouble("extension_duration_s", mustBePositive);
  }
  h.timeScale = m.getDouble("time_scale", 1.0, mustBePositive);
  m.finish();
  return h;
}

Participant readParticipant(YamlMap& yaml) {
  Participant p;
  p.path = yaml.path();
  p.name = yaml.getString("name");
  yaml.getString("source", "");
  p.height = yaml.getDouble("height_m", [](double v) { return v > 0.5 && v < 2.6 ? "" : "expected a standing height between 0.5 and 2.6 m"; });
  p.bodyMass = yaml.getDouble("body_mass_kg", mustBePositive);
  {
    YamlMap segments = yaml.getMap("segments");
    p.thigh = readSegment(segments, "thigh");
    p.shank = readSegment(segments, "shank");
    p.foot = readSegment(segments, "foot");
    segments.finish();
  }
  p.kneeFriction = yaml.getDouble("knee_friction_Nm", mustBeNonNegative);
  p.kneeModelPath = yaml.resolvePath(yaml.getString("knee_model"));
  p.comRule = yaml.getChoice("com_rule", {"fixed_from_proximal", "proportional"}, "fixed_from_proximal") == "proportional"
                  ? ComRule::kProportional
                  : ComRule::kFixedFromProximal;
  p.footComFrom = yaml.getChoice("foot_com_from", {"toe", "ankle"}, "toe") == "ankle" ? FootComFrom::kAnkle : FootComFrom::kToe;
  p.minShankLength = yaml.getDouble("min_shank_length_m", p.minShankLength, mustBePositive);
  if (p.minShankLength >= p.shank.length) {
    yaml.fail("min_shank_length_m", "must be shorter than the shank (" + formatNumber(p.shank.length) + " m)",
              formatNumber(p.minShankLength));
  }
  if (yaml.has("initial")) {
    YamlMap m = yaml.getMap("initial");
    p.initial.hipFlexion = readAngle(m, "hip_flexion_deg", p.initial.hipFlexion);
    p.initial.kneeFlexion = readAngle(m, "knee_flexion_deg", p.initial.kneeFlexion);
    p.initial.hipFlexionRate = readAngle(m, "hip_flexion_rate_deg_s", p.initial.hipFlexionRate);
    p.initial.kneeFlexionRate = readAngle(m, "knee_flexion_rate_deg_s", p.initial.kneeFlexionRate);
    m.finish();
  }
  if (yaml.has("hip_range")) {
    YamlMap m = yaml.getMap("hip_range");
    p.hipRange.minFlexion = readAngle(m, "min_flexion_deg", p.hipRange.minFlexion);
    p.hipRange.maxFlexion = readAngle(m, "max_flexion_deg", p.hipRange.maxFlexion);
    if (!(p.hipRange.maxFlexion > p.hipRange.minFlexion))
      m.fail("max_flexion_deg", "must exceed min_flexion_deg", formatNumber(p.hipRange.maxFlexion * kRadToDeg));
    m.finish();
  }
  if (p.initial.hipFlexion < p.hipRange.minFlexion || p.initial.hipFlexion > p.hipRange.maxFlexion) {
    yaml.fail("initial", "the initial hip flexion must lie inside hip_range",
              formatNumber(p.initial.hipFlexion * kRadToDeg) + " deg");
  }
  if (yaml.has("swing_end")) {
    YamlMap m = yaml.getMap("swing_end");
    p.swingEnd.thighTargetFlexion = readAngle(m, "thigh_target_flexion_deg", p.swingEnd.thighTargetFlexion);
    p.swingEnd.zoneOfStability = m.getDouble("zone_of_stability_deg", p.swingEnd.zoneOfStability * kRadToDeg, mustBePositive) * kDegToRad;
    // A swing lasts well under a second; a limit of hours would make a stuck run look hung.
    p.swingEnd.timeLimit = m.getDouble("time_limit_s", p.swingEnd.timeLimit, [](double v) {
      return v > 0 && v <= 10 ? "" : "expected a time limit from 0 to 10 s";
    });
    p.swingEnd.bounceWindow = m.getDouble("bounce_window_s", p.swingEnd.bounceWindow, [](double v) {
      return v >= 0 && v <= 2 ? "" : "expected a window from 0 to 2 s";
    });
    m.finish();
  }
  if (!(p.swingEnd.thighTargetFlexion > p.initial.hipFlexion)) {
    yaml.fail("swing_end", "thigh_target_flexion_deg must be above the initial hip flexion",
              formatNumber(p.swingEnd.thighTargetFlexion * kRadToDeg) + " deg");
  }
  p.hipMoment = readHipMoment(yaml);
  yaml.finish();
  return p;
}

}  // namespace

Participant loadParticipant(const std::string& path) {
  YamlMap yaml = YamlMap::loadFile(path);
  return readParticipant(yaml);
}

Participant parseParticipant(const std::string& text, const std::string& path) {
  YamlMap yaml = YamlMap::loadString(text, path);
  return readParticipant(yaml);
}

}  // namespace swingsim
