#include "sweep/terminal_impact.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "core/input_error.h"
#include "core/text_format.h"
#include "core/units.h"
#include "swing/knee_setup.h"

namespace swingsim {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// "0.00-0.13 m" style ranges of consecutive grid lowerings, or "none".
std::string describeLowerings(const std::vector<double>& lowerings, double step) {
  if (lowerings.empty()) return "at no lowering";
  std::string out;
  std::size_t i = 0;
  while (i < lowerings.size()) {
    std::size_t j = i;
    while (j + 1 < lowerings.size() && lowerings[j + 1] - lowerings[j] < 1.5 * step) ++j;
    out +=
        (out.empty() ? "" : ", ") + fmt("%.3f", lowerings[i]) + (j > i ? "-" + fmt("%.3f", lowerings[j]) : "") + " m";
    i = j + 1;
  }
  return "at " + out;
}

// Grid lowerings where the knee bounced, the fastest grid point, and whether it is interior.
void summarize(const ParticipantSweep& ps, std::vector<double>& bounces, double& fastest, double& time,
               bool& interior) {
  bounces.clear();
  fastest = time = kNaN;
  interior = false;
  double largest = -1;
  for (const auto& pt : ps.points) {
    if (!pt.onGrid || !pt.ok) continue;
    if (pt.result.bounce) bounces.push_back(pt.lowering);
    largest = std::max(largest, pt.lowering);
  }
  if (ps.best >= 0) {
    const SweepPoint& b = ps.points[static_cast<std::size_t>(ps.best)];
    fastest = b.lowering;
    time = b.result.swingTime;
    interior = b.lowering < largest - 1e-9;
  }
}

double workOf(const StopImpact& impact, const std::string& cause) {
  for (const auto& w : impact.work)
    if (w.cause == cause) return w.work;
  return 0;
}

/// The friction-free sweep: the same grid without Tc (and without the added-mass grid).
SweepResults runFrictionFreeSweep(const SweepStudy& study, int jobs) {
  SweepStudy frictionFree = study;
  for (Participant& p : frictionFree.participants) p.kneeFriction = 0;
  frictionFree.addedMasses = {0.0};
  frictionFree.includePublishedLowerings = false;
  return runSweep(frictionFree, jobs);
}

/// The impact-energy bookkeeping at the standard location and the largest lowering.
std::vector<TrackedImpactSwing> trackImpacts(const SweepStudy& study, const Participant& p, const KneeModel& model,
                                             double loweringCap) {
  std::vector<TrackedImpactSwing> out;
  const auto knee = std::make_shared<const KneeLawSum>(makeKneeLaw(p, model));
  for (double lowering : {0.0, loweringCap}) {
    TrackedImpactSwing tracked;
    tracked.lowering = lowering;
    const SwingSetup setup = makeSwingSetup(p, knee, lowering);
    SwingOptions options = study.swing;
    options.recordTrajectory = false;
    options.trackImpactEnergy = true;
    try {
      tracked.result = simulateSwing(setup, options);
      tracked.ok = true;
    } catch (const std::exception& e) {
      tracked.failure = e.what();
    }
    out.push_back(std::move(tracked));
  }
  return out;
}

/// Whether and where the knee bounced, against Burkett's finding.
std::string describeBounce(const TerminalImpactCheck& check, double step) {
  return "Bounce (Burkett: at large lowerings for every participant): the knee bounces out of the zone " +
         describeLowerings(check.bounceLowerings, step) + (check.bounceLowerings.empty() ? " (not reproduced)." : ".");
}

/// Whether the fastest lowering (`fastest`, m) is interior, against Burkett's finding.
std::string describeInteriorOptimum(const TerminalImpactCheck& check, double fastest) {
  return std::string("Interior optimum (Burkett: swing time rises again past the fastest lowering): ") +
         (check.interiorOptimum
              ? "yes, fastest at " + fmt("%.3f", fastest) + " m."
              : std::string("no, the swing is fastest at the largest lowering (not reproduced") +
                    (check.bounceLowerings.empty() ? "; in Burkett's Fig. 3 the slower swings past the optimum come "
                                                     "with the bounce, which this model does not show here)."
                                                   : ")."));
}

/// Where a tracked swing's first stop impact's energy goes: the stop, friction, the knee's law.
std::string describeStopImpact(const TrackedImpactSwing& t) {
  const StopImpact& im = t.result.impacts.front();
  const double stop = workOf(im, "hyperextension stop"), friction = workOf(im, "knee friction");
  double damping = 0;
  for (const auto& w : im.work)
    if (w.cause != "hyperextension stop" && w.cause != "knee friction" && w.cause != "hip drive") damping += w.work;
  return "At " + fmt("%.3f", t.lowering) + " m the knee meets its stop at " + fmt("%.1f", im.impactRate) +
         " rad/s with " + fmt("%.2f", im.kineticEnergy) +
         " J of kinetic energy in the leg; to the top of the rebound the stop takes " + fmt("%.2f", -stop) +
         " J, the knee friction " + fmt("%.2f", -friction) + " J, the knee's resisting law " + fmt("%.2f", -damping) +
         " J; the knee leaves the stop at " + fmt("%.2f", im.reboundRate) + " rad/s and rises to " +
         fmt("%.1f", im.reboundHeight * kRadToDeg) + " deg.";
}

/// What stops the bounce (neither friction nor anything, or the knee friction), if that can
/// be told from the two sweeps; nullopt when the knee bounces with friction.
std::optional<std::string> describeWhatStopsBounce(const TerminalImpactCheck& check, double restitution, double step,
                                                   double loweringCap) {
  if (check.bounceLowerings.empty() && check.bounceLoweringsWithoutFriction.empty())
    return "Friction is not what stops the bounce here: without it the knee still does not bounce at any lowering; "
           "with the stop's restitution of " +
           fmt("%.2f", restitution) + " the rebound does not carry the knee back out of the zone.";
  if (!(check.bounceLowerings.empty() && check.frictionMoment > 0)) return std::nullopt;
  std::string s = "What stops the bounce: the knee friction near extension (Tc = " + fmt("%.1f", check.frictionMoment) +
                  " N m below 4 deg, Burkett Table 2). Without it the knee bounces " +
                  describeLowerings(check.bounceLoweringsWithoutFriction, step);
  if (!check.bounceLoweringsWithoutFriction.empty()) {
    const bool smallOnly = check.bounceLoweringsWithoutFriction.back() < loweringCap - 1e-9;
    s += smallOnly ? ": at small lowerings, not large ones, because the impact speed falls as the shank shortens" : "";
    s += std::string(", and the fastest lowering ") +
         (std::isnan(check.fastestWithoutFriction)
              ? "is undefined (no swing ended)"
              : "is " + fmt("%.3f", check.fastestWithoutFriction) + " m (" +
                    (check.interiorOptimumWithoutFriction ? "interior" : "the largest") + ")");
  }
  return s + ".";
}

/// One participant's check from its sweep with and without knee friction.
TerminalImpactCheck checkParticipant(const SweepStudy& study, const Participant& p, const ParticipantSweep& ps,
                                     const ParticipantSweep& withoutFriction) {
  TerminalImpactCheck check;
  check.participant = p.name;
  check.frictionMoment = p.kneeFriction;
  double fastest = kNaN, time = kNaN;
  summarize(ps, check.bounceLowerings, fastest, time, check.interiorOptimum);
  summarize(withoutFriction, check.bounceLoweringsWithoutFriction, check.fastestWithoutFriction,
            check.fastestTimeWithoutFriction, check.interiorOptimumWithoutFriction);
  const KneeModel& model = findStudyKneeModel(study, p);
  check.tracked = trackImpacts(study, p, model, ps.loweringCap);

  // The findings, in words.
  const double step = study.loweringStep;
  check.findings.push_back(describeBounce(check, step));
  check.findings.push_back(describeInteriorOptimum(check, fastest));
  for (const auto& t : check.tracked)
    if (t.ok && !t.result.impacts.empty()) check.findings.push_back(describeStopImpact(t));
  if (auto cause = describeWhatStopsBounce(check, model.spec.stop.restitution, step, ps.loweringCap))
    check.findings.push_back(*cause);
  return check;
}

}  // namespace

void checkTerminalImpact(const SweepStudy& study, SweepResults& results, int jobs) {
  const SweepResults withoutFriction = runFrictionFreeSweep(study, jobs);
  results.terminalImpact.clear();
  for (std::size_t i = 0; i < study.participants.size() && i < results.participants.size(); ++i)
    results.terminalImpact.push_back(
        checkParticipant(study, study.participants[i], results.participants[i], withoutFriction.participants[i]));
}

}  // namespace swingsim
