// swingsim simulate PARTICIPANT.yaml [--side r|l] [--lowering M] [--knee MODEL.yaml] [--add-mass KG@M]
//   [--hip-rate-deg-s DEG/S] [--knee-rate-deg-s DEG/S] [--knee-start measured|initial]
//   [--integrator METHOD] [--accuracy A]
//   [--json FILE] [--out DIR]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "core/input_error.h"
#include "core/output_files.h"
#include "core/plausible_ranges.h"
#include "core/text_format.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "io/swing_record_csv.h"
#include "io/trajectory_writer.h"
#include "leg/toe_off_state.h"
#include "report/swing_json.h"
#include "report/swing_plot.h"
#include "swing/knee_setup.h"
#include "swing/swing_simulation.h"

namespace swingsim::cli {
namespace {

/// What `swingsim simulate` was given; nullopt: not given (the default applies).
struct SimulateArguments {
  std::string participant;
  std::string side = "r";  ///< the leg the .sto's columns name (hip_flexion_<side>, knee_angle_<side>)
  double lowering = 0;  ///< m
  std::optional<std::string> knee;
  std::optional<AddedMass> added;
  std::optional<double> hipRateDegS, kneeRateDegS;  ///< deg/s
  std::optional<std::string> kneeStart;              ///< "measured" or "initial"
  std::optional<std::string> integrator;
  std::optional<double> accuracy;
  std::optional<std::string> json, out;
};

// The measured knee at time t (s), rad, if the drive file is a swing kinematics CSV that
// has one (time_s, hip_flexion_deg, knee_flexion_deg); linear between samples.
std::optional<double> findMeasuredKnee(const ThighKinematics& drive, double t) {
  const std::string& path = drive.path;
  if (path.size() < 4 || path.compare(path.size() - 4, 4, ".csv") != 0) return std::nullopt;
  SwingRecord record;
  try {
    record = readSwingRecord(path);
  } catch (const InputError&) {
    return std::nullopt;  // the drive loaded; a file without a usable knee has nothing to compare
  }
  const std::vector<double>& time = record.time;
  if (time.empty() || t < time.front() || t > time.back()) return std::nullopt;
  const auto upper = std::lower_bound(time.begin(), time.end(), t);
  const std::size_t k = static_cast<std::size_t>(upper - time.begin());
  if (k == 0) return record.kneeFlexion.front();
  const double s = (t - time[k - 1]) / (time[k] - time[k - 1]);
  return record.kneeFlexion[k - 1] + s * (record.kneeFlexion[k] - record.kneeFlexion[k - 1]);
}

// A measured trial that ended before the swing did: the unmet condition and the numbers,
// the measured knee beside the model's where the drive file has one.
void printTrialEnd(const TrialEnd& e, const Participant& p) {
  std::printf("  swing time          not reached (%s)\n", e.unmet.c_str());
  std::printf("  trial end           %s\n", e.describe().c_str());
  std::printf("  at the trial's end  model knee %.1f deg", e.kneeFlexion * kRadToDeg);
  if (const auto measured = findMeasuredKnee(p.thighKinematics, e.time))
    std::printf(", measured knee %.1f deg", *measured * kRadToDeg);
  std::printf("; thigh %.1f deg (peak %.1f deg, target %.1f deg)\n", e.thighFlexion * kRadToDeg,
              e.thighPeak * kRadToDeg, e.thighTarget * kRadToDeg);
}

// The integrator and its accuracy: --integrator at its converged setting unless --accuracy
// says otherwise.
SwingOptions makeSwingOptions(const SimulateArguments& a) {
  SwingOptions options;
  if (a.integrator) {
    options.integrator = *findIntegrator(*a.integrator);  // checked while parsing
    options.accuracy = calcConvergedAccuracy(options.integrator);  // its converged setting unless --accuracy says otherwise
  }
  if (a.accuracy) options.accuracy = *a.accuracy;
  return options;
}

// The participant's file with the toe-off rates and knee start the command line overrides.
Participant loadSimulatedParticipant(const SimulateArguments& a) {
  Participant loaded = loadParticipant(a.participant);
  if (a.hipRateDegS) loaded.initial.hipFlexionRate = *a.hipRateDegS * kDegToRad;
  if (a.kneeStart) loaded.initial.kneeStart = *a.kneeStart == "initial" ? KneeStart::kInitial : KneeStart::kMeasured;
  if (a.kneeRateDegS && startsKneeFromRecord(loaded))
    throw InputError("--knee-rate-deg-s: under the measured thigh drive the knee starts at the record's angle and rate at "
                     "toe-off (" + loaded.thighKinematics.path + "); add --knee-start initial to start it from the participant's "
                     "initial knee_flexion_deg and this rate");
  if (a.kneeRateDegS) loaded.initial.kneeFlexionRate = *a.kneeRateDegS * kDegToRad;
  return loaded;
}

// The state the swing started from (calcToeOffState), the trajectory's first sample, and
// where it came from.
void printToeOff(const SwingResult& r, const Participant& p) {
  const SwingTrajectory& tr = r.trajectory;
  const double knee = tr.kneeFlexion.front() * kRadToDeg, kneeRate = tr.kneeFlexionRate.front() * kRadToDeg;
  const double hip = tr.hipFlexion.front() * kRadToDeg, hipRate = tr.hipFlexionRate.front() * kRadToDeg;
  if (p.drive == SwingDrive::kThighKinematics)
    std::printf("  toe-off             knee %.1f deg, %.1f deg/s (%s); thigh %.1f deg, %.1f deg/s (the record's)\n", knee, kneeRate,
                startsKneeFromRecord(p)                 ? "the record's, smoothing-spline value and slope"
                : p.thighKinematics.kneeFlexion.empty() ? "initial: the record has no knee"
                                                        : "initial: knee_start: initial",
                hip, hipRate);
  else
    std::printf("  toe-off             knee %.1f deg, %.1f deg/s; hip %.1f deg, %.1f deg/s (initial)\n", knee, kneeRate, hip, hipRate);
}

// The swing time (or why the trial ended first), the peak knee flexion and the bounce.
void printSwingOutcome(const SwingResult& r, const Participant& p) {
  if (r.trialEnd)
    printTrialEnd(*r.trialEnd, p);
  else
    std::printf("  swing time          %.4f s\n", r.swingTime);
  if (const std::optional<double> entry = calcFirstZoneEntry(r))
    std::printf("  knee first in zone  %.4f s (continuous in the settings; the swing end waits until the knee stays in "
                "the zone)\n", *entry);
  if (r.peakKneeFlexion)
    std::printf("  peak knee flexion   %.1f deg at %.4f s\n", r.peakKneeFlexion->flexion * kRadToDeg,
                r.peakKneeFlexion->time);
  else
    std::printf("  peak knee flexion   none (no knee peak above the zone of stability)\n");
  if (r.bounce && r.bounceHeight)
    std::printf("  bounce              yes: the knee left the zone of stability %d time%s, up to %.1f deg\n", r.bounces,
                r.bounces == 1 ? "" : "s", *r.bounceHeight * kRadToDeg);
  else if (r.bounce)  // left the zone; the run ended before the rebound peaked, or the peak fell in one step
    std::printf("  bounce              yes: the knee left the zone of stability %d time%s (its peak was not "
                "recorded)\n", r.bounces, r.bounces == 1 ? "" : "s");
  else
    std::printf("  bounce              no\n");
}

// Each impact on the knee's extension stop, with the energy bookkeeping where it was tracked.
void printStopImpacts(const std::vector<StopImpact>& impacts) {
  for (std::size_t i = 0; i < impacts.size(); ++i) {
    const StopImpact& im = impacts[i];
    std::printf("  stop impact %-2zu     at %.4f s: %.2f rad/s in, %.2f rad/s out (restitution %.2f), %.2f deg past the stop, "
                "rebound to %.1f deg\n",
                i + 1, im.time, im.impactRate, im.reboundRate, im.restitution, im.maxPenetration * kRadToDeg,
                im.reboundHeight * kRadToDeg);
    if (im.work.empty()) continue;
    std::printf("                      kinetic energy at contact %.3f J; work to the top of the rebound:", im.kineticEnergy);
    for (const auto& w : im.work) std::printf(" %s %+.3f J;", w.cause.c_str(), w.work);
    std::printf("\n");
  }
}

// The smallest toe clearance, with the strike alarm where it holds (walking).
void printToeClearance(const SwingResult& r, const Participant& p) {
  const std::string clearance = fmtOrNone("%.3f m", r.minToeClearance);
  if (!r.minToeClearance)
    std::printf("  min toe clearance   none (no knee peak to measure it from)\n");
  else if (p.toeClearance.alarmHolds())
    std::printf("  min toe clearance   %s%s\n", clearance.c_str(), *r.minToeClearance < 0 ? "  (TOE STRIKES THE GROUND)" : "");
  else
    std::printf("  min toe clearance   %s relative to standing hip height (running: no strike alarm without "
                "toe_clearance.hip_rise_m)\n",
                clearance.c_str());
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
  std::printf("  trajectory          %s/%s.csv and .sto; hip and knee moments %s-moments.svg\n", out.c_str(), tag.c_str(),
              tag.c_str());
}

int runSimulate(const SimulateArguments& a) {
  SwingOptions options = makeSwingOptions(a);
  Participant loaded = loadSimulatedParticipant(a);
  const KneeModel model = loadKneeModel(a.knee.value_or(loaded.kneeModelPath));
  const SwingSetup setup = makeSwingSetup(std::move(loaded), model, a.lowering, a.added.value_or(AddedMass{}));
  const Participant& p = setup.participant;
  const std::string tag = makeTrajectoryFileStem(p.name, setup.lowering);
  checkOutputsAreNotInputs(
      {{"PARTICIPANT.yaml", a.participant}, {a.knee ? "--knee" : "PARTICIPANT.yaml: knee_model", model.path}},
      listRunOutputs(a.out.value_or(makeTrajectoryFolder(p.name)), {tag + ".csv", tag + ".sto", tag + "-moments.svg"}, a.json));
  options.trackImpactEnergy = true;  // one swing: the bookkeeping is cheap here
  const SwingResult r = simulateSwing(setup, options);

  std::printf("%s, knee lowered %.3f m, knee model %s\n", p.name.c_str(), setup.lowering, model.name.c_str());
  std::printf("  drive               %s\n", describeDrive(p).c_str());
  printToeOff(r, p);
  printSwingOutcome(r, p);
  printStopImpacts(r.impacts);
  printToeClearance(r, p);
  std::printf("  integrator          %s, accuracy %g (%d realizations)\n", integratorName(options.integrator),
              options.accuracy, r.realizations);
  std::printf("  events:");
  for (const auto& e : r.events) std::printf(" %s@%.4f", e.name.c_str(), e.time);
  std::printf("\n");
  writeSimulateFiles(a, setup, r);
  return 0;
}

}  // namespace

Command addSimulateCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("simulate", "simulate one swing: swing time, peak knee flexion, events, trajectory CSV/.sto");
  auto a = std::make_shared<SimulateArguments>();
  std::string integrators;
  for (const auto& k : integratorKeys()) integrators += (integrators.empty() ? "" : ", ") + k;
  sub->add_option("PARTICIPANT.yaml", a->participant, "participant file")->required()->type_name("");
  sub->add_option("--side", a->side, "the leg the trajectory .sto names: hip_flexion_<side>, knee_angle_<side>, as export-osim --side "
                  "and a lab's IK file (default r)")
      ->type_name("r|l")
      ->check(oneOf({"r", "l"}));
  sub->add_option("--lowering", a->lowering, "knee-axis lowering below the standard location, m (default 0)")
      ->type_name("M")
      ->check(finiteNumber(checkLowering));
  sub->add_option_function<std::string>("--knee", [a](const std::string& v) { a->knee = v; },
                                        "knee model YAML (default: the participant's knee_model)")
      ->type_name("MODEL.yaml");
  sub->add_option_function<std::string>("--add-mass", [a](const std::string& v) { a->added = readAddedMass(v); },
                                        "added shank mass as KG@METRES below the knee, e.g. 0.5@0.2 (default none)")
      ->type_name("KG@M")
      ->check(addedMassSpec());
  sub->add_option_function<double>("--hip-rate-deg-s", [a](double v) { a->hipRateDegS = v; },
                                   "hip flexion rate at toe-off, deg/s (default: the participant's, 0)")
      ->type_name("DEG/S")
      ->check(finiteNumber([](double v) { return checkPlausible(v, kJointRateRange, "a hip rate"); }));
  addTextOption(sub, "--knee-start", a->kneeStart,
                "under the measured thigh drive, where the knee starts: measured (the record's angle and rate at toe-off) or initial "
                "(the participant's initial values); default: the participant's initial.knee_start, measured if absent",
                "measured|initial")
      ->check(oneOf({"measured", "initial"}));
  sub->add_option_function<double>("--knee-rate-deg-s", [a](double v) { a->kneeRateDegS = v; },
                                   "knee flexion rate at toe-off, deg/s (default: the participant's, 0)")
      ->type_name("DEG/S")
      ->check(finiteNumber([](double v) { return checkPlausible(v, kJointRateRange, "a knee rate"); }));
  sub->add_option_function<std::string>("--integrator", [a](const std::string& v) { a->integrator = v; },
                                        "integration method, one of " + integrators + " (default " +
                                            integratorKeys().front() + "), at its converged accuracy")
      ->type_name("METHOD")
      ->check(oneOf(integratorKeys()));
  sub->add_option_function<double>("--accuracy", [a](double v) { a->accuracy = v; },
                                   "integrator relative accuracy, [1e-14, 0.01] (default: the integrator's converged one)")
      ->type_name("A")
      ->check(finiteNumber(checkAccuracy));
  addJsonOption(sub, a->json);
  addTextOption(sub, "--out", a->out, "output folder for the trajectory (default out/simulate-<participant>/)", "DIR");
  return {sub, [a] { return runSimulate(*a); }};
}

}  // namespace swingsim::cli
