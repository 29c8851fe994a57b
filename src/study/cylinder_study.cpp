#include "study/cylinder_study.h"
#include "core/units.h"

#include <cmath>

#include "io/knee_model_loader.h"
#include "core/output_files.h"
#include "io/yaml_reader.h"

namespace swingsim {

namespace {


std::vector<std::string> resolveAll(const YamlMap& yaml, const std::vector<std::string>& paths) {
  std::vector<std::string> out;
  for (const auto& p : paths) out.push_back(yaml.resolvePath(p));
  return out;
}

}  // namespace

CylinderBenchStudy readCylinderBenchStudy(YamlMap& yaml) {
  CylinderBenchStudy s;
  s.path = yaml.path();
  s.name = yaml.getString("name", fileStem(yaml.path()));
  yaml.getString("description", "");
  s.modelPath = yaml.resolvePath(yaml.getString("model"));
  s.kneeAnglesPath = yaml.resolvePath(yaml.getString("knee_angles"));
  s.strideFirstFrame = yaml.getInt("stride_first_frame", s.strideFirstFrame);
  s.strideLastFrame = yaml.getInt("stride_last_frame", s.strideLastFrame);
  if (s.strideLastFrame <= s.strideFirstFrame + 8)
    yaml.fail("stride_last_frame", "must be at least 8 frames after stride_first_frame", std::to_string(s.strideLastFrame));
  auto& p = s.profile;
  // Bounds keep a record's size sane: 1e300 Hz overflowed the sample count (0 samples,
  // empty files, exit 0) and 1e9 cycles filled memory.
  p.sampleRate = yaml.getDouble("sample_rate_Hz", p.sampleRate, [](double v) {
    return v > 0 && v <= 100000 ? "" : "expected a sample rate above 0 and at most 100000 Hz";
  });
  p.cycles = yaml.getInt("cycles", p.cycles);
  if (p.cycles < 1 || p.cycles > 1000) yaml.fail("cycles", "must be from 1 to 1000", std::to_string(p.cycles));
  p.terminalSwingMinimum = yaml.getDouble("terminal_swing_min_deg", 3.0) * kDegToRad;
  p.hyperextension = yaml.getDouble("hyperextension_deg", -4.0, [](double v) {
    return v < 0 ? "" : "must be negative (hyperextension)";
  }) * kDegToRad;
  p.holdSamples = yaml.getInt("hold_samples", p.holdSamples);
  if (p.holdSamples < 0 || p.holdSamples > 1000)
    yaml.fail("hold_samples", "must be from 0 to 1000", std::to_string(p.holdSamples));
  s.noise = yaml.getDouble("noise_N", 0.0, mustBeNonNegative);
  const double seed = yaml.getDouble("seed", 1.0, [](double v) {
    return v >= 0 && v == std::floor(v) && v < 9e15 ? "" : "must be a whole number >= 0";
  });
  s.seed = static_cast<std::uint64_t>(seed);
  s.outputDir = yaml.resolvePath(yaml.getString("output_dir"));
  if (yaml.has("hidden_effects")) {
    YamlMap h = yaml.getMap("hidden_effects");
    if (h.has("switch_delay")) {
      YamlMap d = h.getMap("switch_delay");
      s.hiddenLatchTimeConstant = d.getDouble("time_constant_s", [](double v) {
        return v > 0 && v <= 1 ? "" : "must be in (0, 1] s";
      });
      d.finish();
    }
    s.hiddenEffects = readMauchAddedEffects(h, 0);
  }
  for (YamlMap& c : yaml.getMapList("conditions")) {
    BenchCondition b;
    b.name = c.getString("name");
    if (b.name.empty() || b.name.find_first_of("/\\ ") != std::string::npos)
      c.fail("name", "must be a plain file stem without spaces or slashes", "'" + b.name + "'");
    for (const auto& other : s.conditions) {
      if (other.name == b.name) c.fail("name", "condition name appears twice", b.name);
    }
    b.strideTime = c.getDouble("stride_s", [](double v) { return v > 0 && v <= 10 ? "" : "expected a stride time above 0 and at most 10 s"; });
    constexpr double kMaxSamples = 1e7;  // per condition: 80 MB a column
    const double samples = p.cycles * b.strideTime * p.sampleRate;
    if (samples > kMaxSamples || samples < 16)
      c.fail("stride_s", "cycles x stride_s x sample_rate_Hz must give 16 to 10 million samples",
             formatNumber(samples) + " samples");
    b.amplitudeScale = c.getDouble("amplitude_scale", 1.0, mustBePositive);
    c.finish();
    s.conditions.push_back(b);
  }
  if (s.conditions.empty()) yaml.fail("conditions", "expected at least one condition", "an empty list");
  return s;
}

CylinderFitStudy readCylinderFitStudy(YamlMap& yaml) {
  CylinderFitStudy s;
  s.path = yaml.path();
  s.name = yaml.getString("name", fileStem(yaml.path()));
  yaml.getString("description", "");
  s.models = resolveAll(yaml, yaml.getStringList("models"));
  s.train = resolveAll(yaml, yaml.getStringList("train"));
  s.validate = yaml.has("validate") ? resolveAll(yaml, yaml.getStringList("validate")) : std::vector<std::string>{};
  s.fitSwitches = yaml.getBool("fit_switches", false);
  s.plotSeconds = yaml.getDouble("plot_seconds", s.plotSeconds, mustBePositive);
  if (s.models.empty()) yaml.fail("models", "expected at least one model", "an empty list");
  if (s.train.empty()) yaml.fail("train", "expected at least one bench CSV", "an empty list");
  // Files are reported by stem: two files with the same stem would be ambiguous.
  std::vector<std::string> stems;
  for (const auto& list : {s.train, s.validate}) {
    for (const auto& f : list) {
      const std::string stem = fileStem(f);
      for (const auto& other : stems) {
        if (other == stem) yaml.fail("validate", "two bench files share the file stem '" + stem + "'", f);
      }
      stems.push_back(stem);
    }
  }
  return s;
}

}  // namespace swingsim
