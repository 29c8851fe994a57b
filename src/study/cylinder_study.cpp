#include "study/cylinder_study.h"

#include <cmath>
#include <set>

#include "core/output_files.h"
#include "core/units.h"
#include "io/knee_model_loader.h"
#include "io/yaml_archive.h"
#include "io/yaml_reader.h"

namespace swingsim {

// ---- The cylinder study formats, described once -------------------------------------------

namespace {

struct SwitchDelayOf {};
struct HiddenEffectsOf {};

// A condition's place in its study: the shared profile (for the record size) and the list
// it is read into (for repeated names).
struct ConditionContext {
  const BenchProfileParams* profile;
  std::set<std::string>* names;  ///< names read so far (a set: linear-time check of long lists)
};

// The hidden effects change the truth only where they act.
bool hasHiddenEffects(const CylinderBenchStudy& s) {
  const MauchAddedEffects& e = s.hiddenEffects;
  return s.hiddenLatchTimeConstant != 0 || e.hyperextensionPhase || e.coulombFriction || e.orificeQuadratic ||
         e.inertia || e.positionDependentDamping;
}

}  // namespace

template <class A>
void serialize(A& a, BenchCondition& b, ConditionContext context) {
  a.text("name", b.name);
  a.require(!b.name.empty() && b.name.find_first_of("/\\ ") == std::string::npos, "name",
            "must be a plain file stem without spaces or slashes", [&] { return "'" + b.name + "'"; });
  a.require(context.names->insert(b.name).second, "name", "condition name appears twice", [&] { return b.name; });
  a.number("stride_s", b.strideTime,
           [](double v) { return v > 0 && v <= 10 ? "" : "expected a stride time above 0 and at most 10 s"; });
  constexpr double kMaxSamples = 1e7;  // per condition: 80 MB a column
  const double samples = context.profile->cycles * b.strideTime * context.profile->sampleRate;
  a.require(samples <= kMaxSamples && samples >= 16, "stride_s",
            "cycles x stride_s x sample_rate_Hz must give 16 to 10 million samples",
            [&] { return formatNumber(samples) + " samples"; });
  a.optionalNumber("amplitude_scale", b.amplitudeScale, mustBePositive);
}

template <class A>
void serialize(A& a, CylinderBenchStudy& s, SwitchDelayOf) {
  a.number("time_constant_s", s.hiddenLatchTimeConstant,
           [](double v) { return v > 0 && v <= 1 ? "" : "must be in (0, 1] s"; });
}

template <class A>
void serialize(A& a, CylinderBenchStudy& s, HiddenEffectsOf) {
  bool delay = s.hiddenLatchTimeConstant != 0;
  a.optionalMap("switch_delay", s, delay, SwitchDelayOf{});
  serialize(a, s.hiddenEffects, 0);
}

// An angle that keeps the field's default (exactly) when absent.
template <class A>
void optionalExactAngle(A& a, const char* key, double& v, const ValueCheck& checkDeg = {}) {
  bool given = true;
  if constexpr (A::kReading) given = a.has(key);
  if (given) a.angle(key, v, checkDeg);
}

template <class A>
void serialize(A& a, CylinderBenchStudy& s) {
  std::string kind = "cylinder-bench";
  a.choice("kind", kind, {{"cylinder-bench", std::string("cylinder-bench")}});
  a.optionalText("name", s.name);
  a.optionalText("description", s.description);
  a.path("model", s.modelPath);
  a.path("knee_angles", s.kneeAnglesPath);
  a.optionalInteger("stride_first_frame", s.strideFirstFrame);
  a.optionalInteger("stride_last_frame", s.strideLastFrame);
  a.require(s.strideLastFrame > s.strideFirstFrame + 8, "stride_last_frame",
            "must be at least 8 frames after stride_first_frame", [&] { return std::to_string(s.strideLastFrame); });
  auto& p = s.profile;
  // Bounds keep a record's size sane: 1e300 Hz overflowed the sample count (0 samples,
  // empty files, exit 0) and 1e9 cycles filled memory.
  a.optionalNumber("sample_rate_Hz", p.sampleRate, [](double v) {
    return v > 0 && v <= 100000 ? "" : "expected a sample rate above 0 and at most 100000 Hz";
  });
  a.optionalInteger("cycles", p.cycles);
  a.require(p.cycles >= 1 && p.cycles <= 1000, "cycles", "must be from 1 to 1000",
            [&] { return std::to_string(p.cycles); });
  optionalExactAngle(a, "terminal_swing_min_deg", p.terminalSwingMinimum);
  optionalExactAngle(a, "hyperextension_deg", p.hyperextension,
                     [](double v) { return v < 0 ? "" : "must be negative (hyperextension)"; });
  a.optionalInteger("hold_samples", p.holdSamples);
  a.require(p.holdSamples >= 0 && p.holdSamples <= 1000, "hold_samples", "must be from 0 to 1000",
            [&] { return std::to_string(p.holdSamples); });
  a.optionalNumber("noise_N", s.noise, mustBePlausible(kForceNoiseRange, "a force noise"));
  double seed = static_cast<double>(s.seed);
  a.optionalNumber("seed", seed, [](double v) {
    return v >= 0 && v == std::floor(v) && v < 9e15 ? "" : "must be a whole number >= 0";
  });
  s.seed = static_cast<std::uint64_t>(seed);
  a.path("output_dir", s.outputDir);
  bool hidden = hasHiddenEffects(s);
  a.optionalMap("hidden_effects", s, hidden, HiddenEffectsOf{});
  std::set<std::string> conditionNames;
  a.mapList("conditions", s.conditions, ConditionContext{&p, &conditionNames});
  a.require(!s.conditions.empty(), "conditions", "expected at least one condition",
            [] { return std::string("an empty list"); });
}

template <class A>
void serialize(A& a, CylinderFitStudy& s) {
  std::string kind = "cylinder-fit";
  a.choice("kind", kind, {{"cylinder-fit", std::string("cylinder-fit")}});
  a.optionalText("name", s.name);
  a.optionalText("description", s.description);
  a.paths("models", s.models);
  a.paths("train", s.train);
  bool validates = !s.validate.empty();
  if constexpr (A::kReading) validates = a.has("validate");
  if (validates) a.paths("validate", s.validate);
  a.optionalFlag("fit_switches", s.fitSwitches);
  a.optionalNumber("plot_seconds", s.plotSeconds, mustBePositive);
  a.require(!s.models.empty(), "models", "expected at least one model", [] { return std::string("an empty list"); });
  a.require(!s.train.empty(), "train", "expected at least one bench CSV", [] { return std::string("an empty list"); });
  // Files are reported by stem: two files with the same stem would be ambiguous.
  std::vector<std::string> stems;
  for (const auto& list : {s.train, s.validate}) {
    for (const auto& f : list) {
      const std::string stem = fileStem(f);
      for (const auto& other : stems)
        a.require(other != stem, "validate", "two bench files share the file stem '" + stem + "'", [&] { return f; });
      stems.push_back(stem);
    }
  }
}

CylinderBenchStudy readCylinderBenchStudy(YamlMap& yaml) {
  CylinderBenchStudy s;
  s.path = yaml.path();
  s.name = fileStem(yaml.path());
  YamlReadArchive a(yaml);
  serialize(a, s);
  return s;
}

CylinderFitStudy loadCylinderFitStudy(const std::string& path) {
  YamlMap yaml = YamlMap::loadFile(path);
  if (!yaml.has("kind")) yaml.getString("kind");
  yaml.getChoice("kind", {"cylinder-fit"}, "");
  CylinderFitStudy study = readCylinderFitStudy(yaml);
  yaml.finish();
  return study;
}

CylinderFitStudy readCylinderFitStudy(YamlMap& yaml) {
  CylinderFitStudy s;
  s.path = yaml.path();
  s.name = fileStem(yaml.path());
  YamlReadArchive a(yaml);
  serialize(a, s);
  return s;
}

std::string formatCylinderBenchStudyYaml(const CylinderBenchStudy& study, const std::string& baseDir) {
  return writeYamlDocument(study, baseDir, "");
}

std::string formatCylinderFitStudyYaml(const CylinderFitStudy& study, const std::string& baseDir) {
  return writeYamlDocument(study, baseDir, "");
}

}  // namespace swingsim
