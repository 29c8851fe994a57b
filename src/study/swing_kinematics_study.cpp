#include "study/swing_kinematics_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "core/input_error.h"
#include "identify/swing_effects.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "io/yaml_archive.h"
#include "io/yaml_reader.h"

namespace swingsim {

// ---- The swing-kinematics study format, described once ------------------------------------

namespace {

// The check of a hidden value: within its record's physical bounds (reported units).
ValueCheck withinBounds(double lower, double upper) {
  return [lower, upper](double v) {
    char bounds[96];
    std::snprintf(bounds, sizeof bounds, "[%.4g, %.4g]", lower, upper);
    return v >= lower && v <= upper ? std::string()
                                    : std::string("expected a value within the effect's physical bounds ") + bounds;
  };
}

}  // namespace

template <class A>
void serialize(A& a, SwingHiddenEffect& h, const SwingEffectRecord& r) {
  const EffectDescriptor& d = r.descriptor;
  if constexpr (A::kReading) {
    h.values.assign(d.parameters.size(), 0.0);
    if (r.gridValue) h.values.back() = d.grid[d.grid.size() / 2] * d.gridReportScale;
  }
  for (std::size_t j = 0; j < r.slots.size(); ++j) {
    const SwingEffectSlot& slot = r.slots[j];
    a.number(d.parameters[j].c_str(), h.values[j],
             withinBounds(slot.bounds.lower * slot.reportScale, slot.bounds.upper * slot.reportScale));
  }
  if (r.gridValue) a.optionalNumber(d.parameters.back().c_str(), h.values.back(), mustBePositive);
}

template <class A>
void serialize(A& a, SwingHiddenEffects& h) {
  const auto& records = swingEffectRecords();
  h.effects.resize(records.size());
  for (std::size_t i = 0; i < records.size(); ++i)
    a.optionalMap(records[i].descriptor.name.c_str(), h.effects[i], h.effects[i].present, records[i]);
}

template <class A>
void serialize(A& a, SwingCondition& c) {
  a.text("name", c.name);
  a.optionalNumber("time_scale", c.timeScale, mustBePlausible(kTimeScaleRange, "a time scale"));
  a.optionalNumber("amplitude_scale", c.amplitudeScale, mustBePlausible(kAmplitudeScaleRange, "an amplitude scale"));
}

template <class A>
void serialize(A& a, SwingKinematicsStudy& s) {
  std::string kind = "swing-kinematics";
  a.choice("kind", kind, {{"swing-kinematics", std::string("swing-kinematics")}});
  // The reader loads each file as it is met (their errors come first).
  a.path("participant", s.participantPath);
  if constexpr (A::kReading) s.base.participant = loadParticipant(s.participantPath);
  a.path("model", s.modelPath);
  if constexpr (A::kReading) s.base.knee = loadKneeModel(s.modelPath);
  a.optionalText("name", s.name);
  a.optionalText("description", s.description);
  a.number("noise_deg", s.noiseDeg, mustBePlausible(kAngleNoiseRange, "an angle noise"));
  double seed = static_cast<double>(s.seed);
  a.optionalNumber("seed", seed, [](double v) {
    return v >= 0 && v < 9e15 && v == std::floor(v) ? "" : "must be a whole number >= 0";
  });
  s.seed = static_cast<std::uint64_t>(seed);
  a.optionalNumber("sample_interval_s", s.sampleInterval,
                   [](double v) { return v >= 1e-4 && v <= 0.02 ? "" : "must be in [0.0001, 0.02] s"; });
  a.path("output_dir", s.outputDir);
  a.mapList("conditions", s.conditions);
  a.require(!s.conditions.empty(), "conditions", "expected at least one condition",
            [] { return std::string("an empty list"); });
  a.optionalMap("hidden_effects", s.hidden, s.hasHiddenEffects);
}

SwingKinematicsStudy readSwingKinematicsStudy(YamlMap& yaml) {
  SwingKinematicsStudy s;
  s.path = yaml.path();
  YamlReadArchive a(yaml);
  serialize(a, s);
  yaml.finish();
  return s;
}

std::string formatSwingKinematicsStudyYaml(const SwingKinematicsStudy& study, const std::string& baseDir) {
  return writeYamlDocument(study, baseDir, "");
}

namespace {

std::size_t hiddenIndex(const std::string& name) {
  const auto& records = swingEffectRecords();
  for (std::size_t i = 0; i < records.size(); ++i)
    if (records[i].descriptor.name == name) return i;
  throw std::invalid_argument("not a library swing effect: " + name);
}

}  // namespace

bool SwingHiddenEffects::has(const std::string& name) const {
  const std::size_t i = hiddenIndex(name);
  return i < effects.size() && effects[i].present;
}

double SwingHiddenEffects::value(const std::string& name, const std::string& parameter) const {
  const std::size_t i = hiddenIndex(name);
  const auto& params = swingEffectRecords()[i].descriptor.parameters;
  const auto j = static_cast<std::size_t>(std::find(params.begin(), params.end(), parameter) - params.begin());
  if (j == params.size()) throw std::invalid_argument(name + " has no parameter " + parameter);
  return has(name) ? effects[i].values[j] : std::numeric_limits<double>::quiet_NaN();
}

SwingModelParams makeHiddenTruth(const SwingHiddenEffects& h, std::vector<std::string>& names) {
  SwingModelParams truth;
  const auto& records = swingEffectRecords();
  for (std::size_t i = 0; i < records.size() && i < h.effects.size(); ++i) {
    if (!h.effects[i].present) continue;
    const SwingEffectRecord& r = records[i];
    const std::vector<double>& v = h.effects[i].values;
    const double grid = r.gridValue ? v.back() / r.descriptor.gridReportScale : 0.0;
    truth = addSwingEffect(truth, r.id(), grid);
    for (std::size_t j = 0; j < r.slots.size(); ++j) r.slots[j].value(truth.effects) = v[j] / r.slots[j].reportScale;
    names.push_back(r.descriptor.name);
  }
  return truth;
}

}  // namespace swingsim
