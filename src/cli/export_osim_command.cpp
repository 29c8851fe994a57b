// swingsim export-osim PARTICIPANT.yaml [--side r|l] [--lowering M] [--add-mass KG@M] [--out DIR]
//
// The simulated leg as an OpenSim 4 model (io/osim_model_writer.h), written beside the
// trajectory .sto that `simulate` writes for the same participant and lowering (same folder
// default, same file stem), whose hip_flexion_<side> and knee_angle_<side> columns are the
// model's coordinates, as a lab's IK file names them, so OpenSim plays the simulated swing and
// the lab's own motion on it (docs/export-osim.md).

#include <algorithm>
#include <array>
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
#include "io/participant_loader.h"
#include "io/trajectory_writer.h"
#include "study/osim_export.h"

namespace swingsim::cli {
namespace {

struct ExportOsimArguments {
  std::string participant;
  std::string side = "r";
  double lowering = 0;             ///< m
  std::optional<AddedMass> added;  ///< --add-mass: on the shank, below the knee
  std::optional<std::string> out;
};

int runExportOsim(const ExportOsimArguments& a) {
  const Participant p = loadParticipant(a.participant);
  const KneeModel knee = loadKneeModel(p.kneeModelPath);
  const std::string stem = makeTrajectoryFileStem(p.name, a.lowering);
  const std::string text =
      formatParticipantOsim(p, knee, OsimExportOptions{a.side.front(), a.lowering, a.added}, stem + ".sto");
  const std::string path = a.out.value_or(makeTrajectoryFolder(p.name)) + "/" + stem + ".osim";
  checkOutputsAreNotInputs({{"PARTICIPANT.yaml", a.participant}, {"PARTICIPANT.yaml: knee_model", p.kneeModelPath}},
                           {{"--out", path}});
  writeFileAtomic(path, text);
  std::printf("export-osim: wrote %s (%s, %s leg, knee lowered %s m%s)\n", path.c_str(), p.name.c_str(),
              a.side == "l" ? "left" : "right", formatNumber(a.lowering).c_str(),
              a.added ? (", added mass " + formatNumber(a.added->mass) + " kg").c_str() : "");
  return 0;
}

}  // namespace

Command addExportOsimCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "export-osim", "the simulated leg as an OpenSim 4 model (.osim) that plays simulate's trajectory .sto");
  auto a = std::make_shared<ExportOsimArguments>();
  sub->add_option("PARTICIPANT.yaml", a->participant, "participant file")->required()->type_name("");
  sub->add_option("--side", a->side,
                  "which leg: r or l; names bodies, joints and coordinates as OpenSim's gait models (femur_<side>, "
                  "hip_flexion_<side>, knee_angle_<side>) (default r)")
      ->type_name("r|l")
      ->check(oneOf({"r", "l"}));
  sub->add_option("--lowering", a->lowering, "knee-axis lowering below the standard location, m (default 0)")
      ->type_name("M")
      ->check(finiteNumber(checkLowering));
  sub->add_option_function<std::string>(
         "--add-mass", [a](const std::string& v) { a->added = readAddedMass(v); },
         "added shank mass as KG@METRES below the knee, e.g. 0.5@0.2, as simulate's: a point mass welded "
         "to the tibia (default none)")
      ->type_name("KG@M")
      ->check(addedMassSpec());
  addTextOption(sub, "--out", a->out,
                "output folder (default out/simulate-<participant>/, beside simulate's .sto); the file is "
                "<participant>-lowerNNNmm.osim",
                "DIR");
  return {sub, [a] { return runExportOsim(*a); }};
}

}  // namespace swingsim::cli
