// swingsim import-osim MODEL.osim [--side r|l] [--out FILE] [--name NAME] [prosthesis options]
//
// A participant YAML from one leg of a scaled OpenSim model (io/osim_model.h): thigh, shank
// and foot from the model's bodies and joint centres, every other field the project's
// default, each number's source in the file's leading comments (docs/import-osim.md).

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
#include "study/osim_import.h"

namespace swingsim::cli {
namespace {

struct ImportOsimArguments {
  std::string model;
  std::string side = "r";
  std::optional<std::string> out, name, knee;
  ImportPartNames parts;
  OsimImportOptions options;
};

int runImportOsim(ImportOsimArguments& a) {
  OsimImportOptions o = a.options;
  o.parts = chooseImportParts(a.parts, [](const std::string& key) {
    return key == "catalogue" ? std::string("--parts-catalogue") : "--" + key + "-part";
  });
  o.side = a.side.front();
  o.name = a.name.value_or("");
  o.kneeModelPath = std::filesystem::absolute(a.knee.value_or(defaultImportKneePath())).lexically_normal().string();
  checkOutputsAreNotInputs({{"MODEL.osim", a.model}, {"--knee", o.kneeModelPath}}, {{"--out", a.out.value_or("")}});
  const std::string dir = a.out ? (std::filesystem::path(*a.out).parent_path().empty()
                                       ? "."
                                       : std::filesystem::path(*a.out).parent_path().string())
                                : ".";
  const ImportedParticipantYaml imported = importOsimParticipant(a.model, o, dir);
  const std::string& text = imported.text;
  if (a.out) {
    writeFileAtomic(*a.out, text);
    std::fprintf(stderr, "import-osim: wrote %s (%s)\n", a.out->c_str(), imported.name.c_str());
  } else {
    std::printf("%s", text.c_str());
  }
  return 0;
}

}  // namespace

Command addImportOsimCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "import-osim",
      "a participant YAML from one leg of a scaled OpenSim 4 model (.osim): thigh, shank, foot, hip offset");
  auto a = std::make_shared<ImportOsimArguments>();
  sub->add_option("MODEL.osim", a->model, "scaled OpenSim 4 model")->required()->type_name("");
  sub->add_option("--side", a->side, "which leg: r (femur_r, tibia_r, talus_r, calcn_r, toes_r) or l (default r)")
      ->type_name("r|l")
      ->check(oneOf({"r", "l"}));
  addTextOption(sub, "--out", a->out, "participant YAML to write (default: print it)", "FILE");
  addTextOption(sub, "--name", a->name, "participant name (default <model name>_<side>)", "NAME");
  addTextOption(sub, "--knee", a->knee,
                "knee model YAML written as knee_model (default models/damping-table-default.yaml)", "MODEL.yaml");
  OsimImportOptions& o = a->options;
  sub->add_option("--knee-friction-Nm", o.kneeFriction, "knee friction moment of the prosthesis, N m (default 0)")
      ->type_name("NM")
      ->check(finiteNumber(checkKneeFriction));
  const auto positive = finiteNumber(checkPositive);
  sub->add_option_function<double>(
         "--shank-mass-kg", [&o](double v) { o.shankMass = v; },
         "the prosthetic shank's mass, kg (default: the model's tibia; inertia scales with it)")
      ->type_name("KG")
      ->check(positive);
  sub->add_option_function<double>(
         "--foot-mass-kg", [&o](double v) { o.footMass = v; },
         "the prosthetic foot's mass, kg (default: the model's talus + calcn + toes; inertia scales with it)")
      ->type_name("KG")
      ->check(positive);
  addTextOption(sub, "--knee-part", a->parts.knee,
                "the knee unit by its catalogue id (`swingsim parts` lists them): its mass, COM and inertia make the "
                "shank with the other shank parts (instead of --shank-mass-kg)",
                "ID");
  addTextOption(sub, "--pylon-part", a->parts.pylon, "the pylon by its catalogue id (its mass per metre over the span)",
                "ID");
  addTextOption(sub, "--ankle-part", a->parts.ankle, "an ankle unit carried by the shank, by its catalogue id", "ID");
  addTextOption(sub, "--foot-part", a->parts.foot, "the foot by its catalogue id (instead of --foot-mass-kg)", "ID");
  addTextOption(sub, "--parts-catalogue", a->parts.catalogue,
                "the parts catalogue YAML (default parts/prosthesis-parts.yaml, shipped)", "FILE");
  sub->add_option_function<double>(
         "--foot-length-m", [&o](double v) { o.footLength = v; },
         "ankle to toe, m (default: from the model's MTP joint and toes)")
      ->type_name("M")
      ->check(positive);
  sub->add_option_function<double>(
         "--height-m", [&o](double v) { o.height = v; },
         "standing height, m (default: hip-to-ankle length / 0.491, Winter 2009)")
      ->type_name("M")
      ->check(positive);
  return {sub, [a] { return runImportOsim(*a); }};
}

}  // namespace swingsim::cli
