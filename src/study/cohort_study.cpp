#include "study/cohort_study.h"

#include <cstdint>
#include <limits>
#include <string>

#include "core/input_error.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "io/yaml_archive.h"
#include "io/yaml_reader.h"
#include "study/sweep_study_format.h"

namespace swingsim {

namespace {

/// Reading context: the distributions of one study, keyed in table order.
struct DistributionsOf {};

}  // namespace

template <class A>
void serialize(A& a, CohortDistribution& d, const CohortProperty& property) {
  a.choice("distribution", d.kind,
           {{"uniform", CohortDistribution::Kind::kUniform}, {"normal", CohortDistribution::Kind::kNormal}});
  a.number("min", d.min);
  a.number("max", d.max);
  if (d.kind == CohortDistribution::Kind::kNormal) {
    a.number("mean", d.mean);
    a.number("sd", d.sd);
  }
  a.text("source", d.source);
  const CohortDistributionProblem problem = checkCohortDistribution(property, d);
  a.require(problem.key.empty(), problem.key.c_str(), "expected " + problem.expected, [&] { return problem.found; });
}

template <class A>
void serialize(A& a, Cohort& c, DistributionsOf) {
  const auto& table = cohortProperties();
  c.distributions.resize(table.size());
  for (std::size_t k = 0; k < table.size(); ++k) a.flowMap(table[k].key.c_str(), c.distributions[k], table[k]);
}

template <class A>
void serialize(A& a, Cohort& c) {
  std::string kind = "cohort-sweep";
  a.choice("kind", kind, {{"cohort-sweep", std::string("cohort-sweep")}});
  a.text("name", c.study.name);
  a.optionalText("description", c.study.description);
  a.integer("participants", c.count);
  a.require(c.count >= 1 && c.count <= kMaxCohortParticipants, "participants",
            "expected a whole number of participants from 1 to " + std::to_string(kMaxCohortParticipants),
            [&] { return std::to_string(c.count); });
  // Every seed std::mt19937_64 takes (drawCohort), read exactly.
  a.whole("seed", c.seed, std::numeric_limits<std::uint64_t>::max(),
          "2^64 - 1 = 18446744073709551615, the seeds of the std::mt19937_64 that draws the cohort");
  a.path("template", c.templatePath);
  bool overridesKnee = !c.study.kneeModelOverride.empty();
  if constexpr (A::kReading) overridesKnee = a.has("knee_model");
  if (overridesKnee) a.path("knee_model", c.study.kneeModelOverride);
  bool present = true;
  a.optionalMap("lowering", c.study, present, LoweringOf{});
  a.optionalMap("integrator", c.study.swing, present = true);
  a.map("distributions", c, DistributionsOf{});
  a.optionalText("output_dir", c.study.outputDir);
}

namespace {

// Draws the participants; a drawn leg that is impossible (makeCohortParticipant) is refused
// at `distributions`, naming the participant and the key. The lowering grid then stops
// where each leg runs out (calcMaxLowering), so every lowering swept passes calcLegGeometry.
void drawCheckedParticipants(Cohort& c, const Participant& templ, const YamlMap& yaml) {
  try {
    drawCohortParticipants(c, templ);
  } catch (const InputError& e) {
    yaml.fail("distributions",
              "expected distributions whose every draw is a leg a participant file may hold (narrow the one named)",
              e.what());
  }
}

Cohort readCohortStudy(YamlMap& yaml, const std::string& path,
                       const std::function<void(const Cohort&)>& beforeDrawing) {
  Cohort c;
  c.study.path = path;
  c.study.includePublishedLowerings = false;  // Table 4's lowerings belong to Burkett's four
  YamlReadArchive a(yaml);
  serialize(a, c);
  const Participant templ = loadParticipant(c.templatePath);
  if (templ.drive != SwingDrive::kHipMoment)
    yaml.fail("template",
              "expected a participant driven by a hip moment (its time scale is calibrated to each drawn "
              "swing time)",
              templ.path + " (drive: thigh_kinematics)");
  yaml.finish();
  if (beforeDrawing) beforeDrawing(c);
  drawCheckedParticipants(c, templ, yaml);
  for (const auto& p : c.study.participants) {
    const std::string modelPath = studyKneeModelPath(c.study, p);
    if (!c.study.kneeModels.count(modelPath)) c.study.kneeModels.emplace(modelPath, loadKneeModel(modelPath));
  }
  return c;
}

}  // namespace

bool isCohortStudyFile(const std::string& path) {
  try {
    YamlMap yaml = YamlMap::loadFile(path);
    return yaml.has("kind") && yaml.getString("kind") == "cohort-sweep";
  } catch (const std::exception&) {
    return false;
  }
}

Cohort loadCohortStudy(const std::string& path, const std::function<void(const Cohort&)>& beforeDrawing) {
  YamlMap yaml = YamlMap::loadFile(path);
  return readCohortStudy(yaml, path, beforeDrawing);
}

Cohort parseCohortStudy(const std::string& text, const std::string& path) {
  YamlMap yaml = YamlMap::loadString(text, path);
  return readCohortStudy(yaml, path, {});
}

}  // namespace swingsim
