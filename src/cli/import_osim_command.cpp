// swingsim import-osim MODEL.osim [--side r|l] [--out FILE] [--name NAME] [prosthesis options]
//
// A participant YAML from one leg of a scaled OpenSim model (io/osim_model.h): thigh, shank
// and foot from the model's bodies and joint centres, every other field the project's
// default, each number's source in the file's leading comments (docs/import-osim.md).

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "core/input_error.h"
#include "core/output_files.h"
#include "io/knee_model_loader.h"
#include "io/osim_model.h"
#include "io/participant_loader.h"

namespace swingsim::cli {
namespace {

// The project's default knee: the damping table the Burkett participants use.
const std::string kDefaultKnee = std::string(SWINGSIM_SOURCE_DIR) + "/models/damping-table-default.yaml";

// The name the imported participant is checked under, and a message without it and its
// line ("imported-participant.yaml:20: segments..." -> "segments...").
const std::string kImportedName = "imported-participant.yaml";
std::string dropImportedPrefix(const std::string& message) {
  const auto at = message.find(kImportedName + ":");
  if (at == std::string::npos) return message;
  std::size_t rest = at + kImportedName.size() + 1;
  while (rest < message.size() && std::isdigit(static_cast<unsigned char>(message[rest]))) ++rest;
  if (message.compare(rest, 2, ": ") == 0) rest += 2;
  return message.substr(rest);
}

struct ImportOsimArguments {
  std::string model;
  std::string side = "r";
  std::optional<std::string> out, name, knee;
  OsimImportOptions options;
};

int runImportOsim(ImportOsimArguments& a) {
  OsimImportOptions o = a.options;
  o.side = a.side.front();
  o.name = a.name.value_or("");
  o.kneeModelPath = std::filesystem::absolute(a.knee.value_or(kDefaultKnee)).lexically_normal().string();
  checkOutputsAreNotInputs({{"MODEL.osim", a.model}, {"--knee", o.kneeModelPath}}, {{"--out", a.out.value_or("")}});
  loadKneeModel(o.kneeModelPath);  // a knee model that does not load is refused before anything is written
  const OsimParticipant imported = calcOsimParticipant(loadOsimModel(a.model), o);
  const std::string dir =
      a.out ? (std::filesystem::path(*a.out).parent_path().empty() ? "." : std::filesystem::path(*a.out).parent_path().string()) : ".";
  const std::string text = formatParticipantYaml(imported.participant, dir, imported.provenance);
  // What is written loads as it is: the loader's checks apply here, before any file is
  // written. The model's own checks (io/osim_model_checks.h) come first and name its
  // element; one the loader still refuses is named by the model, not by a YAML not written.
  try {
    parseParticipant(text, dir + "/" + kImportedName);
  } catch (const InputError& e) {
    throw InputError(a.model + ": the participant imported from it is refused: " + dropImportedPrefix(e.what()) +
                     " (in the participant YAML, not written)");
  }
  if (a.out) {
    writeFileAtomic(*a.out, text);
    std::fprintf(stderr, "import-osim: wrote %s (%s)\n", a.out->c_str(), imported.participant.name.c_str());
  } else {
    std::printf("%s", text.c_str());
  }
  return 0;
}

}  // namespace

Command addImportOsimCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "import-osim", "a participant YAML from one leg of a scaled OpenSim 4 model (.osim): thigh, shank, foot, hip offset");
  auto a = std::make_shared<ImportOsimArguments>();
  sub->add_option("MODEL.osim", a->model, "scaled OpenSim 4 model")->required()->type_name("");
  sub->add_option("--side", a->side, "which leg: r (femur_r, tibia_r, talus_r, calcn_r, toes_r) or l (default r)")
      ->type_name("r|l")
      ->check(oneOf({"r", "l"}));
  addTextOption(sub, "--out", a->out, "participant YAML to write (default: print it)", "FILE");
  addTextOption(sub, "--name", a->name, "participant name (default <model name>_<side>)", "NAME");
  addTextOption(sub, "--knee", a->knee, "knee model YAML written as knee_model (default models/damping-table-default.yaml)",
                "MODEL.yaml");
  OsimImportOptions& o = a->options;
  sub->add_option("--knee-friction-Nm", o.kneeFriction, "knee friction moment of the prosthesis, N m (default 0)")
      ->type_name("NM")
      ->check(finiteNumber([](double v) { return v >= 0 ? "" : "expected a moment >= 0 N m"; }));
  const auto positive = finiteNumber([](double v) { return v > 0 ? "" : "expected a positive value"; });
  sub->add_option_function<double>("--shank-mass-kg", [&o](double v) { o.shankMass = v; },
                                   "the prosthetic shank's mass, kg (default: the model's tibia; inertia scales with it)")
      ->type_name("KG")
      ->check(positive);
  sub->add_option_function<double>("--foot-mass-kg", [&o](double v) { o.footMass = v; },
                                   "the prosthetic foot's mass, kg (default: the model's talus + calcn + toes; inertia scales with it)")
      ->type_name("KG")
      ->check(positive);
  sub->add_option_function<double>("--foot-length-m", [&o](double v) { o.footLength = v; },
                                   "ankle to toe, m (default: from the model's MTP joint and toes)")
      ->type_name("M")
      ->check(positive);
  sub->add_option_function<double>("--height-m", [&o](double v) { o.height = v; },
                                   "standing height, m (default: hip-to-ankle length / 0.491, Winter 2009)")
      ->type_name("M")
      ->check(positive);
  return {sub, [a] { return runImportOsim(*a); }};
}

}  // namespace swingsim::cli
