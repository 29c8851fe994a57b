// swingsim generate STUDY.yaml: synthetic measurement data from a model. The study's
// `kind:` selects the generator; each kind has one function here.
#include <cstdio>
#include <functional>
#include <map>
#include <optional>
#include <string>

#include "io/bench_csv.h"
#include "cli/command.h"
#include "cli/generate_swing_kinematics.h"
#include "identify/bench_data.h"
#include "knee/bench_profile.h"
#include "io/csv_table.h"
#include "study/cylinder_study.h"
#include "core/input_error.h"
#include "io/knee_model_loader.h"
#include "core/output_files.h"
#include "core/output_paths.h"
#include "io/yaml_reader.h"

namespace swingsim::cli {

namespace {

// kind: cylinder-bench. Everything is computed before the first file is written. `outDir`:
// --out, if given.
int generateCylinderBench(YamlMap& yaml, const std::optional<std::string>& outDir) {
  CylinderBenchStudy study = readCylinderBenchStudy(yaml);
  yaml.finish();
  if (outDir) study.outputDir = *outDir;
  else checkOutputFolder(study.outputDir, study.path + ": output_dir");  // before any work
  MauchCylinderParams truthParams = loadMauchCylinder(study.modelPath);
  // Hidden effects: the truth gets them, the fitted models do not know.
  truthParams.effects = study.hiddenEffects;
  if (study.hiddenLatchTimeConstant > 0) truthParams.switches.latchRate = 1.0 / study.hiddenLatchTimeConstant;
  MauchCylinder truth = [&] {
    try {
      return MauchCylinder(truthParams);
    } catch (const std::invalid_argument& e) {
      throw InputError(study.path + ": hidden_effects: " + e.what());
    }
  }();
  const KneeAngleStride stride = readKneeAngleStride(study.kneeAnglesPath, study.strideFirstFrame, study.strideLastFrame);

  std::vector<std::pair<std::string, std::string>> files;
  const bool hidden = study.hiddenEffects.any() || study.hiddenLatchTimeConstant > 0;
  const MauchCylinder plain(loadMauchCylinder(study.modelPath));
  std::printf("%-8s %8s %9s %8s %10s %10s %10s%s\n", "file", "stride_s", "amplitude", "samples", "x_min_mm", "x_max_mm",
              "F_rms_N", hidden ? "  hidden_rms_N" : "");
  for (std::size_t i = 0; i < study.conditions.size(); ++i) {
    const auto& c = study.conditions[i];
    BenchProfileParams p = study.profile;
    p.strideTime = c.strideTime;
    p.amplitudeScale = c.amplitudeScale;
    BenchProfile profile;
    try {
      profile = makeBenchProfile(stride, p, truth.geometry());
    } catch (const std::invalid_argument& e) {
      throw InputError(study.path + ": conditions[" + std::to_string(i) + "] (" + c.name + "): " + e.what());
    }
    const auto velocity = estimatePistonVelocity(profile.time, profile.position);
    auto force = calcCylinderTrace(truth, profile.time, profile.position, velocity, 0.0).force;
    double hiddenSq = 0;  // force of the hidden effects: truth minus the model without them
    if (hidden) {
      const auto plainForce = calcCylinderTrace(plain, profile.time, profile.position, velocity, 0.0).force;
      for (std::size_t k = 0; k < force.size(); ++k) hiddenSq += (force[k] - plainForce[k]) * (force[k] - plainForce[k]);
    }
    NormalNoise noise(study.seed + i);
    double sumSq = 0;
    for (double& f : force) {
      f += study.noise * noise.next();
      sumSq += f * f;
    }
    files.emplace_back(study.outputDir + "/" + c.name + ".csv",
                       formatCsv({"time_s", "position_m", "force_N"}, {profile.time, profile.position, force}));
    double xmin = 1e9, xmax = -1e9;
    for (double x : profile.position) {
      xmin = std::min(xmin, x);
      xmax = std::max(xmax, x);
    }
    std::printf("%-8s %8.3f %9.3f %8zu %10.3f %10.3f %10.1f", c.name.c_str(), c.strideTime, c.amplitudeScale,
                profile.time.size(), 1e3 * xmin, 1e3 * xmax, std::sqrt(sumSq / static_cast<double>(force.size())));
    if (hidden) std::printf("  %12.1f", std::sqrt(hiddenSq / static_cast<double>(force.size())));
    std::printf("\n");
  }
  std::vector<CommandFile> outputs;
  for (const auto& file : files) outputs.push_back({"STUDY.yaml: output_dir (or --out)", file.first});
  checkOutputsAreNotInputs({{"STUDY.yaml", study.path}, {"STUDY.yaml: model", study.modelPath}}, outputs);
  for (const auto& [path, text] : files) writeFileAtomic(path, text);
  std::printf("wrote %zu bench files to %s (truth %s, noise %s N, seed %llu)\n", files.size(), study.outputDir.c_str(),
              truth.name().c_str(), formatNumber(study.noise).c_str(), static_cast<unsigned long long>(study.seed));
  return 0;
}

using Generator = std::function<int(YamlMap&, const std::optional<std::string>& outDir)>;

const std::map<std::string, Generator>& generators() {
  static const std::map<std::string, Generator> g = {{"cylinder-bench", generateCylinderBench},
                                                              {"swing-kinematics", generateSwingKinematics}};
  return g;
}

/// What `swingsim generate` was given; nullopt: not given (the default applies).
struct GenerateArguments {
  std::string study;
  std::optional<std::string> out;
};

int runGenerate(const GenerateArguments& args) {
  YamlMap yaml = YamlMap::loadFile(args.study);
  std::vector<std::string> kinds;
  for (const auto& kv : generators()) kinds.push_back(kv.first);
  if (!yaml.has("kind")) yaml.getString("kind");  // "required key is missing"
  const std::string kind = yaml.getChoice("kind", kinds, "");
  return generators().at(kind)(yaml, args.out);
}

}  // namespace

Command addGenerateCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "generate", "synthetic measurement data (cylinder bench records, swing kinematics) from a model, noise and seed");
  auto a = std::make_shared<GenerateArguments>();
  sub->add_option("STUDY.yaml", a->study, "study of kind cylinder-bench or swing-kinematics")->required()->type_name("");
  addTextOption(sub, "--out", a->out, "output folder for the CSV files (default: the study's output_dir)", "DIR");
  return {sub, [a] { return runGenerate(*a); }};
}

}  // namespace swingsim::cli
