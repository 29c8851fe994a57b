#pragma once
// A microprocessor knee's swing controller: an impedance state machine (the Open Source
// Leg's walking controller, docs/formats.md "Microprocessor knee"). Each state holds a
// stiffness, a damping and an equilibrium angle; a state ends when its transition's rule
// holds, and the next state in the list follows.
//
// The discrete state is carried as continuous states so every integrator (Simbody's, our
// Dormand-Prince, the reference integrator) integrates it unchanged, as the Mauch S2 latch
// is: latch s_i (i = 1..n-1, "state i has been entered") relaxes towards s_{i-1} with time
// constant tau once the rule of state i-1 holds, and holds itself once past 1/2; the weight
// of state i is s_i - s_{i+1} (s_0 = 1, s_n = 0), a partition of unity; the time in state i
// is the integral of its weight.
#include <memory>
#include <string>
#include <vector>

#include "core/units.h"
#include "knee/knee_law.h"

namespace swingsim {

/// What the controller may do with the impedance moment.
enum class ImpedanceMode {
  kPowered,      ///< the impedance moment as is, clipped to the torque limit (the Open Source Leg)
  kDissipative,  ///< only a moment that resists the knee's motion (damping-controlled knees)
};

/// Which side of a threshold a transition waits for.
enum class ThresholdSide { kAny, kAbove, kBelow };

/// The rule that ends a state: every condition given must hold at once.
struct ImpedanceTransition {
  std::string to;  ///< name of the next state (the following one in the list)
  ThresholdSide flexionSide = ThresholdSide::kAny;
  double flexion = 0;  ///< knee flexion threshold, rad
  ThresholdSide rateSide = ThresholdSide::kAny;
  double rate = 0;     ///< knee flexion rate threshold, rad/s
  double minTime = 0;  ///< minimum time in the state before it may end, s, >= 0
};

/// One controller state: M = -k (theta - theta_eq) - b theta_dot.
struct ImpedanceState {
  std::string name;
  double stiffness = 0;    ///< k, N m/rad, >= 0
  double damping = 0;      ///< b, N m s/rad, >= 0
  double equilibrium = 0;  ///< theta_eq, rad (flexion positive)
  bool hasTransition = false;
  ImpedanceTransition transition;  ///< how the state ends (every state but the last)
};

struct ImpedanceStateMachineParams {
  ImpedanceMode mode = ImpedanceMode::kPowered;
  double torqueLimit = 60;  ///< N m, > 0: the actuator's limit on |M|
  /// tau, s: the latch's time constant. Far below the swing's time scales (0.1 s), so a
  /// transition completes (to 1 - e^-5) within 5 tau of its rule holding.
  double latchTime = 1e-3;
  /// w, rad/s: the dissipative projection fades a resisting moment out below this knee speed
  /// (M_d = s min(0, s M), s = tanh(theta_dot / w)), so the moment is continuous at rest.
  double projectionRate = 2.0 * kDegToRad;
  std::vector<ImpedanceState> states;  ///< in the order they follow each other; at least one
};

/// The impedance state machine as a knee law. States: the n-1 latches, then the n-1 times
/// spent in the states that have a transition. Throws std::invalid_argument on bad params
/// (no state, negative stiffness or damping, a torque limit <= 0, a transition to a state
/// that does not follow, a last state with a transition).
class ImpedanceStateMachine final : public KneeLaw {
 public:
  explicit ImpedanceStateMachine(ImpedanceStateMachineParams params);
  const ImpedanceStateMachineParams& params() const { return p_; }

  std::string name() const override { return "impedance state machine"; }
  int numStates() const override;
  void initialStates(double* z) const override;
  double calcMoment(const KneeKinematics& knee, const double* z) const override;
  void calcStateDerivatives(const KneeKinematics& knee, const double* z, double* zdot) const override;
  /// True in the dissipative mode only: there M theta_dot <= 0 at every state.
  bool isPassive() const override { return p_.mode == ImpedanceMode::kDissipative; }
  /// 0: a dissipative moment stores nothing (the springs of the states only shape how much
  /// it resists); in the powered mode the interface's stored energy is not meaningful.
  double calcStoredEnergy(const KneeKinematics&, const double*) const override { return 0; }
  std::unique_ptr<KneeLaw> clone() const override;

  /// The weight of each state at the latch values z (sums to 1).
  std::vector<double> calcStateWeights(const double* z) const;
  /// The impedance moment before the torque limit and the projection, N m.
  double calcImpedanceMoment(const KneeKinematics& knee, const double* z) const;
  /// Index of the state with the largest weight.
  int calcCurrentState(const double* z) const;

 private:
  bool ruleHolds(const ImpedanceTransition& t, const KneeKinematics& knee, double timeInState) const;
  ImpedanceStateMachineParams p_;
};

}  // namespace swingsim
