// The impedance state machine (microprocessor knee) on its own: one state is a linear
// spring-damper (checked against the closed-form damped oscillation), transitions happen
// where their rule says (to within the latch's time constant), the dissipative mode never
// pushes the knee, the powered mode respects the torque limit, and bad parameters are refused.
#include "knee/impedance_state_machine.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <vector>

#include "core/units.h"
#include "numerics/dormand_prince.h"

namespace swingsim {
namespace {

ImpedanceState state(const char* name, double k, double b, double eqDeg) {
  ImpedanceState s;
  s.name = name;
  s.stiffness = k;
  s.damping = b;
  s.equilibrium = eqDeg * kDegToRad;
  return s;
}

// The Open Source Leg's swing (models/microprocessor-knee-osl.yaml).
ImpedanceStateMachineParams oslSwing() {
  ImpedanceStateMachineParams p;
  p.states = {state("swing_flexion", 39.749, 0.063, 60), state("swing_extension", 15.899, 3.816, 5),
              state("terminal_swing", 99.372, 3.180, 5)};
  ImpedanceTransition& t0 = p.states[0].transition;
  p.states[0].hasTransition = true;
  t0.to = "swing_extension";
  t0.flexionSide = ThresholdSide::kAbove;
  t0.flexion = 50 * kDegToRad;
  t0.rateSide = ThresholdSide::kBelow;
  t0.rate = 3 * kDegToRad;
  ImpedanceTransition& t1 = p.states[1].transition;
  p.states[1].hasTransition = true;
  t1.to = "terminal_swing";
  t1.flexionSide = ThresholdSide::kBelow;
  t1.flexion = 30 * kDegToRad;
  return p;
}

// A 1-DOF knee, I theta'' = M(theta, theta', z), with the law's states: y = (theta, theta', z).
class KneeOnFixedThigh final : public OdeSystem {
 public:
  KneeOnFixedThigh(const KneeLaw& law, double inertia) : law_(law), inertia_(inertia) {}
  int numStates() const override { return 2 + law_.numStates(); }
  void calcDerivatives(double, const double* y, double* dydt) const override {
    const KneeKinematics knee{y[0], y[1]};
    dydt[0] = y[1];
    dydt[1] = law_.calcMoment(knee, y + 2) / inertia_;
    law_.calcStateDerivatives(knee, y + 2, dydt + 2);
  }

 private:
  const KneeLaw& law_;
  double inertia_;
};

// The law's states along a prescribed knee motion theta(t): y = z only.
class PrescribedKnee final : public OdeSystem {
 public:
  PrescribedKnee(const KneeLaw& law, std::function<KneeKinematics(double)> motion)
      : law_(law), motion_(std::move(motion)) {}
  int numStates() const override { return law_.numStates(); }
  void calcDerivatives(double t, const double* y, double* dydt) const override {
    law_.calcStateDerivatives(motion_(t), y, dydt);
  }

 private:
  const KneeLaw& law_;
  std::function<KneeKinematics(double)> motion_;
};

constexpr double kOdeTol = 1e-11;  // Dormand-Prince relative and absolute tolerance

TEST(ImpedanceStateMachine, OneStateIsTheClosedFormDampedOscillation) {
  // Shank about a fixed knee, no gravity: I theta'' = -k (theta - theta_eq) - b theta'.
  constexpr double kInertia = 0.1;  // kg m^2: a shank and foot about the knee (Burkett Table 2 order)
  ImpedanceStateMachineParams p;
  p.states = {state("only", 20.0, 0.4, 30)};
  p.torqueLimit = 1e3;  // far above k * 30 deg: the clip never acts
  const ImpedanceStateMachine law(p);
  ASSERT_EQ(law.numStates(), 0);
  const double theta0 = 0, eq = 30 * kDegToRad;
  const double omega = std::sqrt(20.0 / kInertia), zeta = 0.4 / (2 * std::sqrt(20.0 * kInertia));
  const double omegaD = omega * std::sqrt(1 - zeta * zeta);
  // theta(t) = eq + e^{-zeta omega t} (A cos omegaD t + B sin omegaD t), theta(0) = 0, theta'(0) = 0.
  const double a = theta0 - eq, b = zeta * omega * a / omegaD;
  KneeOnFixedThigh ode(law, kInertia);
  DormandPrince dp(ode, kOdeTol, kOdeTol);
  const double y0[2] = {theta0, 0.0};
  dp.initialize(0, y0);
  double maxError = 0;
  for (int i = 1; i <= 200; ++i) {
    const double t = 0.005 * i;
    dp.integrateTo(t);
    const double exact = eq + std::exp(-zeta * omega * t) * (a * std::cos(omegaD * t) + b * std::sin(omegaD * t));
    maxError = std::max(maxError, std::abs(dp.getState()[0] - exact));
  }
  constexpr double kAngleTol = 1e-9;  // rad: 1000 steps of 1e-11 local error, with margin
  EXPECT_LT(maxError, kAngleTol);
  std::printf("one-state knee vs closed-form damped oscillation: max |error| %.2e rad over 1 s\n", maxError);
  EXPECT_GT(zeta, 0.05);  // a real oscillation, decaying: the damping is tested too
  EXPECT_LT(zeta, 0.5);
}

// Knee motion: a half sine, 10 -> 70 -> 10 deg over 0.4 s.
KneeKinematics halfSine(double t) {
  constexpr double kPeriod = 0.4, kLow = 10 * kDegToRad, kAmplitude = 60 * kDegToRad;
  return {kLow + kAmplitude * std::sin(kPi * t / kPeriod), kAmplitude * kPi / kPeriod * std::cos(kPi * t / kPeriod)};
}

// Time at which the weight of state `index` first reaches 1/2 along the prescribed motion.
double timeStateEntered(const ImpedanceStateMachine& law, int index, double tEnd) {
  PrescribedKnee ode(law, halfSine);
  DormandPrince dp(ode, kOdeTol, kOdeTol);
  std::vector<double> z(static_cast<std::size_t>(law.numStates()));
  law.initialStates(z.data());
  dp.initialize(0, z.data());
  dp.setMaxStep(1e-4);
  while (dp.getTime() < tEnd) {
    dp.step(tEnd);
    if (law.calcStateWeights(dp.getState())[static_cast<std::size_t>(index)] >= 0.5) {
      // Refine inside the last step by bisection on the dense output.
      double lo = dp.getStepStartTime(), hi = dp.getTime();
      for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        dp.interpolate(mid, z.data());
        (law.calcStateWeights(z.data())[static_cast<std::size_t>(index)] >= 0.5 ? hi : lo) = mid;
      }
      return hi;
    }
  }
  return NAN;
}

TEST(ImpedanceStateMachine, TransitionsHappenWhereTheirRuleSays) {
  const ImpedanceStateMachineParams p = oslSwing();
  const ImpedanceStateMachine law(p);
  // Rule times of the half sine: rate < 3 deg/s (with the knee above 50 deg) where
  // cos(pi t / T) = 3 / (60 pi / 0.4); knee < 30 deg after the peak where sin = 20/60.
  const double fireFlexion = 0.4 / kPi * std::acos(3.0 / (60 * kPi / 0.4));
  const double fireExtension = 0.4 - 0.4 / kPi * std::asin(20.0 / 60.0);
  // Once fired, s' = (1 - s) / tau: the weight of the next state passes 1/2 at tau ln 2.
  const double lag = p.latchTime * std::log(2.0);
  // The rule switches the latch derivative on; at 1e-11 the error control brackets that
  // switch far inside a microsecond (measured: 1e-12 s).
  constexpr double kGateTol = 1e-6;  // s
  const double entered1 = timeStateEntered(law, 1, 0.4), entered2 = timeStateEntered(law, 2, 0.4);
  EXPECT_NEAR(entered1, fireFlexion + lag, kGateTol);
  EXPECT_NEAR(entered2, fireExtension + lag, kGateTol);
  std::printf("transitions: extension entered %.3e s, terminal %.3e s after rule + tau ln 2\n",
              entered1 - fireFlexion - lag, entered2 - fireExtension - lag);
  EXPECT_GT(fireExtension - fireFlexion, 0.1);  // two distinct events
}

TEST(ImpedanceStateMachine, MinimumTimeInStateDelaysTheTransition) {
  ImpedanceStateMachineParams p = oslSwing();
  p.states[0].transition.flexionSide = ThresholdSide::kAny;
  p.states[0].transition.rateSide = ThresholdSide::kAny;
  p.states[0].transition.minTime = 0.05;
  const ImpedanceStateMachine law(p);
  constexpr double kGateTol = 1e-6;  // s, as above
  EXPECT_NEAR(timeStateEntered(law, 1, 0.4), 0.05 + p.latchTime * std::log(2.0), kGateTol);
}

TEST(ImpedanceStateMachine, AFiredTransitionHoldsAndWeightsSumToOne) {
  const ImpedanceStateMachine law(oslSwing());
  // Latches past 1/2 keep going whatever the knee does; below, they wait for the rule.
  const double past[4] = {0.6, 0.0, 0.1, 0.0};
  double zdot[4];
  law.calcStateDerivatives({0.0, 5.0}, past, zdot);  // knee at 0 deg, flexing: rule 0 does not hold
  EXPECT_GT(zdot[0], 0.0);
  const double before[4] = {0.4, 0.0, 0.1, 0.0};
  law.calcStateDerivatives({0.0, 5.0}, before, zdot);
  EXPECT_EQ(zdot[0], 0.0);
  // Rule 1 (knee < 30 deg) holds, but the machine is still in state 0: no skipping.
  EXPECT_EQ(zdot[1], 0.0);
  for (double s1 : {0.0, 0.3, 1.0})
    for (double s2 : {0.0, 0.2 * s1, s1}) {
      const double z[4] = {s1, s2, 0.0, 0.0};
      const std::vector<double> w = law.calcStateWeights(z);
      EXPECT_NEAR(w[0] + w[1] + w[2], 1.0, 1e-15);
    }
}

TEST(ImpedanceStateMachine, DissipativeModeOnlyResists) {
  ImpedanceStateMachineParams p = oslSwing();
  p.mode = ImpedanceMode::kDissipative;
  p.torqueLimit = 1e3;  // the clip never acts: the projection alone is tested
  const ImpedanceStateMachine law(p);
  EXPECT_TRUE(law.isPassive());
  int pushedBack = 0;  // samples where the impedance moment had the rate's sign
  for (double s1 : {0.0, 0.5, 1.0})
    for (double deg : {-5.0, 10.0, 40.0, 65.0, 90.0})
      for (double rate : {-8.0, -0.5, -0.01, 0.0, 0.01, 0.5, 8.0}) {
        const double z[4] = {s1, 0.0, 0.0, 0.0};
        const KneeKinematics knee{deg * kDegToRad, rate};
        const double m = law.calcMoment(knee, z);
        EXPECT_LE(m * rate, 0.0) << deg << " deg, " << rate << " rad/s";
        if (law.calcImpedanceMoment(knee, z) * rate > 0) ++pushedBack;
        // Fast enough that tanh(rate / w) = 1: a resisting moment passes unchanged.
        const double impedance = law.calcImpedanceMoment(knee, z);
        if (std::abs(rate) >= 0.5 && impedance * rate <= 0) {
          EXPECT_NEAR(m, impedance, 1e-9 * std::abs(impedance));
        }
      }
  EXPECT_GT(pushedBack, 10);  // the projection had work to do
}

TEST(ImpedanceStateMachine, PoweredModeRespectsTheTorqueLimit) {
  ImpedanceStateMachineParams p = oslSwing();
  p.torqueLimit = 20;
  const ImpedanceStateMachine law(p);
  EXPECT_FALSE(law.isPassive());
  const double z[4] = {0, 0, 0, 0};
  // 39.749 N m/rad * 60 deg = 41.6 N m towards the equilibrium: clipped to 20 N m.
  EXPECT_GT(law.calcImpedanceMoment({0.0, 0.0}, z), 40.0);
  EXPECT_DOUBLE_EQ(law.calcMoment({0.0, 0.0}, z), 20.0);
  EXPECT_DOUBLE_EQ(law.calcMoment({0.0, -100.0}, z), 20.0);
  EXPECT_DOUBLE_EQ(law.calcMoment({2.0, 30.0}, z), -20.0);
  // Inside the limit the impedance law as is (and it may push: powered).
  EXPECT_DOUBLE_EQ(law.calcMoment({50 * kDegToRad, 1.0}, z), law.calcImpedanceMoment({50 * kDegToRad, 1.0}, z));
  EXPECT_GT(law.calcMoment({50 * kDegToRad, 1.0}, z), 0.0);
}

TEST(ImpedanceStateMachine, RefusesBadParameters) {
  const auto refuses = [](const std::function<void(ImpedanceStateMachineParams&)>& edit, const char* what) {
    ImpedanceStateMachineParams p = oslSwing();
    edit(p);
    try {
      ImpedanceStateMachine law(p);
      ADD_FAILURE() << "accepted: " << what;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  refuses([](auto& p) { p.states.clear(); }, "at least one state");
  refuses([](auto& p) { p.states[1].damping = -1; }, "damping must not be negative");
  refuses([](auto& p) { p.states[0].stiffness = -1; }, "stiffness must not be negative");
  refuses([](auto& p) { p.torqueLimit = 0; }, "torque limit must be positive");
  refuses([](auto& p) { p.states[0].transition.to = "nowhere"; }, "goes to the next state, swing_extension");
  refuses([](auto& p) { p.states[1].hasTransition = false; }, "needs a transition");
  refuses([](auto& p) { p.states[2].hasTransition = true; }, "has no state to go to");
  refuses([](auto& p) { p.states[2].name = "swing_flexion"; }, "appears twice");
  refuses([](auto& p) { p.states[0].transition.minTime = -0.1; }, "minimum time must not be negative");
}

}  // namespace
}  // namespace swingsim
