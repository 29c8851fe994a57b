#include "study/simulate_run.h"

#include <algorithm>
#include <utility>

#include "core/input_error.h"
#include "core/text_format.h"
#include "core/units.h"
#include "io/swing_record_csv.h"
#include "leg/toe_off_state.h"

namespace swingsim {

SwingOptions makeSimulateOptions(const std::optional<std::string>& integrator, std::optional<double> accuracy) {
  SwingOptions options;
  options.trackImpactEnergy = true;
  if (integrator) {
    options.integrator = *findIntegrator(*integrator);
    options.accuracy = calcConvergedAccuracy(options.integrator);
  }
  if (accuracy) options.accuracy = *accuracy;
  return options;
}

void applyToeOffOverrides(Participant& p, const ToeOffOverrides& overrides, const std::string& kneeRateName) {
  if (overrides.hipFlexionRate) p.initial.hipFlexionRate = *overrides.hipFlexionRate;
  if (overrides.kneeStart) p.initial.kneeStart = *overrides.kneeStart;
  if (overrides.kneeFlexionRate && startsKneeFromRecord(p))
    throw InputError(kneeRateName +
                     ": under the measured thigh drive the knee starts at the record's angle and rate at "
                     "toe-off (" +
                     p.thighKinematics.path +
                     "); add --knee-start initial to start it from the participant's "
                     "initial knee_flexion_deg and this rate");
  if (overrides.kneeFlexionRate) p.initial.kneeFlexionRate = *overrides.kneeFlexionRate;
}

SimulateRun runSimulate(SwingSetup setup, const SwingOptions& options) {
  SimulateRun run{std::move(setup), {}};
  run.result = simulateSwing(run.setup, options);
  return run;
}

SimulateRun runSimulate(Participant participant, const KneeModel& knee, double lowering, const AddedMass& added,
                        const SwingOptions& options) {
  return runSimulate(makeSwingSetup(std::move(participant), knee, lowering, added), options);
}

namespace {

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
std::string formatTrialEnd(const TrialEnd& e, const Participant& p) {
  std::string s = "  swing time          not reached (" + e.unmet + ")\n";
  s += "  trial end           " + e.describe() + "\n";
  s += fmt("  at the trial's end  model knee %.1f deg", e.kneeFlexion * kRadToDeg);
  if (const auto measured = findMeasuredKnee(p.thighKinematics, e.time))
    s += fmt(", measured knee %.1f deg", *measured * kRadToDeg);
  s += fmt("; thigh %.1f deg (peak %.1f deg, target %.1f deg)\n", e.thighFlexion * kRadToDeg, e.thighPeak * kRadToDeg,
           e.thighTarget * kRadToDeg);
  return s;
}

// The state the swing started from (calcToeOffState), the trajectory's first sample, and
// where it came from.
std::string formatToeOff(const SwingResult& r, const Participant& p) {
  const SwingTrajectory& tr = r.trajectory;
  const double knee = tr.kneeFlexion.front() * kRadToDeg, kneeRate = tr.kneeFlexionRate.front() * kRadToDeg;
  const double hip = tr.hipFlexion.front() * kRadToDeg, hipRate = tr.hipFlexionRate.front() * kRadToDeg;
  if (p.drive == SwingDrive::kThighKinematics)
    return fmt("  toe-off             knee %.1f deg, %.1f deg/s (%s); thigh %.1f deg, %.1f deg/s (the record's)\n",
               knee, kneeRate,
               startsKneeFromRecord(p)                 ? "the record's, smoothing-spline value and slope"
               : p.thighKinematics.kneeFlexion.empty() ? "initial: the record has no knee"
                                                       : "initial: knee_start: initial",
               hip, hipRate);
  return fmt("  toe-off             knee %.1f deg, %.1f deg/s; hip %.1f deg, %.1f deg/s (initial)\n", knee, kneeRate,
             hip, hipRate);
}

// The swing time (or why the trial ended first), the peak knee flexion and the bounce.
std::string formatSwingOutcome(const SwingResult& r, const Participant& p) {
  std::string s = r.trialEnd ? formatTrialEnd(*r.trialEnd, p) : fmt("  swing time          %.4f s\n", r.swingTime);
  if (const std::optional<double> entry = calcFirstZoneEntry(r))
    s +=
        fmt("  knee first in zone  %.4f s (continuous in the settings; the swing end waits until the knee stays in "
            "the zone)\n",
            *entry);
  if (r.peakKneeFlexion)
    s += fmt("  peak knee flexion   %.1f deg at %.4f s\n", r.peakKneeFlexion->flexion * kRadToDeg,
             r.peakKneeFlexion->time);
  else
    s += "  peak knee flexion   none (no knee peak above the zone of stability)\n";
  if (r.bounce && r.bounceHeight)
    s += fmt("  bounce              yes: the knee left the zone of stability %d time%s, up to %.1f deg\n", r.bounces,
             r.bounces == 1 ? "" : "s", *r.bounceHeight * kRadToDeg);
  else if (r.bounce)  // left the zone; the run ended before the rebound peaked, or the peak fell in one step
    s +=
        fmt("  bounce              yes: the knee left the zone of stability %d time%s (its peak was not "
            "recorded)\n",
            r.bounces, r.bounces == 1 ? "" : "s");
  else
    s += "  bounce              no\n";
  return s;
}

// Each impact on the knee's extension stop, with the energy bookkeeping where it was tracked.
std::string formatStopImpacts(const std::vector<StopImpact>& impacts) {
  std::string s;
  for (std::size_t i = 0; i < impacts.size(); ++i) {
    const StopImpact& im = impacts[i];
    s += fmt(
        "  stop impact %-2zu     at %.4f s: %.2f rad/s in, %.2f rad/s out (restitution %.2f), %.2f deg past the stop, "
        "rebound to %.1f deg\n",
        i + 1, im.time, im.impactRate, im.reboundRate, im.restitution, im.maxPenetration * kRadToDeg,
        im.reboundHeight * kRadToDeg);
    if (im.work.empty()) continue;
    s += fmt("                      kinetic energy at contact %.3f J; work to the top of the rebound:",
             im.kineticEnergy);
    for (const auto& w : im.work) s += fmt(" %s %+.3f J;", w.cause.c_str(), w.work);
    s += "\n";
  }
  return s;
}

// The smallest toe clearance, with the strike alarm where it holds (walking).
std::string formatToeClearance(const SwingResult& r, const Participant& p) {
  const std::string clearance = fmtOrNone("%.3f m", r.minToeClearance);
  if (!r.minToeClearance) return "  min toe clearance   none (no knee peak to measure it from)\n";
  if (p.toeClearance.alarmHolds())
    return fmt("  min toe clearance   %s%s\n", clearance.c_str(),
               *r.minToeClearance < 0 ? "  (TOE STRIKES THE GROUND)" : "");
  return fmt(
      "  min toe clearance   %s relative to standing hip height (running: no strike alarm without "
      "toe_clearance.hip_rise_m)\n",
      clearance.c_str());
}

// A compliant socket's largest give, against MyoSuite's joint ranges (docs/socket.md).
std::string formatSocket(const SwingResult& r, const Participant& p) {
  if (!r.socketPeak || !p.socket) return "";
  const double piston = r.socketPeak->piston, rotation = r.socketPeak->rotation;
  const bool past = piston > p.socket->pistonRange || rotation > p.socket->rotationRange;
  return fmt("  socket              peak piston %.2f mm, peak rotation %.2f deg (range +-%.0f mm, +-%.1f deg)%s\n",
             piston * 1e3, rotation * kRadToDeg, p.socket->pistonRange * 1e3, p.socket->rotationRange * kRadToDeg,
             past ? "  (PAST THE SOCKET'S RANGE: its springs are linear there, a real socket's are not)" : "");
}

}  // namespace

std::string formatSimulateSummary(const SimulateRun& run, const KneeModel& knee, const SwingOptions& options) {
  const Participant& p = run.setup.participant;
  const SwingResult& r = run.result;
  std::string s = p.name + fmt(", knee lowered %.3f m, knee model ", run.setup.lowering) + knee.name + "\n";
  s += "  drive               " + describeDrive(p) + "\n";
  s += formatToeOff(r, p);
  s += formatSwingOutcome(r, p);
  s += formatStopImpacts(r.impacts);
  s += formatToeClearance(r, p);
  s += formatSocket(r, p);
  s += fmt("  integrator          %s, accuracy %g (%d realizations)\n", integratorName(options.integrator),
           options.accuracy, r.realizations);
  s += "  events:";
  for (const auto& e : r.events) s += fmt(" %s@%.4f", e.name.c_str(), e.time);
  s += "\n";
  return s;
}

}  // namespace swingsim
