// swingsim export-osim PARTICIPANT.yaml [--lowering M] [--out DIR]
//
// The simulated leg as an OpenSim 4 model (io/osim_model_writer.h), written beside the
// trajectory .sto that `simulate` writes for the same participant and lowering (same folder
// default, same file stem), whose hip_flexion and knee_flexion columns are the model's
// coordinates, so OpenSim plays the simulated swing on it (docs/export-osim.md).

#include <algorithm>
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
#include "io/osim_model_writer.h"
#include "io/participant_loader.h"
#include "io/trajectory_writer.h"
#include "swing/swing_simulation.h"

namespace swingsim::cli {
namespace {

struct ExportOsimArguments {
  std::string participant;
  double lowering = 0;  ///< m
  std::optional<std::string> out;
};

// The participant's hip height, body mass, initial state, hip range and its knee model's stop.
OsimLegPlacement makePlacement(const Participant& p, const KneeModel& knee) {
  OsimLegPlacement place;
  place.modelName = p.name;
  place.hipHeight = calcHipHeight(p);
  place.hipOffsetInPelvis = p.hipOffsetInPelvis;
  place.bodyMass = p.bodyMass;
  place.initial = p.initial;
  place.hipRange = p.hipRange;
  place.kneeMinFlexion = knee.spec.stop.lower;
  // No flexion stop: the knee's physical range, 180 deg.
  place.kneeMaxFlexion = std::min(knee.spec.stop.upper.value_or(kKneeFlexionLimit), kKneeFlexionLimit);
  return place;
}

std::string makeHeader(const Participant& p, const std::string& kneeName, double lowering, const std::string& stoName) {
  return "Written by `swingsim export-osim` from " + std::filesystem::path(p.path).filename().string() + " (participant " + p.name +
         "), knee axis lowered " + formatNumber(lowering) + " m, knee model " + kneeName +
         ".\n  The planar leg swingsim simulates (docs/export-osim.md): pelvis welded to the ground with the hip at " +
         "0.530 x height (plus a stated toe_clearance.hip_rise_m); femur_r, tibia_r: the thigh and shank (hip and knee pins); talus_r: the whole foot, welded at the ankle, "
         "perpendicular to the shank;\n  calcn_r and toes_r: massless, welded; toes_r's origin is the toe tip. Only Izz is swingsim's; "
         "Ixx, Iyy are a thin rod's. No muscles, no knee damper: a model to play the swing on, not to simulate it again.\n"
         "  Play the swing: File > Load Motion " + stoName + " (written by `swingsim simulate` for this participant at this lowering);"
         " its hip_flexion and knee_flexion columns (degrees, inDegrees=yes) are the coordinates.\n";
}

int runExportOsim(const ExportOsimArguments& a) {
  const Participant p = loadParticipant(a.participant);
  const LegGeometry geometry = calcLegGeometry(p, a.lowering);
  const KneeModel knee = loadKneeModel(p.kneeModelPath);
  const std::string stem = makeTrajectoryFileStem(p.name, a.lowering);
  const std::string text =
      formatOsimModel(makeOsimLegModel(geometry, makePlacement(p, knee)), makeHeader(p, knee.name, a.lowering, stem + ".sto"));
  const std::string path = a.out.value_or(makeTrajectoryFolder(p.name)) + "/" + stem + ".osim";
  checkOutputsAreNotInputs({{"PARTICIPANT.yaml", a.participant}, {"PARTICIPANT.yaml: knee_model", p.kneeModelPath}},
                           {{"--out", path}});
  writeFileAtomic(path, text);
  std::printf("export-osim: wrote %s (%s, knee lowered %s m)\n", path.c_str(), p.name.c_str(), formatNumber(a.lowering).c_str());
  return 0;
}

}  // namespace

Command addExportOsimCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("export-osim", "the simulated leg as an OpenSim 4 model (.osim) that plays simulate's trajectory .sto");
  auto a = std::make_shared<ExportOsimArguments>();
  sub->add_option("PARTICIPANT.yaml", a->participant, "participant file")->required()->type_name("");
  sub->add_option("--lowering", a->lowering, "knee-axis lowering below the standard location, m (default 0)")
      ->type_name("M")
      ->check(finiteNumber(checkLowering));
  addTextOption(sub, "--out", a->out,
                "output folder (default out/simulate-<participant>/, beside simulate's .sto); the file is <participant>-lowerNNNmm.osim",
                "DIR");
  return {sub, [a] { return runExportOsim(*a); }};
}

}  // namespace swingsim::cli
