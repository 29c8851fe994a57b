#include "study/sweep_study.h"

#include <cstdint>
#include <set>
#include <string>

#include "core/input_error.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "io/yaml_archive.h"
#include "io/yaml_reader.h"
#include "study/run_arguments.h"
#include "study/sweep_study_format.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim {

// ---- The knee-axis sweep study format, described once ------------------------------------

namespace {

struct AddedMassOf {};
struct UncertaintyOf {};

}  // namespace

template <class A>
void serialize(A& a, SweepStudy& s, AddedMassOf) {
  a.numbers("mass_kg", s.addedMasses);
  a.numbers("distance_below_knee_m", s.addedMassDistances);
  for (double v : s.addedMasses)
    a.require(v >= 0, "mass_kg", "masses must not be negative", [&] { return formatNumber(v); });
  for (double v : s.addedMassDistances)
    a.require(v >= 0, "distance_below_knee_m", "distances must not be negative", [&] { return formatNumber(v); });
  a.require(!s.addedMassDistances.empty(), "distance_below_knee_m", "expected at least one distance",
            [] { return std::string("an empty list"); });
}

template <class A>
void serialize(A& a, SweepStudy& s, UncertaintyOf) {
  a.integer("samples", s.uncertaintySamples);
  a.require(uncertaintySamplesRange().check(static_cast<long long>(s.uncertaintySamples)).empty(), "samples",
            uncertaintySamplesRange().expected, [&] { return std::to_string(s.uncertaintySamples); });
  bool seeded = true;
  if constexpr (A::kReading) seeded = a.has("seed");
  // Read as digits, not through an int, so a seed above the range is named as such.
  auto seed = static_cast<std::uint64_t>(s.uncertaintySeed);
  if (seeded) a.whole("seed", seed, kMaxSeed, std::to_string(kMaxSeed));
  s.uncertaintySeed = static_cast<int>(seed);
}

template <class A>
void serialize(A& a, SweepStudy& s) {
  std::string kind = "knee-axis-sweep";
  a.choice("kind", kind, {{"knee-axis-sweep", std::string("knee-axis-sweep")}});
  a.text("name", s.name);
  a.optionalText("description", s.description);
  // The reader loads each participant file it lists (their errors come first, as they are met).
  std::vector<std::string> files;
  for (const auto& p : s.participants) files.push_back(p.path);
  a.paths("participants", files);
  if constexpr (A::kReading)
    for (const auto& f : files) s.participants.push_back(loadParticipant(f));
  a.require(!s.participants.empty(), "participants", "expected at least one participant file",
            [] { return std::string("an empty list"); });
  // Results, figures and table rows are keyed by participant name.
  std::set<std::string> names;  // a set: linear-time check of long lists
  for (const auto& p : s.participants)
    a.require(names.insert(p.name).second, "participants",
              "two participant files have the same name '" + p.name + "' (results are keyed by name)",
              [&] { return p.path; });
  bool overridesKnee = !s.kneeModelOverride.empty();
  if constexpr (A::kReading) overridesKnee = a.has("knee_model");
  if (overridesKnee) a.path("knee_model", s.kneeModelOverride);
  // A sensitivity study: the same participants under the other COM reading.
  if constexpr (A::kReading) s.overridesComRule = a.has("com_rule");
  if (s.overridesComRule) {
    a.choice("com_rule", s.comRule,
             {{"fixed_from_proximal", ComRule::kFixedFromProximal}, {"proportional", ComRule::kProportional}});
    for (auto& p : s.participants) p.comRule = s.comRule;
  }
  bool present = true;
  a.optionalMap("lowering", s, present, LoweringOf{});
  bool addedMass = !s.addedMassDistances.empty();
  a.optionalMap("added_mass", s, addedMass, AddedMassOf{});
  a.optionalMap("integrator", s.swing, present = true);
  // Calibrate the hip time scales to Burkett Table 3 before sweeping (measured_validation.h).
  a.choice("calibrate_to", s.calibrateTo, calibrationTargetChoices(), true);
  bool uncertainty = s.uncertaintySamples > 0;
  a.optionalMap("uncertainty", s, uncertainty, UncertaintyOf{});
  a.optionalText("output_dir", s.outputDir);
}

namespace {

SweepStudy readSweepStudy(YamlMap& yaml, const std::string& path) {
  SweepStudy s;
  s.path = path;
  YamlReadArchive a(yaml);
  serialize(a, s);
  yaml.finish();
  for (const auto& p : s.participants) {
    const std::string modelPath = studyKneeModelPath(s, p);
    if (!s.kneeModels.count(modelPath)) s.kneeModels.emplace(modelPath, loadKneeModel(modelPath));
  }
  return s;
}

}  // namespace

std::string formatSweepStudyYaml(const SweepStudy& study, const std::string& baseDir) {
  return writeYamlDocument(study, baseDir, "");
}

SweepStudy loadSweepStudy(const std::string& path) {
  YamlMap yaml = YamlMap::loadFile(path);
  return readSweepStudy(yaml, path);
}

SweepStudy parseSweepStudy(const std::string& text, const std::string& path) {
  YamlMap yaml = YamlMap::loadString(text, path);
  return readSweepStudy(yaml, path);
}

}  // namespace swingsim
