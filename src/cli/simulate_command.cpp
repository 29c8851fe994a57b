// swingsim simulate PARTICIPANT.yaml [--side r|l] [--lowering M] [--knee MODEL.yaml] [--add-mass KG@M]
//   [--hip-rate-deg-s DEG/S] [--knee-rate-deg-s DEG/S] [--knee-start measured|initial]
//   [--integrator METHOD] [--accuracy A]
//   [--json FILE] [--out DIR]
#include <cstdio>
#include <optional>
#include <string>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "core/output_files.h"
#include "core/plausible_ranges.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "io/trajectory_writer.h"
#include "report/swing_json.h"
#include "report/swing_plot.h"
#include "study/simulate_run.h"

namespace swingsim::cli {
namespace {

/// What `swingsim simulate` was given; nullopt: not given (the default applies).
struct SimulateArguments {
  std::string participant;
  std::string side = "r";  ///< the leg the .sto's columns name (hip_flexion_<side>, knee_angle_<side>)
  double lowering = 0;     ///< m
  std::optional<std::string> knee;
  std::optional<AddedMass> added;
  std::optional<double> hipRateDegS, kneeRateDegS;  ///< deg/s
  std::optional<std::string> kneeStart;             ///< "measured" or "initial"
  std::optional<std::string> integrator;
  std::optional<double> accuracy;
  std::optional<std::string> json, out;
};

// The participant's file with the toe-off rates and knee start the command line overrides.
Participant loadSimulatedParticipant(const SimulateArguments& a) {
  Participant loaded = loadParticipant(a.participant);
  ToeOffOverrides overrides;
  if (a.hipRateDegS) overrides.hipFlexionRate = *a.hipRateDegS * kDegToRad;
  if (a.kneeRateDegS) overrides.kneeFlexionRate = *a.kneeRateDegS * kDegToRad;
  if (a.kneeStart) overrides.kneeStart = *a.kneeStart == "initial" ? KneeStart::kInitial : KneeStart::kMeasured;
  applyToeOffOverrides(loaded, overrides, "--knee-rate-deg-s");
  return loaded;
}

// The trajectory's CSV and .sto, the moments' plot, and the JSON if --json asked for it.
void writeSimulateFiles(const SimulateArguments& a, const SwingSetup& setup, const SwingResult& r) {
  const Participant& p = setup.participant;
  const std::string out = a.out.value_or(makeTrajectoryFolder(p.name));
  const std::string tag = makeTrajectoryFileStem(p.name, setup.lowering);
  // One staged set: a full disk or a folder in the way leaves none of them, not a CSV alone.
  StagedOutput staged(out);
  staged.add(tag + ".csv", formatTrajectoryCsv(r.trajectory));
  staged.add(tag + ".sto", formatTrajectorySto(r.trajectory, tag, a.side.front()));
  staged.add(tag + "-moments.svg", formatSwingMomentsSvg(r.trajectory, p.name + ", drive: " + driveKey(p.drive)));
  if (a.json) staged.addBeside(*a.json, formatJson(makeSimulateJson(setup, r)));
  staged.commit();
  std::printf("  trajectory          %s/%s.csv and .sto; hip and knee moments %s-moments.svg\n", out.c_str(),
              tag.c_str(), tag.c_str());
}

int runSimulateCommand(const SimulateArguments& a) {
  const SwingOptions options = makeSimulateOptions(a.integrator, a.accuracy);
  Participant loaded = loadSimulatedParticipant(a);
  const KneeModel model = loadKneeModel(a.knee.value_or(loaded.kneeModelPath));
  SwingSetup setup = makeSwingSetup(std::move(loaded), model, a.lowering, a.added.value_or(AddedMass{}));
  const std::string tag = makeTrajectoryFileStem(setup.participant.name, setup.lowering);
  checkOutputsAreNotInputs(
      {{"PARTICIPANT.yaml", a.participant}, {a.knee ? "--knee" : "PARTICIPANT.yaml: knee_model", model.path}},
      listRunOutputs(a.out.value_or(makeTrajectoryFolder(setup.participant.name)),
                     {tag + ".csv", tag + ".sto", tag + "-moments.svg"}, a.json));
  const SimulateRun run = runSimulate(std::move(setup), options);
  std::fputs(formatSimulateSummary(run, model, options).c_str(), stdout);
  writeSimulateFiles(a, run.setup, run.result);
  return 0;
}

}  // namespace

Command addSimulateCommand(CLI::App& app) {
  CLI::App* sub =
      app.add_subcommand("simulate", "simulate one swing: swing time, peak knee flexion, events, trajectory CSV/.sto");
  auto a = std::make_shared<SimulateArguments>();
  std::string integrators;
  for (const auto& k : integratorKeys()) integrators += (integrators.empty() ? "" : ", ") + k;
  sub->add_option("PARTICIPANT.yaml", a->participant, "participant file")->required()->type_name("");
  sub->add_option("--side", a->side,
                  "the leg the trajectory .sto names: hip_flexion_<side>, knee_angle_<side>, as export-osim --side "
                  "and a lab's IK file (default r)")
      ->type_name("r|l")
      ->check(oneOf({"r", "l"}));
  sub->add_option("--lowering", a->lowering, "knee-axis lowering below the standard location, m (default 0)")
      ->type_name("M")
      ->check(finiteNumber(checkLowering));
  sub->add_option_function<std::string>(
         "--knee", [a](const std::string& v) { a->knee = v; },
         "knee model YAML (default: the participant's knee_model)")
      ->type_name("MODEL.yaml");
  sub->add_option_function<std::string>(
         "--add-mass", [a](const std::string& v) { a->added = readAddedMass(v); },
         "added shank mass as KG@METRES below the knee, e.g. 0.5@0.2 (default none)")
      ->type_name("KG@M")
      ->check(addedMassSpec());
  sub->add_option_function<double>(
         "--hip-rate-deg-s", [a](double v) { a->hipRateDegS = v; },
         "hip flexion rate at toe-off, deg/s (default: the participant's, 0)")
      ->type_name("DEG/S")
      ->check(finiteNumber([](double v) { return checkPlausible(v, kJointRateRange, "a hip rate"); }));
  addTextOption(sub, "--knee-start", a->kneeStart,
                "under the measured thigh drive, where the knee starts: measured (the record's angle and rate at "
                "toe-off) or initial "
                "(the participant's initial values); default: the participant's initial.knee_start, measured if absent",
                "measured|initial")
      ->check(oneOf({"measured", "initial"}));
  sub->add_option_function<double>(
         "--knee-rate-deg-s", [a](double v) { a->kneeRateDegS = v; },
         "knee flexion rate at toe-off, deg/s (default: the participant's, 0)")
      ->type_name("DEG/S")
      ->check(finiteNumber([](double v) { return checkPlausible(v, kJointRateRange, "a knee rate"); }));
  sub->add_option_function<std::string>(
         "--integrator", [a](const std::string& v) { a->integrator = v; },
         "integration method, one of " + integrators + " (default " + integratorKeys().front() +
             "), at its converged accuracy")
      ->type_name("METHOD")
      ->check(oneOf(integratorKeys()));
  sub->add_option_function<double>(
         "--accuracy", [a](double v) { a->accuracy = v; },
         "integrator relative accuracy, [1e-14, 0.01] (default: the integrator's converged one)")
      ->type_name("A")
      ->check(finiteNumber(checkAccuracy));
  addJsonOption(sub, a->json);
  addTextOption(sub, "--out", a->out, "output folder for the trajectory (default out/simulate-<participant>/)", "DIR");
  return {sub, [a] { return runSimulateCommand(*a); }};
}

}  // namespace swingsim::cli
