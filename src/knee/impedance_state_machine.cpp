#include "knee/impedance_state_machine.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

namespace swingsim {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("impedance state machine: " + what);
}

bool sideHolds(ThresholdSide side, double value, double threshold) {
  if (side == ThresholdSide::kAbove) return value > threshold;
  if (side == ThresholdSide::kBelow) return value < threshold;
  return true;
}

void checkState(const ImpedanceState& s, const ImpedanceState* next) {
  require(!s.name.empty(), "every state needs a name");
  require(std::isfinite(s.stiffness) && s.stiffness >= 0, "state " + s.name + ": stiffness must not be negative");
  require(std::isfinite(s.damping) && s.damping >= 0, "state " + s.name + ": damping must not be negative");
  require(std::isfinite(s.equilibrium), "state " + s.name + ": equilibrium angle must be finite");
  if (!next) {
    require(!s.hasTransition, "the last state, " + s.name + ", has no state to go to");
    return;
  }
  require(s.hasTransition, "state " + s.name + " needs a transition to the next state, " + next->name);
  const ImpedanceTransition& t = s.transition;
  require(t.to == next->name, "state " + s.name + ": a transition goes to the next state, " + next->name);
  require(std::isfinite(t.flexion) && std::isfinite(t.rate), "state " + s.name + ": thresholds must be finite");
  require(std::isfinite(t.minTime) && t.minTime >= 0, "state " + s.name + ": minimum time must not be negative");
}

}  // namespace

ImpedanceStateMachine::ImpedanceStateMachine(ImpedanceStateMachineParams params) : p_(std::move(params)) {
  require(!p_.states.empty(), "needs at least one state");
  require(std::isfinite(p_.torqueLimit) && p_.torqueLimit > 0, "torque limit must be positive, N m");
  require(std::isfinite(p_.latchTime) && p_.latchTime > 0, "latch time constant must be positive, s");
  require(std::isfinite(p_.projectionRate) && p_.projectionRate > 0, "projection speed must be positive, rad/s");
  std::set<std::string> names;
  for (const ImpedanceState& s : p_.states) require(names.insert(s.name).second, "state " + s.name + " appears twice");
  for (std::size_t i = 0; i < p_.states.size(); ++i) {
    checkState(p_.states[i], i + 1 < p_.states.size() ? &p_.states[i + 1] : nullptr);
  }
}

int ImpedanceStateMachine::numStates() const { return 2 * (static_cast<int>(p_.states.size()) - 1); }

void ImpedanceStateMachine::initialStates(double* z) const { std::fill(z, z + numStates(), 0.0); }

std::vector<double> ImpedanceStateMachine::calcStateWeights(const double* z) const {
  // Weight of state i: s_i - s_{i+1}, with s_0 = 1, s_n = 0 and s_i = z[i - 1].
  const std::size_t n = p_.states.size();
  std::vector<double> w(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double entered = i == 0 ? 1.0 : z[i - 1];
    const double left = i + 1 == n ? 0.0 : z[i];
    w[i] = entered - left;
  }
  return w;
}

int ImpedanceStateMachine::calcCurrentState(const double* z) const {
  const std::vector<double> w = calcStateWeights(z);
  return static_cast<int>(std::max_element(w.begin(), w.end()) - w.begin());
}

double ImpedanceStateMachine::calcImpedanceMoment(const KneeKinematics& knee, const double* z) const {
  const std::vector<double> w = calcStateWeights(z);
  double moment = 0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const ImpedanceState& s = p_.states[i];
    moment += w[i] * (-s.stiffness * (knee.flexion - s.equilibrium) - s.damping * knee.flexionRate);
  }
  return moment;
}

double ImpedanceStateMachine::calcMoment(const KneeKinematics& knee, const double* z) const {
  const double clipped = std::clamp(calcImpedanceMoment(knee, z), -p_.torqueLimit, p_.torqueLimit);
  if (p_.mode == ImpedanceMode::kPowered) return clipped;
  // Keep only the resisting part: with s = tanh(rate / w), s M_d = s^2 min(0, s M) and
  // M_d rate = s rate min(0, s M) <= 0, as s rate >= 0 (docs/formats.md).
  const double s = std::tanh(knee.flexionRate / p_.projectionRate);
  return s * std::min(0.0, s * clipped);
}

bool ImpedanceStateMachine::ruleHolds(const ImpedanceTransition& t, const KneeKinematics& knee,
                                      double timeInState) const {
  return timeInState >= t.minTime && sideHolds(t.flexionSide, knee.flexion, t.flexion) &&
         sideHolds(t.rateSide, knee.flexionRate, t.rate);
}

void ImpedanceStateMachine::calcStateDerivatives(const KneeKinematics& knee, const double* z, double* zdot) const {
  const std::size_t transitions = p_.states.size() - 1;
  const std::vector<double> w = calcStateWeights(z);
  for (std::size_t i = 0; i < transitions; ++i) {
    // Latch s_{i+1}: the way out of state i, towards s_i once the rule holds in state i;
    // past 1/2 the transition has fired and completes whatever the rule says now.
    const double from = i == 0 ? 1.0 : z[i - 1];
    const double latch = z[i];
    const double timeInState = z[transitions + i];
    const bool fires = w[i] > 0.5 && ruleHolds(p_.states[i].transition, knee, timeInState);
    zdot[i] = (fires || latch >= 0.5) ? (from - latch) / p_.latchTime : 0.0;
    zdot[transitions + i] = w[i];
  }
}

std::unique_ptr<KneeLaw> ImpedanceStateMachine::clone() const { return std::make_unique<ImpedanceStateMachine>(*this); }

}  // namespace swingsim
