#pragma once
// One swing: build the leg for a participant and lowering, integrate from toe-off with
// Simbody, find the swing end by event handlers, and return times, events and trajectory.
#include <optional>
#include <string>
#include <vector>

#include "knee/knee_law.h"
#include "model/leg_parameters.h"
#include "model/swing_trajectory.h"

namespace swingsim {

/// The error-controlled explicit integrators the convergence study compares: our
/// Dormand-Prince over Simbody's realizations, and Simbody's own (CPodes is left out: on
/// this chain it did not finish a swing in 20 s). All of them integrate the same Simbody
/// system; they differ in how they step it.
enum class SwingIntegrator {
  /// Dormand-Prince RK5(4) (dormand_prince.h) stepping the Simbody leg's (q, u, z) through
  /// SimbodyOde: 6 realizations per step, no State copies (the default; fast path only).
  kDormandPrince,
  kRungeKuttaMerson,    ///< RK 4(3), 5 stages
  kRungeKuttaFeldberg,  ///< RK 4(5), 6 stages
  kRungeKutta3,         ///< RK 3(2), 3 stages
  kVerlet,              ///< velocity Verlet with error control
};

/// Display name ("Dormand-Prince 5(4) over Simbody realizations", "Simbody Runge-Kutta-Merson").
const char* integratorName(SwingIntegrator integrator);
/// YAML key of each integrator, in enum order: dormand-prince, runge-kutta-merson,
/// runge-kutta-feldberg, runge-kutta-3, verlet.
const std::vector<std::string>& integratorKeys();
/// The integrator of a YAML/CLI key (integratorKeys), or nullopt.
std::optional<SwingIntegrator> findIntegrator(const std::string& key);
/// "" if `accuracy` is usable (in [1e-14, 0.01]: tighter is below double round-off), else
/// what was expected.
std::string checkAccuracy(double accuracy);

/// Integrator settings. The defaults are the converged settings of the README's
/// convergence study (swing time converged to 0.1 ms).
struct SwingOptions {
  /// Relative accuracy: Simbody's integrator accuracy, or Dormand-Prince's relative and
  /// absolute tolerance (the same number). Converged values differ by integrator (README).
  double accuracy = 1e-5;
  SwingIntegrator integrator = SwingIntegrator::kDormandPrince;
  double sampleInterval = 0.002;    ///< s between trajectory samples (Hermite-interpolated between steps: free)
  bool recordTrajectory = true;
  /// How the swing events (thigh at target, knee peak, knee enters/leaves the zone) are
  /// located. false (the fast path): sign changes of the event witnesses between two
  /// integrator steps, each crossing found on the cubic Hermite interpolant of the bracketing
  /// step ends (angle and rate, or rate and acceleration), which costs no realization.
  /// true (the plain path): Simbody TriggeredEventHandlers, each crossing localized by the
  /// integrator to eventWindow (extra realizations and State copies) and the step restarted
  /// there; needs one of Simbody's integrators (simulateSwing throws std::invalid_argument
  /// with kDormandPrince). Both give the same swing times to the converged tolerance (tests/swing/fast_path_test.cpp).
  bool simbodyEvents = false;
  double eventWindow = 1e-5;        ///< s, localization window of the plain path
  /// Fast path: after the swing end the integrator restarts at accuracy x this factor, but
  /// no looser than 1e-3, for the bounce window (about half the realizations of a swing: the
  /// knee meets its hyperextension stop there). The swing time, peak and clearance are
  /// found before the restart; the bounce flag (the knee back above the zone, a margin of
  /// degrees) and the trajectory past the end are integrated less tightly (1e-3 by
  /// default). Events in the window agree with the plain path within 1 ms
  /// (tests/swing/fast_path_test.cpp). 1 = no restart.
  double bounceWindowAccuracyFactor = 100;
  /// Budgets of one swing, far above what any study needs (a swing of the bundled
  /// participants takes a few hundred realizations, 15000 at accuracy 1e-12, and
  /// milliseconds; the budget is 1 to 2 s of computing): a knee law far too
  /// stiff for an explicit integrator at this accuracy (a damping table in N m s/rad
  /// written 1e6 too large, an accuracy of 1e-18) would otherwise run for hours. Past
  /// either, simulateSwing throws RunError naming the participant, the lowering and what
  /// to change.
  long maxRealizations = 150000;
  double maxWallSeconds = 60;  ///< s of wall-clock time for one swing
};

struct SwingEvent {
  std::string name;  ///< thigh_at_target, knee_peak_flexion, knee_enters_zone, knee_leaves_zone, swing_end
  double time;       ///< s since toe-off
};

/// Sampled trajectory, SI units (rad, rad/s, N m, m).

struct SwingResult {
  double swingTime = 0;            ///< s: thigh at target AND knee back in the zone after its peak
  double peakKneeFlexion = 0;      ///< rad
  double peakKneeFlexionTime = 0;  ///< s
  bool bounce = false;             ///< knee left the zone again after entering it
  double minToeClearance = 0;      ///< m, lowest ankle or toe height above ground from peak knee flexion to the swing end
  std::vector<SwingEvent> events;
  SwingTrajectory trajectory;
  int steps = 0;                   ///< integrator steps taken
  int realizations = 0;            ///< system realizations the integrator asked for
  int realizationsToEnd = 0;       ///< of which up to the step where the swing ended (the rest: bounce window)
};

/// The participant-level inputs one swing needs, after loading.
struct SwingSetup {
  Participant participant;
  const KneeLaw* knee = nullptr;  ///< full knee law (model + friction + stop)
  double lowering = 0;            ///< m
  AddedMass added;
};

/// Standing hip height used for toe clearance: 0.530 x height (Winter 2009, Table 4.1
/// segment lengths: greater trochanter at 0.530 H).
double calcHipHeight(const Participant& p);

/// The loosest accuracy at which this integrator's swing time is converged to 0.1 ms in the
/// README's convergence study (Dormand-Prince 1e-5 also over the whole sweep, by the guard
/// test; Runge-Kutta-Merson 1e-4, Runge-Kutta-Feldberg 1e-5, Runge-Kutta 3 1e-3, Verlet 1e-5).
double calcConvergedAccuracy(SwingIntegrator integrator);

/// Options of the plain path: Simbody's Runge-Kutta-Merson with its event handlers at
/// `accuracy`, localizing crossings to `eventWindow` s. Shares no integration code with the
/// reference swing (reference_swing.h), so checks against the reference stay independent.
SwingOptions makePlainPathOptions(double accuracy, double eventWindow);

/// The fast path on Simbody's Runge-Kutta-Merson at `accuracy` (converged at 1e-4, README
/// "Convergence study"): for results that must not share integration code with the
/// reference swing (the synthetic truth of the swing diagnosis, the Simbody check of a
/// diagnosed model).
SwingOptions makeSimbodyIntegratorOptions(double accuracy = 1e-4);

/// Runs one swing. Throws RunError (with the time, the state and the likely cause) if the
/// integrator fails, the swing does not end within the time limit, or it exceeds
/// options.maxRealizations or options.maxWallSeconds.
SwingResult simulateSwing(const SwingSetup& setup, const SwingOptions& options = {});

}  // namespace swingsim
