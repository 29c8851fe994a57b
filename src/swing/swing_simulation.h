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
  /// Fast path (Dormand-Prince) only: once the knee has entered the zone, the settle dwell
  /// that confirms the end (SwingEndRule::settleDwell; the knee meets its stop there, about
  /// two thirds of a swing's realizations at full accuracy) is integrated at accuracy x this
  /// factor, no looser than 1e-3, with Bogacki-Shampine 3(2) (numerics/bogacki_shampine.h:
  /// half the realizations per step where the stop, not the order, sets the step). The swing time, peak and clearance are found before it. If
  /// the knee rises to within 0.5 deg of the zone's edge during the loose dwell (a bounce
  /// may decide the end), the swing goes back to the entry and integrates the dwell at full
  /// accuracy (SwingResult::looseDwellRetries). Off with trackImpactEnergy (the impact
  /// bookkeeping wants full accuracy). 1 = no loose dwell.
  double dwellAccuracyFactor = 100;
  /// false: a swing that reaches its time limit (or the end of a measured thigh drive)
  /// before the end rule is met returns what it has, with swingTime NaN, instead of throwing
  /// RunError (a model run along a measured trial cut at heel contact).
  bool requireSwingEnd = true;
  /// Fast path (Dormand-Prince) only: end the settle dwell as soon as the knee cannot leave
  /// the zone before the dwell would end, instead of integrating the whole dwell. Decided at
  /// a step end where the knee rises or rests (rate >= 0; on its hyperextension stop coming
  /// out of it, or above it) and, treated as one degree of freedom with the thigh free
  /// (swing/knee_climb.h), cannot climb to within the loose dwell's 0.5 deg of the zone's
  /// edge: its energy (its rate and what the stop can give back) is used up first by half
  /// of what holds it back: the acceleration that presses it down under the hip moment still
  /// to come (HipMomentProfile::calcRangeFrom, the end of it that holds the knee least,
  /// through the present M^-1) and the knee law's other parts on the way up (the friction
  /// near extension, the damping table; see simulateSwing's isSettled). Swing
  /// time, events, bounces and bounce height are those of the full dwell (tests/swing/
  /// settle_dwell_test.cpp, every lowering of the four Burkett participants, bouncy knees
  /// included); the trajectory and the stop contacts end where the end was decided (a
  /// contact still open there is closed as at the end of a dwell). Off with
  /// trackImpactEnergy (the impact bookkeeping wants the whole dwell) and with the
  /// measured thigh drive (the prescribed thigh's future is not bounded like a hip moment's).
  bool earlySettleEnd = true;
  /// Fast path (Dormand-Prince) only: stop a swing as soon as its thigh provably cannot reach
  /// the target flexion any more, instead of integrating to the time limit (a Monte Carlo
  /// sample with a weak hip moment spends most of its time there). Decided at a step end past
  /// the hip moment's last breakpoint (the moment constant from there on, M), with the thigh
  /// below its target and inside its range, when the leg's energy E = kinetic + gravity
  /// potential + what the knee law stores (KneeLaw::calcStoredEnergy) - M hip falls more
  /// than 0.01 J (kUnreachableEnergyMargin) below the least energy the thigh at its target needs
  /// (LegModel::calcLeastPotentialEnergy - M target). Only with a passive knee law
  /// (KneeLaw::isPassive): then E never rises, so the thigh never gets there; the hip's
  /// range stop is passive in the same way (JointStop). The outcome is the time limit's:
  /// RunError naming the cause, or with requireSwingEnd false a NaN swing time. Off with the
  /// measured thigh drive.
  bool earlyThighFailure = true;
  /// Energy bookkeeping of each stop impact (StopImpact::work): integrates the work of every
  /// knee law part and of the hip as extra states (a little slower; off in sweeps).
  bool trackImpactEnergy = false;
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
  /// toe_off, thigh_at_target, knee_peak_flexion, knee_enters_zone, knee_leaves_zone,
  /// knee_bounce_peak (a flexion peak above the zone after a bounce), swing_end
  std::string name;
  double time;       ///< s since toe-off
};

/// Work done on the leg by one cause over an impact, J (negative: taken out of the leg).
struct ImpactWork {
  std::string cause;  ///< a knee law part's name ("hyperextension stop", "knee friction", ...) or "hip drive"
  double work = 0;
};

/// One contact of the knee with its hyperextension stop (flexion below the stop's engage
/// angle), found on the integrator's step ends and their Hermite interpolants.
struct StopImpact {
  double time = 0;            ///< s since toe-off, contact begins
  double impactRate = 0;      ///< rad/s, knee extension speed at contact (> 0)
  double reboundRate = 0;     ///< rad/s, knee flexion speed at separation (0: no separation)
  double restitution = 0;     ///< reboundRate / impactRate
  double maxPenetration = 0;  ///< rad past the engage angle (hyperextension)
  /// rad, knee flexion at the top of the rebound after separation (the engage angle if none
  /// was reached before the simulation ended)
  double reboundHeight = 0;
  /// SwingOptions::trackImpactEnergy only: the leg's kinetic energy at contact, J, and the
  /// work of each knee law part and of the hip from contact to the top of the rebound (to
  /// the end of the simulation if there was none): where the impact's energy went.
  double kineticEnergy = 0;
  std::vector<ImpactWork> work;
};

struct SwingResult {
  /// s: thigh at target AND knee back in the zone after its peak, staying there for the
  /// settle dwell (SwingEndRule::settleDwell); NaN if the swing had not ended
  /// (SwingOptions::requireSwingEnd false)
  double swingTime = 0;
  double peakKneeFlexion = 0;      ///< rad
  double peakKneeFlexionTime = 0;  ///< s
  bool bounce = false;             ///< knee left the zone after entering it (bounces > 0)
  int bounces = 0;                 ///< times the knee left the zone after entering it
  double bounceHeight = 0;         ///< rad, highest knee flexion after leaving the zone (0: no bounce)
  std::vector<StopImpact> impacts; ///< contacts with the hyperextension stop, in time order (at most 20)
  double minToeClearance = 0;      ///< m, lowest ankle or toe height above ground from peak knee flexion to the swing end
  std::vector<SwingEvent> events;
  SwingTrajectory trajectory;
  int steps = 0;                   ///< integrator steps taken
  int realizations = 0;            ///< system realizations the integrator asked for
  int realizationsToEnd = 0;       ///< of which up to the step where the swing ended (the rest: the settle dwell)
  int looseDwellRetries = 0;       ///< loose settle dwells redone at full accuracy (SwingOptions::dwellAccuracyFactor)
  /// s since toe-off when the end was decided: the swing end plus the settle dwell, or
  /// earlier where the knee could no longer leave the zone (SwingOptions::earlySettleEnd)
  double endDecidedTime = 0;
};

/// The participant-level inputs one swing needs, after loading.
struct SwingSetup {
  Participant participant;
  const KneeLaw* knee = nullptr;  ///< full knee law (model + friction + stop)
  double lowering = 0;            ///< m
  AddedMass added;
};

/// What drives the participant's swing, in words for reports: the hip moment profile
/// (HipMomentProfile::describe), or the measured thigh angle (file, samples, duration, and
/// what the smoothing spline removed).
std::string describeDrive(const Participant& p);
/// The drive's YAML key: "hip_moment" or "thigh_kinematics".
const char* driveKey(SwingDrive drive);

/// Hip height used for toe clearance: 0.530 x height (Winter 2009, Table 4.1 segment
/// lengths: greater trochanter at 0.530 H), plus the participant's stated hip rise
/// (ToeClearanceRule::hipRise) if any.
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
