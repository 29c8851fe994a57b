#include "swing/swing_simulation.h"

#include <Simbody.h>

#include <cmath>
#include <cstdio>
#include <iterator>

#include "core/input_error.h"
#include "leg/thigh_motion.h"
#include "swing/swing_run.h"

namespace swingsim {

using namespace SimTK;

const char* driveKey(SwingDrive drive) { return drive == SwingDrive::kHipMoment ? "hip_moment" : "thigh_kinematics"; }

std::string describeDrive(const Participant& p) {
  if (p.drive == SwingDrive::kHipMoment) return "hip moment: " + p.hipMoment.describe();
  const ThighKinematics& k = p.thighKinematics;
  std::string text = "measured thigh angle prescribed on the hip (" +
                     (k.path.empty() ? std::string("given in code") : k.path) + ", " + std::to_string(k.time.size()) +
                     " samples over " + formatSeconds(k.time.empty() ? 0.0 : k.time.back()) + " s";
  try {
    const ThighMotion motion(k);
    char buf[96];
    std::snprintf(buf, sizeof buf, "; GCV quintic spline, %.3f deg RMS from the samples",
                  motion.getFitRms() * kRadToDeg);
    text += buf;
  } catch (const InputError& e) {
    text += std::string("; unusable: ") + e.what();
  }
  return text + "); the hip moment is what the prescription needs";
}

double calcHipHeight(const Participant& p) {
  return 0.530 * p.height + (p.toeClearance.hipRiseGiven ? p.toeClearance.hipRise : 0.0);
}

namespace {

// Every integrator once: its YAML/CLI key, its display name, and the loosest accuracy at
// which its swing times converge to 0.1 ms (docs/speed.md, "Convergence study"). In enum order.
struct IntegratorInfo {
  const char* key;
  const char* name;
  double convergedAccuracy;
};
constexpr IntegratorInfo kIntegrators[] = {
    {"dormand-prince", "Dormand-Prince 5(4) over Simbody realizations", 1e-5},
    {"runge-kutta-merson", "Simbody Runge-Kutta-Merson", 1e-4},
    {"runge-kutta-feldberg", "Simbody Runge-Kutta-Feldberg", 1e-5},
    {"runge-kutta-3", "Simbody Runge-Kutta 3", 1e-3},
    {"verlet", "Simbody Verlet", 1e-5},
    {"cpodes", "Simbody CPodes (implicit BDF)", 1e-5},
};

const IntegratorInfo& infoOf(SwingIntegrator integrator) { return kIntegrators[static_cast<int>(integrator)]; }

}  // namespace

const char* integratorName(SwingIntegrator integrator) { return infoOf(integrator).name; }

double calcConvergedAccuracy(SwingIntegrator integrator) { return infoOf(integrator).convergedAccuracy; }

const std::vector<std::string>& integratorKeys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k;
    for (const auto& i : kIntegrators) k.push_back(i.key);
    return k;
  }();
  return keys;
}

std::optional<SwingIntegrator> findIntegrator(const std::string& key) {
  for (std::size_t i = 0; i < std::size(kIntegrators); ++i)
    if (key == kIntegrators[i].key) return static_cast<SwingIntegrator>(i);
  return std::nullopt;
}

std::string checkAccuracy(double accuracy) {
  // Below about 1e-14 a relative accuracy asks for less than double round-off: the step-size
  // control breaks down (1e-300 made a NaN inertia) instead of converging further.
  constexpr double kTightestAccuracy = 1e-14;
  return accuracy >= kTightestAccuracy && accuracy <= 1e-2 ? "" : "expected a relative accuracy in [1e-14, 0.01]";
}

SwingOptions makeSimbodyIntegratorOptions(double accuracy) {
  SwingOptions o;
  o.integrator = SwingIntegrator::kRungeKuttaMerson;
  o.accuracy = accuracy;
  return o;
}

SwingOptions makePlainPathOptions(double accuracy, double eventWindow) {
  SwingOptions o = makeSimbodyIntegratorOptions(accuracy);
  o.simbodyEvents = true;
  o.eventWindow = eventWindow;
  return o;
}

std::string TrialEnd::describe() const {
  char buf[320];
  if (unmet == "thigh_target")
    std::snprintf(buf, sizeof buf,
                  "the thigh never reached its target flexion of %.1f deg (its peak %.1f deg, %.1f deg at the end)",
                  thighTarget * kRadToDeg, thighPeak * kRadToDeg, thighFlexion * kRadToDeg);
  else if (unmet == "knee_peak")
    std::snprintf(buf, sizeof buf,
                  "the knee had not peaked above the zone of stability (%.1f deg); knee %.1f deg at the end",
                  zoneOfStability * kRadToDeg, kneeFlexion * kRadToDeg);
  else if (unmet == "knee_zone")
    std::snprintf(buf, sizeof buf,
                  "the knee was not back in the zone of stability: %.1f deg at the end, %.1f deg above its %.1f deg "
                  "(thigh %.1f deg, target %.1f deg)",
                  kneeFlexion * kRadToDeg, (kneeFlexion - zoneOfStability) * kRadToDeg, zoneOfStability * kRadToDeg,
                  thighFlexion * kRadToDeg, thighTarget * kRadToDeg);
  else
    std::snprintf(buf, sizeof buf,
                  "the knee was back in the zone for %.3f s of the settle dwell of %.3f s (knee %.1f deg at the end)",
                  dwellDone.value_or(0), settleDwell, kneeFlexion * kRadToDeg);
  return "the measured trial ended at " + formatSeconds(time) + " s before the swing did: " + buf;
}

SwingResult simulateSwing(const SwingSetup& setup, const SwingOptions& options) {
  return SwingRun(setup, options).run();
}

std::optional<double> calcFirstZoneEntry(const SwingResult& result) {
  for (const SwingEvent& e : result.events)
    if (e.name == "knee_enters_zone") return e.time;
  return std::nullopt;
}

}  // namespace swingsim
