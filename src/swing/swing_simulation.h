#pragma once
// One swing: build the leg for a participant and lowering, integrate from toe-off with
// Simbody, find the swing end by event handlers, and return times, events and trajectory.
#include <memory>
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
  kCPodes,              ///< CPODES, implicit BDF: for a stiff leg (a compliant socket, docs/socket.md)
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

/// Integrator settings, one line each; what each one does and why is in docs/swing-options.md.
/// The defaults are the converged settings of the convergence study (docs/speed.md,
/// "Convergence study").
struct SwingOptions {
  double accuracy = 1e-5;                                        ///< relative (and absolute) accuracy of the integrator
  SwingIntegrator integrator = SwingIntegrator::kDormandPrince;  ///< which integrator steps the leg
  double sampleInterval = 0.002;  ///< s between trajectory samples (Hermite-interpolated between steps)
  bool recordTrajectory = true;   ///< keep the sampled trajectory in SwingResult
  bool simbodyEvents = false;     ///< locate events with Simbody's event handlers (plain path; not with Dormand-Prince)
  double eventWindow = 1e-5;      ///< s, event localization window of the plain path
  double dwellAccuracyFactor = 100;  ///< accuracy multiplier of the loose settle dwell (1: none; fast path)
  bool requireSwingEnd = true;     ///< false: a swing that does not end returns with swingTime NaN instead of RunError
  bool earlySettleEnd = true;      ///< end the settle dwell once the knee provably stays in the zone (fast path)
  bool earlyThighFailure = true;   ///< stop once the thigh provably cannot reach its target (fast path, passive knee)
  bool trackImpactEnergy = false;  ///< energy bookkeeping of each stop impact (extra states; slower)
  long maxRealizations = 150000;   ///< realizations one swing may take before RunError
  double maxWallSeconds = 60;      ///< s of wall-clock time one swing may take before RunError
};

/// rad: where the knee's physical flexion range ends (180 deg: the shank folded onto the
/// thigh). No knee model has a flexion stop, so nothing in the model holds the knee below it;
/// a simulated knee that passes it is a failed run (RunError), never a result.
constexpr double kKneeFlexionLimit = kPi;

struct SwingEvent {
  /// toe_off, thigh_at_target, knee_peak_flexion, knee_enters_zone, knee_leaves_zone,
  /// knee_bounce_peak (a flexion peak above the zone after a bounce), swing_end
  std::string name;
  double time;  ///< s since toe-off
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

/// A measured trial (SwingDrive::kThighKinematics) that ended before the swing-end rule was
/// met: which condition was not met at the trial's end, and by how much.
struct TrialEnd {
  /// thigh_target (the thigh never reached its target), knee_peak (no knee peak above the
  /// zone), knee_zone (the knee was not back in the zone), settle_dwell (back in the zone,
  /// but for less than the settle dwell)
  std::string unmet;
  double time = 0;             ///< s, the trial's end
  double kneeFlexion = 0;      ///< rad, the model's knee at the trial's end
  double thighFlexion = 0;     ///< rad, the thigh at the trial's end
  double thighPeak = 0;        ///< rad, highest thigh flexion of the trial
  double thighTarget = 0;      ///< rad, SwingEndRule::thighTargetFlexion
  double zoneOfStability = 0;  ///< rad, SwingEndRule::zoneOfStability
  /// s the knee had been in the zone with the thigh at target; set only when unmet is settle_dwell
  std::optional<double> dwellDone;
  double settleDwell = 0;  ///< s, SwingEndRule::settleDwell
  /// One line for people: the unmet condition and the numbers.
  std::string describe() const;
};

/// A flexion peak of the knee: its angle and when.
struct KneePeak {
  double flexion = 0;  ///< rad
  double time = 0;     ///< s since toe-off
};

/// What one swing did. A quantity the swing did not have is absent (nullopt), never a
/// marker value: printers write "none" (text), null (JSON), None (Python).
struct SwingResult {
  /// s: thigh at target AND knee back in the zone after its peak, staying there for the
  /// settle dwell (SwingEndRule::settleDwell); NaN if the swing had not ended
  /// (SwingOptions::requireSwingEnd false)
  double swingTime = 0;
  /// The highest knee flexion peak above the zone of stability; absent if the knee had none
  /// (a measured trial cut before it). Always set when the swing ended.
  std::optional<KneePeak> peakKneeFlexion;
  bool bounce = false;  ///< knee left the zone after entering it (bounces > 0)
  int bounces = 0;      ///< times the knee left the zone after entering it
  /// rad, highest knee flexion peak after leaving the zone; absent if it had none (no bounce,
  /// or a run that stopped before the bouncing knee peaked)
  std::optional<double> bounceHeight;
  std::vector<StopImpact> impacts;  ///< contacts with the hyperextension stop, in time order (at most 20)
  /// m, lowest ankle or toe height above ground from peak knee flexion to the swing end (or
  /// the run's end); absent without a knee peak or without a trajectory sample in that span
  std::optional<double> minToeClearance;
  std::vector<SwingEvent> events;
  /// A compliant socket's largest deflections (magnitudes, each at its own step end) up to the
  /// run's end; absent without a compliant socket (docs/socket.md).
  std::optional<SocketDeflection> socketPeak;
  SwingTrajectory trajectory;
  int steps = 0;              ///< integrator steps taken
  int realizations = 0;       ///< system realizations the integrator asked for
  int realizationsToEnd = 0;  ///< of which up to the step where the swing ended (the rest: the settle dwell)
  int looseDwellRetries = 0;  ///< loose settle dwells redone at full accuracy (SwingOptions::dwellAccuracyFactor)
  /// s since toe-off when the end was decided: the swing end plus the settle dwell, or
  /// earlier where the knee could no longer leave the zone (SwingOptions::earlySettleEnd)
  double endDecidedTime = 0;
  /// Set when a measured trial ended before the swing did (swingTime NaN, the trajectory kept).
  std::optional<TrialEnd> trialEnd;
};

/// s since toe-off of the knee's first entry into the zone of stability after its peak (the
/// first "knee_enters_zone" event); absent if it never entered. The swing time's continuous
/// companion: a rebound past the zone makes the swing time jump (the end waits for the next
/// entry), never this.
std::optional<double> calcFirstZoneEntry(const SwingResult& result);

/// The participant-level inputs one swing needs, after loading. Built by makeSwingSetup
/// (swing/knee_setup.h).
struct SwingSetup {
  Participant participant;
  std::shared_ptr<const KneeLaw> knee;  ///< full knee law (model + friction + stop), shared
  double lowering = 0;                  ///< m
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
/// convergence study (docs/speed.md, "Convergence study"; Dormand-Prince 1e-5 also over the
/// whole sweep, by the guard test; Runge-Kutta-Merson 1e-4, Runge-Kutta-Feldberg 1e-5,
/// Runge-Kutta 3 1e-3, Verlet 1e-5).
double calcConvergedAccuracy(SwingIntegrator integrator);

/// Options of the plain path: Simbody's Runge-Kutta-Merson with its event handlers at
/// `accuracy`, localizing crossings to `eventWindow` s. Shares no integration code with the
/// reference swing (reference_swing.h), so checks against the reference stay independent.
SwingOptions makePlainPathOptions(double accuracy, double eventWindow);

/// The fast path on Simbody's Runge-Kutta-Merson at `accuracy` (converged at 1e-4,
/// docs/speed.md, "Convergence study"): for results that must not share integration code
/// with the reference swing (the synthetic truth of the swing diagnosis, the Simbody check of
/// a diagnosed model).
SwingOptions makeSimbodyIntegratorOptions(double accuracy = 1e-4);

/// Runs one swing (SwingRun, swing/swing_run.h). Throws RunError (with the time, the state
/// and the likely cause) if the integrator fails, the knee passes its physical range
/// (kKneeFlexionLimit), the swing does not end within the time
/// limit, or it exceeds options.maxRealizations or options.maxWallSeconds. A measured trial
/// that ends before the swing does is a result (SwingResult::trialEnd), not an error.
SwingResult simulateSwing(const SwingSetup& setup, const SwingOptions& options = {});

}  // namespace swingsim
