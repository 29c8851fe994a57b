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
#include "io/osim_model_writer.h"
#include "io/participant_loader.h"
#include "io/trajectory_writer.h"
#include "swing/swing_simulation.h"

namespace swingsim::cli {
namespace {

struct ExportOsimArguments {
  std::string participant;
  std::string side = "r";
  double lowering = 0;  ///< m
  std::optional<AddedMass> added;  ///< --add-mass: on the shank, below the knee
  std::optional<std::string> out;
};

// Under a measured drive the model starts where the swing does, at the record's toe-off (its
// first sample): the hip at the thigh's angle less the pelvis tilt (hip_flexion is in the
// pelvis), the knee at the record's when it has one and `knee_start` is measured; a measured
// pelvis moves on its planar joint from its toe-off pose (a column the record lacks keeps the
// welded pose's value).
void applyMeasuredDrive(const ThighKinematics& t, const InitialConditions& initial, OsimLegPlacement& place) {
  const bool hasPelvis = !t.pelvisX.empty() || !t.pelvisY.empty() || !t.pelvisTilt.empty();
  if (hasPelvis) {
    const std::array<double, 2> hip = place.hipOffsetInPelvis.value_or(std::array<double, 2>{0, 0});
    OsimPelvisPose at{0, -hip[0], place.hipHeight - hip[1]};
    if (!t.pelvisTilt.empty()) at.tilt = t.pelvisTilt.front();
    if (!t.pelvisX.empty()) at.x = t.pelvisX.front();
    if (!t.pelvisY.empty()) at.y = t.pelvisY.front();
    place.measuredPelvis = at;
  }
  if (!t.hipFlexion.empty()) place.initial.hipFlexion = t.hipFlexion.front() - (t.pelvisTilt.empty() ? 0.0 : t.pelvisTilt.front());
  if (!t.kneeFlexion.empty() && initial.kneeStart == KneeStart::kMeasured) place.initial.kneeFlexion = t.kneeFlexion.front();
}

// The participant's hip height, body mass, initial state, hip range and its knee model's stop.
OsimLegPlacement makePlacement(const Participant& p, const KneeModel& knee, char side) {
  OsimLegPlacement place;
  place.modelName = p.name;
  place.side = side;
  place.hipHeight = calcHipHeight(p);
  place.hipOffsetInPelvis = p.hipOffsetInPelvis;
  place.bodyMass = p.bodyMass;
  place.initial = p.initial;
  place.hipRange = p.hipRange;
  place.kneeMinFlexion = knee.spec.stop.lower;
  // No flexion stop: the knee's physical range, 180 deg.
  place.kneeMaxFlexion = std::min(knee.spec.stop.upper.value_or(kKneeFlexionLimit), kKneeFlexionLimit);
  if (p.drive == SwingDrive::kThighKinematics) applyMeasuredDrive(p.thighKinematics, p.initial, place);
  return place;
}

std::string makeHeader(const Participant& p, const std::string& kneeName, const ExportOsimArguments& a, const std::string& stoName) {
  const char side = a.side.front();
  const std::string added = a.added ? ", added mass " + formatNumber(a.added->mass) + " kg " + formatNumber(a.added->distanceBelowKnee) +
                                          " m below the knee (body added_mass_" + a.side + ", welded to tibia_" + a.side + ")"
                                    : "";
  return "Written by `swingsim export-osim` from " + std::filesystem::path(p.path).filename().string() + " (participant " + p.name +
         "), " + (side == 'l' ? "left" : "right") + " leg, knee axis lowered " + formatNumber(a.lowering) + " m, knee model " + kneeName + added +
         ".\n  The planar leg swingsim simulates (docs/export-osim.md): pelvis welded to the ground with the hip at " +
         "0.530 x height (plus a stated toe_clearance.hip_rise_m), or, under a measured drive with a pelvis, on a PlanarJoint (pelvis_tilt, pelvis_tx, pelvis_ty) at its toe-off pose; femur, tibia: the thigh and shank (hip and knee pins); talus: the whole foot, welded at the ankle, "
         "perpendicular to the shank;\n  calcn and toes: massless, welded; toes' origin is the toe tip. Only Izz is swingsim's; "
         "Ixx, Iyy are a thin rod's. Shapes (cylinders, brick, ellipsoid) are for display only. No muscles, no knee damper: a model to play the swing on, not to simulate it again.\n"
         "  Play the swing: File > Load Motion " + stoName + " (written by `swingsim simulate" + (side == 'l' ? " --side l" : "") +
         "` for this participant at this lowering); its " + makeOsimHipCoordinate(side) + " and " + makeOsimKneeCoordinate(side) +
         " columns (degrees, inDegrees=yes, knee negative in flexion) are the coordinates, as in a lab's IK .mot.\n";
}

int runExportOsim(const ExportOsimArguments& a) {
  const Participant p = loadParticipant(a.participant);
  const LegGeometry geometry = calcLegGeometry(p, a.lowering, a.added.value_or(AddedMass{}));
  const KneeModel knee = loadKneeModel(p.kneeModelPath);
  const std::string stem = makeTrajectoryFileStem(p.name, a.lowering);
  const std::string text =
      formatOsimModel(makeOsimLegModel(geometry, makePlacement(p, knee, a.side.front())), makeHeader(p, knee.name, a, stem + ".sto"));
  const std::string path = a.out.value_or(makeTrajectoryFolder(p.name)) + "/" + stem + ".osim";
  checkOutputsAreNotInputs({{"PARTICIPANT.yaml", a.participant}, {"PARTICIPANT.yaml: knee_model", p.kneeModelPath}},
                           {{"--out", path}});
  writeFileAtomic(path, text);
  std::printf("export-osim: wrote %s (%s, %s leg, knee lowered %s m%s)\n", path.c_str(), p.name.c_str(), a.side == "l" ? "left" : "right",
              formatNumber(a.lowering).c_str(), a.added ? (", added mass " + formatNumber(a.added->mass) + " kg").c_str() : "");
  return 0;
}

}  // namespace

Command addExportOsimCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("export-osim", "the simulated leg as an OpenSim 4 model (.osim) that plays simulate's trajectory .sto");
  auto a = std::make_shared<ExportOsimArguments>();
  sub->add_option("PARTICIPANT.yaml", a->participant, "participant file")->required()->type_name("");
  sub->add_option("--side", a->side, "which leg: r or l; names bodies, joints and coordinates as OpenSim's gait models (femur_<side>, "
                  "hip_flexion_<side>, knee_angle_<side>) (default r)")
      ->type_name("r|l")
      ->check(oneOf({"r", "l"}));
  sub->add_option("--lowering", a->lowering, "knee-axis lowering below the standard location, m (default 0)")
      ->type_name("M")
      ->check(finiteNumber(checkLowering));
  sub->add_option_function<std::string>("--add-mass", [a](const std::string& v) { a->added = readAddedMass(v); },
                                        "added shank mass as KG@METRES below the knee, e.g. 0.5@0.2, as simulate's: a point mass welded "
                                        "to the tibia (default none)")
      ->type_name("KG@M")
      ->check(addedMassSpec());
  addTextOption(sub, "--out", a->out,
                "output folder (default out/simulate-<participant>/, beside simulate's .sto); the file is <participant>-lowerNNNmm.osim",
                "DIR");
  return {sub, [a] { return runExportOsim(*a); }};
}

}  // namespace swingsim::cli
