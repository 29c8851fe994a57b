#pragma once
// An independent reference for the Simbody swing: the thigh and
// the rigid shank+foot(+added mass) as a 2-DOF planar double pendulum (with a compliant
// socket, four coordinates: swing/reference_socket_chain.h) whose equations of
// motion are derived by hand (Lagrange, see reference_swing.cpp), integrated by our own
// Dormand-Prince RK5(4) (dormand_prince.h). No Simbody multibody code in this unit: it shares
// with LegModel only the inputs (LegGeometry, the knee law, the hip moment profile and the
// hip range stop, or the prescribed thigh's spline, leg/thigh_motion.h), so a mistake in the multibody model shows up
// as a disagreement. It is also the performance baseline for the Simbody swing.
#include <memory>
#include <vector>

#include "knee/joint_stop.h"
#include "knee/knee_law.h"
#include "leg/hip_path.h"
#include "leg/thigh_motion.h"
#include "model/hip_moment_profile.h"
#include "model/leg_parameters.h"

namespace swingsim {

/// Hip and knee angles and rates at requested times (rad, rad/s).
struct ReferenceTrajectory {
  std::vector<double> time, hipFlexion, kneeFlexion, hipFlexionRate, kneeFlexionRate;
  /// N m, + = flexion: the hip moment profile plus the hip range stop, or with a prescribed
  /// thigh the moment the prescription needs (inverse dynamics of the thigh equation).
  std::vector<double> hipMoment;
  std::vector<double> kneeMoment;  ///< N m, + = flexion: the knee law's moment
  /// A compliant socket's deflection at each sample (empty without one); hipFlexion is then
  /// the residual limb's and kneeFlexion the knee's own (socket to shank).
  std::vector<SocketDeflection> socket, socketRate;  ///< m and rad; m/s and rad/s
  std::size_t size() const { return time.size(); }
};

/// The swing end found by the reference, with the same rule as simulateSwing.
struct ReferenceSwingEnd {
  double swingTime = 0;            ///< s: thigh past target AND knee back in the zone after its peak
  double thighAtTargetTime = 0;    ///< s: first rising crossing of the thigh target
  double peakKneeFlexion = 0;      ///< rad: highest knee peak above the zone
  double peakKneeFlexionTime = 0;  ///< s
  double kneeEntersZoneTime = 0;   ///< s: last entry into the zone before the end
  long steps = 0;                  ///< accepted integrator steps
};

/// The knee moment (N m, + = flexion) a leg's motion needs at one instant, from the reference
/// integrator's own equations (their shank row, docs/reference-swing.md) with the hip fixed:
/// inverse dynamics. Hip = thigh from hanging straight down (rad), knee flexion (rad), their
/// rates and accelerations. With the moment, its derivatives by the two accelerations (the
/// terms through which a smoother's noise reaches it).
struct KneeMomentNeeded {
  double moment = 0;
  double perHipAcceleration = 0, perKneeAcceleration = 0;  ///< N m per rad/s^2
};
KneeMomentNeeded calcKneeMomentNeeded(const LegGeometry& g, double hip, double hipRate, double hipAcc, double knee,
                                      double kneeAcc);

class ReferenceSwing {
 public:
  /// Copies everything it needs (the knee law is cloned). The hip range becomes the same
  /// hip stop LegModel applies (JointStopParams defaults, lower = minFlexion,
  /// upper = maxFlexion).
  ReferenceSwing(const LegGeometry& geometry, const KneeLaw& knee, const HipMomentProfile& hipMoment,
                 const HipRange& hipRange);
  /// The measured thigh drive: hip flexion follows `thigh` (its acceleration replaces the
  /// thigh's equation of motion; InitialConditions' hip angle and rate are replaced by the
  /// thigh's at t = 0), the knee swings freely. The spline is the shared input, as the hip
  /// moment profile is for the other constructor.
  ReferenceSwing(const LegGeometry& geometry, const KneeLaw& knee, const ThighMotion& thigh);
  /// The measured thigh drive on a moving hip: as above, with the hip joint centre following
  /// `hip` (its acceleration enters as the support's inertial force; docs/moving-hip.md).
  ReferenceSwing(const LegGeometry& geometry, const KneeLaw& knee, const ThighMotion& thigh, const HipPath& hip);

  /// Integrates from toe-off (t = 0) and returns the state at `sampleTimes` (s, >= 0,
  /// non-decreasing); steps are shortened to land exactly on each sample time. relTol and
  /// absTol are the Dormand-Prince local error tolerances (rad, rad/s and the knee law's
  /// state units). Throws std::invalid_argument on bad sample times, std::runtime_error if
  /// the integration fails, RunError past kMaxSteps.
  ReferenceTrajectory integrate(const InitialConditions& initial, const std::vector<double>& sampleTimes, double relTol,
                                double absTol) const;

  /// Swing end by the rule of simulateSwing (swing_simulation.cpp): the thigh's first rising
  /// crossing of rule.thighTargetFlexion, a knee peak (flexion rate falling through zero)
  /// above rule.zoneOfStability, then the knee re-entering the zone; the swing ends when the
  /// thigh has reached its target and the knee is inside the zone, in whichever order.
  /// Sign transitions follow Simbody's Event::classifyTransition (a value leaving exactly
  /// zero is not an event). Crossings are located on the dense output to kEventTimeTol.
  /// Throws RunError if the swing has not ended by rule.timeLimit or takes more than kMaxSteps.
  ReferenceSwingEnd calcSwingEnd(const InitialConditions& initial, const SwingEndRule& rule, double relTol,
                                 double absTol) const;
  /// calcSwingEnd(initial, rule, tol, tol).swingTime, s.
  double calcSwingTime(const InitialConditions& initial, const SwingEndRule& rule, double tol) const;

  /// Kinetic + gravitational potential energy (J) at hip/knee angles and rates, with the
  /// potential zero at hip height (LegModel's differs by a constant). With a compliant
  /// socket, its deflection and rates too (the springs' energy included; the knee the
  /// socket's to the shank).
  double calcMechanicalEnergy(double hipFlexion, double kneeFlexion, double hipFlexionRate, double kneeFlexionRate,
                              const SocketDeflection& socket = {}, const SocketDeflection& socketRate = {}) const;

  /// Time tolerance of the crossing search on the dense output, s.
  static constexpr double kEventTimeTol = 1e-12;
  /// Accepted steps one integration may take (a swing at 1e-10 takes a few thousand): past
  /// it, integrate and calcSwingEnd throw RunError saying the knee law is too stiff for the
  /// tolerance, instead of running for hours.
  static constexpr long kMaxSteps = 1000000;

 private:
  class Equations;
  std::shared_ptr<const Equations> equations_;
};

}  // namespace swingsim
