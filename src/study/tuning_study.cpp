#include "study/tuning_study.h"

#include <cmath>

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/units.h"
#include "io/knee_model_knobs.h"
#include "io/participant_loader.h"
#include "io/yaml_reader.h"
#include "study/run_arguments.h"
#include "study/tuning_model.h"
#include "sweep/tuning_resolution.h"

namespace swingsim {
namespace {

// One knob: key, range, log_scale; tried at both range ends (through the knee model loader
// or the leg geometry), so no point of the range is refused later.
TuningKnob readKnob(YamlMap& m, const Participant& p, const KneeModelKnobs& knee, const TuningStudy& s) {
  TuningKnob k;
  k.key = m.getString("key");
  if (!isLegTuningKnob(k.key)) {
    const std::string problem = knee.checkKey(k.key);
    if (!problem.empty())
      m.fail("key",
             "expected " + std::string(kLoweringKnob) + ", " + kAddedMassKnob + ", " + kAddedMassDistanceKnob +
                 " or a numeric key of the knee model " + knee.path() + ": " + problem,
             k.key);
  }
  const std::vector<double> range = m.getDoubleList("range");
  if (range.size() != 2) m.fail("range", "expected [min, max]", std::to_string(range.size()) + " values");
  k.lower = range[0];
  k.upper = range[1];
  if (!(k.lower < k.upper))
    m.fail("range", "expected min < max", formatNumber(k.lower) + " >= " + formatNumber(k.upper));
  k.logScale = m.getBool("log_scale", false);
  if (k.logScale && k.lower <= 0) m.fail("log_scale", "a log-scaled knob needs a range above 0", formatNumber(k.lower));
  for (double end : range) {
    try {
      if (isLegTuningKnob(k.key))
        checkLegAtKnob(p, s.lowering, s.added, k.key, end);
      else
        knee.make({k.key}, {end});
    } catch (const InputError& e) {
      m.fail("range", "every value of the range must be usable; at " + formatNumber(end) + ": " + e.what(),
             formatNumber(end));
    }
  }
  // The finest step a person can set: stated, or implied by the key's unit suffix.
  const std::optional<double> byUnit = findDefaultKnobResolution(k.key);
  if (m.has("resolution"))
    k.resolution = m.getDouble("resolution", mustBePositive);
  else if (byUnit)
    k.resolution = *byUnit;
  else
    m.fail("resolution",
           "the unit of " + k.key +
               " cannot be told from its key: state the finest step a person can set "
               "(docs/tuning.md, \"Settings at the knob's resolution\")",
           "none");
  if (!(k.resolution <= k.upper - k.lower))
    m.fail("resolution", "expected a step no larger than the range (" + formatNumber(k.upper - k.lower) + ")",
           formatNumber(k.resolution));
  m.finish();
  return k;
}

// A target's window from `value:` or `min:`/`max:`, in SI (`toSi` converts the file's unit).
void readWindow(YamlMap& m, TuningTarget& t, double toSi, const Participant& p, TuningStudy& s) {
  if (m.has("value")) {
    if (m.has("min") || m.has("max")) m.fail("value", "give value or min/max, not both", "both");
    const bool swingTime = t.quantity == TuningQuantity::kSwingTime;
    if (swingTime && m.getString("value") == "sound_limb") {
      if (!p.soundLimbSwingTime)
        m.fail("value",
               "sound_limb needs the participant's sound_limb_swing_time_s, which " + p.path + " does not give",
               "sound_limb");
      t.lower = t.upper = *p.soundLimbSwingTime;
      s.swingTimeSource = p.path + ": sound_limb_swing_time_s";
      return;
    }
    t.lower = t.upper = m.getDouble("value") * toSi;
    return;
  }
  if (!m.has("min") && !m.has("max")) m.fail("", "expected value, or min and/or max", "neither");
  if (m.has("min")) t.lower = m.getDouble("min") * toSi;
  if (m.has("max")) t.upper = m.getDouble("max") * toSi;
  if (!(t.lower < t.upper))
    m.fail("max", "expected min < max", formatNumber(t.lower / toSi) + " >= " + formatNumber(t.upper / toSi));
}

void readTargets(YamlMap& yaml, const Participant& p, TuningStudy& s) {
  YamlMap targets = yaml.getMap("targets");
  const std::pair<TuningQuantity, double> kinds[] = {{TuningQuantity::kSwingTime, 1.0},
                                                     {TuningQuantity::kPeakKneeFlexion, kDegToRad},
                                                     {TuningQuantity::kMinToeClearance, 1.0},
                                                     {TuningQuantity::kMaxStopImpactSpeed, kDegToRad}};
  for (const auto& [quantity, toSi] : kinds) {
    const char* key = tuningQuantityKey(quantity);
    if (!targets.has(key)) continue;
    YamlMap m = targets.getMap(key);
    TuningTarget t;
    t.quantity = quantity;
    t.scale = tuningTargetScale(quantity);
    readWindow(m, t, toSi, p, s);
    t.hard = m.getBool("hard", false);
    if (t.hard && m.has("weight"))
      m.fail("weight", "a hard limit has no weight (it must be met)", "weight with hard: true");
    t.weight = m.getDouble("weight", 1.0, mustBePositive);
    m.finish();
    s.targets.push_back(t);
  }
  targets.finish();
  if (s.targets.empty())
    targets.fail(
        "", "expected at least one of swing_time_s, peak_knee_flexion_deg, min_toe_clearance_m, max_stop_impact_deg_s",
        "none");
}

void readSettings(YamlMap& yaml, TuningStudy& s) {
  if (yaml.has("start_points")) {
    const std::uint64_t n = yaml.getWhole("start_points", 10000, "10000");
    if (n < 2) yaml.fail("start_points", "expected at least 2 start points", std::to_string(n));
    s.settings.startPoints = static_cast<int>(n);
  }
  if (yaml.has("seed")) s.settings.seed = yaml.getWhole("seed", 1000000000, "1000000000");
  s.settings.toleranceWindow = yaml.getDouble("tolerance_window_s", s.settings.toleranceWindow, mustBePositive);
  s.lowering = yaml.getDouble("lowering_m", 0.0, mustBeNonNegative);
  if (yaml.has("uncertainty")) {  // as a sweep study's: samples (1 to 100000) and an optional seed
    YamlMap m = yaml.getMap("uncertainty");
    s.chance.samples = static_cast<int>(m.getWhole("samples", static_cast<std::uint64_t>(uncertaintySamplesRange().max),
                                                   std::to_string(uncertaintySamplesRange().max)));
    if (s.chance.samples < 1) m.fail("samples", uncertaintySamplesRange().expected, std::to_string(s.chance.samples));
    if (m.has("seed")) s.chance.seed = m.getWhole("seed", kMaxSeed, std::to_string(kMaxSeed));
    m.finish();
  }
  if (yaml.has("added_mass")) {
    YamlMap m = yaml.getMap("added_mass");
    s.added.mass = m.getDouble("mass_kg", mustBeNonNegative);
    s.added.distanceBelowKnee = m.getDouble("below_knee_m", mustBeNonNegative);
    m.finish();
  }
}

}  // namespace

TuningStudy loadTuningStudy(const std::string& path) {
  YamlMap yaml = YamlMap::loadFile(path);
  if (!yaml.has("kind")) yaml.getString("kind");
  yaml.getChoice("kind", {"knee-tuning"}, "");
  TuningStudy s;
  s.path = path;
  s.name = yaml.getString("name", fileStem(path));
  s.description = yaml.getString("description", "");
  s.participantPath = yaml.resolvePath(yaml.getString("participant"), "participant");
  const Participant p = loadParticipant(s.participantPath);
  s.kneeModelPath =
      yaml.has("knee_model") ? yaml.resolvePath(yaml.getString("knee_model"), "knee_model") : p.kneeModelPath;
  const KneeModelKnobs knee(s.kneeModelPath);
  readSettings(yaml, s);
  try {
    calcLegGeometry(p, s.lowering, s.added);
  } catch (const InputError& e) {
    yaml.fail("lowering_m", std::string("the leg cannot take this lowering and added mass: ") + e.what(),
              formatNumber(s.lowering));
  }
  for (YamlMap& m : yaml.getMapList("knobs")) {
    s.knobs.push_back(readKnob(m, p, knee, s));
    for (std::size_t i = 0; i + 1 < s.knobs.size(); ++i)
      if (s.knobs[i].key == s.knobs.back().key) m.fail("key", "this knob appears twice", s.knobs.back().key);
    // A fixed lowering beside a lowering knob would be dropped without a word.
    if (s.knobs.back().key == "lowering_m" && yaml.has("lowering_m"))
      m.fail("key",
             "a lowering knob or a fixed lowering_m, not both (the knob moves the lowering; remove lowering_m: " +
                 formatNumber(s.lowering) + ")",
             "lowering_m");
  }
  if (s.knobs.empty()) yaml.fail("knobs", "expected at least one knob", "an empty list");
  readTargets(yaml, p, s);
  yaml.finish();
  return s;
}

}  // namespace swingsim
