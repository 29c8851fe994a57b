#include "swing/reference_swing.h"

#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/input_error.h"
#include "numerics/dormand_prince.h"
#include "swing/reference_socket_chain.h"

namespace swingsim {

namespace {

// The chain's constant terms (docs/reference-swing.md): the shank-and-foot body's COM angle
// gamma off the shank axis, the inertia terms and the gravity moments.
struct ChainTerms {
  double gamma, m11, m22, m2L1r2, massMoment1, massMoment2, gravity1, gravity2;
  double shankBodyMass;  // kg: shank, foot and added mass
};

ChainTerms calcChainTerms(const LegGeometry& g) {
  const double m1 = g.thighMass, a1 = g.thighCom, I1 = g.thighInertia, L1 = g.thighLength;
  const double ms = g.shankMass, as = g.shankCom, Is = g.shankInertia, L2 = g.shankLength;
  const double mf = g.footMass, cf = g.footComForward, If = g.footInertia;
  const double ma = g.added.mass, da = g.added.distanceBelowKnee;
  const double m2 = ms + mf + ma;
  const double momentX = mf * cf;                      // m2 r2 sin gamma
  const double momentY = ms * as + mf * L2 + ma * da;  // m2 r2 cos gamma
  const double r2 = std::hypot(momentX, momentY) / m2;
  ChainTerms c{};
  c.gamma = std::atan2(momentX, momentY);
  c.m11 = I1 + m1 * a1 * a1 + m2 * L1 * L1;
  c.m22 = Is + ms * as * as + If + mf * (cf * cf + L2 * L2) + ma * da * da;
  c.m2L1r2 = m2 * L1 * r2;
  c.massMoment1 = m1 * a1 + m2 * L1;
  c.massMoment2 = m2 * r2;
  c.gravity1 = c.massMoment1 * kGravity;
  c.gravity2 = c.massMoment2 * kGravity;
  c.shankBodyMass = m2;
  return c;
}

}  // namespace

KneeMomentNeeded calcKneeMomentNeeded(const LegGeometry& g, double hip, double hipRate, double hipAcc, double knee,
                                      double kneeAcc) {
  // The shank row of the equations with the hip fixed, solved for the knee moment:
  // m12 phi'' + m22 beta'' = -M + m2 L1 r2 sin(phi - beta) phi'^2 - m2 r2 g sin(beta).
  const ChainTerms c = calcChainTerms(g);
  const double beta = hip - knee + c.gamma, betaAcc = hipAcc - kneeAcc;
  const double m12 = c.m2L1r2 * std::cos(hip - beta);
  KneeMomentNeeded out;
  out.moment = -(m12 * hipAcc + c.m22 * betaAcc) + c.m2L1r2 * std::sin(hip - beta) * hipRate * hipRate -
               c.gravity2 * std::sin(beta);
  out.perHipAcceleration = -(m12 + c.m22);
  out.perKneeAcceleration = c.m22;
  return out;
}

// The equations of motion, derived by hand (2-DOF Lagrangian): docs/reference-swing.md; the
// moving hip's support-acceleration forces: docs/moving-hip.md. With a compliant socket the
// leg is ReferenceSocketChain's four coordinates; its piston and rotation and their rates
// follow the knee law's states in y (y[0..3] keep their meaning: limb, shank line, rates).
class ReferenceSwing::Equations final : public OdeSystem {
 public:
  Equations(const LegGeometry& g, const KneeLaw& knee, const HipMomentProfile& hipMoment, const HipRange& hipRange,
            std::optional<ThighMotion> thigh = std::nullopt, std::optional<HipPath> hip = std::nullopt)
      : law_(knee.clone()),
        numLawStates_(law_->numStates()),
        hipMoment_(hipMoment),
        hipStop_(makeHipStop(hipRange)),
        thigh_(std::move(thigh)),
        hip_(std::move(hip)) {
    const ChainTerms c = calcChainTerms(g);
    gamma_ = c.gamma;
    m11_ = c.m11;
    m22_ = c.m22;
    m2L1r2_ = c.m2L1r2;
    massMoment1_ = c.massMoment1;
    massMoment2_ = c.massMoment2;
    gravity1_ = c.gravity1;
    gravity2_ = c.gravity2;
    if (g.socket) {
      socket_.emplace(g, c.gamma, c.massMoment2, c.shankBodyMass, c.m22);
      socketIndex_ = 4 + numLawStates_;
    }
  }

  int numStates() const override { return 4 + numLawStates_ + (socket_ ? 4 : 0); }

  /// The socket's piston in y (then rotation and their rates); -1 without a socket.
  int socketIndex() const { return socketIndex_; }

  void calcDerivatives(double t, const double* y, double* dydt) const override {
    double hipMoment;
    calcDerivativesAndHipMoment(t, y, dydt, hipMoment);
  }

  /// The derivatives and the hip moment (the drive's, or the one a prescribed thigh needs).
  void calcDerivativesAndHipMoment(double t, const double* y, double* dydt, double& hipMoment) const {
    if (socket_) {
      calcSocketDerivatives(t, y, dydt, hipMoment);
      return;
    }
    const double phi = y[0], beta = y[1], phiDot = y[2], betaDot = y[3];
    const KneeKinematics knee{calcKneeFlexion(y), phiDot - betaDot, phi, phiDot, t};
    const double* z = y + 4;
    const double kneeMoment = law_->calcMoment(knee, z);
    const double s = std::sin(phi - beta);
    const double m12 = m2L1r2_ * std::cos(phi - beta);
    // The moving support's generalized forces (zero with the hip fixed).
    double supportPhi = 0, supportBeta = 0;
    if (hip_) {
      const std::array<double, 2> a = hip_->calcAcceleration(t);
      supportPhi = -massMoment1_ * (a[0] * std::cos(phi) + a[1] * std::sin(phi));
      supportBeta = -massMoment2_ * (a[0] * std::cos(beta) + a[1] * std::sin(beta));
    }
    const double rhs2 = -kneeMoment + m2L1r2_ * s * phiDot * phiDot - gravity2_ * std::sin(beta) + supportBeta;
    dydt[0] = phiDot;
    dydt[1] = betaDot;
    if (thigh_) {
      const double phiDDot = thigh_->calcAcceleration(t);
      const double betaDDot = (rhs2 - m12 * phiDDot) / m22_;
      dydt[2] = phiDDot;
      dydt[3] = betaDDot;
      hipMoment = m11_ * phiDDot + m12 * betaDDot + m2L1r2_ * s * betaDot * betaDot + gravity1_ * std::sin(phi) -
                  kneeMoment - supportPhi;
    } else {
      hipMoment = hipMoment_.calcMoment(t) + hipStop_.calcJointMoment(phi, phiDot);
      const double rhs1 =
          hipMoment + kneeMoment - m2L1r2_ * s * betaDot * betaDot - gravity1_ * std::sin(phi) + supportPhi;
      const double det = m11_ * m22_ - m12 * m12;
      dydt[2] = (m22_ * rhs1 - m12 * rhs2) / det;
      dydt[3] = (m11_ * rhs2 - m12 * rhs1) / det;
    }
    if (numLawStates_ > 0) law_->calcStateDerivatives(knee, z, dydt + 4);
  }

  /// The hip moment at (t, y), N m.
  double calcHipMoment(double t, const double* y) const {
    std::vector<double> dydt(static_cast<std::size_t>(numStates()));
    double hipMoment;
    calcDerivativesAndHipMoment(t, y, dydt.data(), hipMoment);
    return hipMoment;
  }
  /// The knee law's moment at y, N m.
  double calcKneeMoment(double t, const double* y) const {
    return law_->calcMoment({calcKneeFlexion(y), calcKneeFlexionRate(y), y[0], y[2], t}, y + 4);
  }

  /// The knee's flexion and rate at y: the limb to the shank, plus the socket's rotation.
  double calcKneeFlexion(const double* y) const {
    return calcKneeFlexion(y[0], y[1]) + (socket_ ? y[socketIndex_ + 1] : 0.0);
  }
  double calcKneeFlexionRate(const double* y) const { return y[2] - y[3] + (socket_ ? y[socketIndex_ + 3] : 0.0); }
  double calcKneeFlexion(double phi, double beta) const { return phi - beta + gamma_; }
  double toBeta(double hipFlexion, double kneeFlexion) const { return hipFlexion - kneeFlexion + gamma_; }

  /// y at toe-off: the mechanics from the initial conditions, the law's own initial states.
  std::vector<double> makeInitialState(const InitialConditions& initial) const {
    std::vector<double> y(static_cast<std::size_t>(numStates()));
    const double hip = thigh_ ? thigh_->calcAngle(0) : initial.hipFlexion;
    const double hipRate = thigh_ ? thigh_->calcRate(0) : initial.hipFlexionRate;
    y[0] = hip;
    y[1] = toBeta(hip, initial.kneeFlexion);
    y[2] = hipRate;
    y[3] = hipRate - initial.kneeFlexionRate;
    if (numLawStates_ > 0) law_->initialStates(y.data() + 4);
    // The socket at rest and undeflected (docs/socket.md): y's trailing zeros.
    return y;
  }

  double calcEnergy(double phi, double beta, double phiDot, double betaDot, const SocketDeflection& d = {},
                    const SocketDeflection& rate = {}) const {
    if (socket_)
      return socket_->calcEnergy({phi, beta, d.piston, d.rotation}, {phiDot, betaDot, rate.piston, rate.rotation});
    const double m12 = m2L1r2_ * std::cos(phi - beta);
    const double kinetic = 0.5 * m11_ * phiDot * phiDot + m12 * phiDot * betaDot + 0.5 * m22_ * betaDot * betaDot;
    return kinetic - gravity1_ * std::cos(phi) - gravity2_ * std::cos(beta);
  }

 private:
  // The socket leg's derivatives and hip moment (ReferenceSocketChain), y as above.
  void calcSocketDerivatives(double t, const double* y, double* dydt, double& hipMoment) const {
    const int s = socketIndex_;
    const ReferenceSocketChain::Vec q{y[0], y[1], y[s], y[s + 1]}, u{y[2], y[3], y[s + 2], y[s + 3]};
    const KneeKinematics knee{calcKneeFlexion(y), calcKneeFlexionRate(y), y[0], y[2], t};
    const double* z = y + 4;
    ReferenceSocketChain::Forces f;
    f.kneeMoment = law_->calcMoment(knee, z);
    if (hip_) f.support = hip_->calcAcceleration(t);
    ReferenceSocketChain::Vec a;
    if (thigh_) {
      a = socket_->calcAccelerationWithThigh(q, u, thigh_->calcAcceleration(t), f, hipMoment);
    } else {
      hipMoment = hipMoment_.calcMoment(t) + hipStop_.calcJointMoment(y[0], y[2]);
      f.hipMoment = hipMoment;
      a = socket_->calcAcceleration(q, u, f);
    }
    for (int i = 0; i < 2; ++i) {
      dydt[i] = u[static_cast<std::size_t>(i)];
      dydt[i + 2] = a[static_cast<std::size_t>(i)];
      dydt[s + i] = u[static_cast<std::size_t>(i + 2)];
      dydt[s + i + 2] = a[static_cast<std::size_t>(i + 2)];
    }
    if (numLawStates_ > 0) law_->calcStateDerivatives(knee, z, dydt + 4);
  }

  static JointStop makeHipStop(const HipRange& range) {
    JointStopParams p;  // stiffness and restitution: the defaults, as in LegModel
    p.lower = range.minFlexion;
    p.upper = range.maxFlexion;
    return JointStop(p);
  }

  std::unique_ptr<KneeLaw> law_;
  int numLawStates_;
  HipMomentProfile hipMoment_;
  JointStop hipStop_;
  std::optional<ThighMotion> thigh_;            // the prescribed thigh, if it drives the swing
  std::optional<HipPath> hip_;                  // the moving hip, if the pelvis is measured
  std::optional<ReferenceSocketChain> socket_;  // a compliant socket's leg
  int socketIndex_ = -1;
  double gamma_ = 0, m11_ = 0, m22_ = 0, m2L1r2_ = 0, gravity1_ = 0, gravity2_ = 0;
  double massMoment1_ = 0, massMoment2_ = 0;  // kg m: m1 a1 + m2 L1, m2 r2
};

ReferenceSwing::ReferenceSwing(const LegGeometry& geometry, const KneeLaw& knee, const HipMomentProfile& hipMoment,
                               const HipRange& hipRange)
    : equations_(std::make_shared<Equations>(geometry, knee, hipMoment, hipRange)) {}

ReferenceSwing::ReferenceSwing(const LegGeometry& geometry, const KneeLaw& knee, const ThighMotion& thigh)
    : equations_(std::make_shared<Equations>(geometry, knee, HipMomentProfile{}, HipRange{}, thigh)) {}

ReferenceSwing::ReferenceSwing(const LegGeometry& geometry, const KneeLaw& knee, const ThighMotion& thigh,
                               const HipPath& hip)
    : equations_(std::make_shared<Equations>(geometry, knee, HipMomentProfile{}, HipRange{}, thigh, hip)) {}

namespace {

// The step budget: a law far too stiff for an explicit method at this tolerance.
void checkStepBudget(const DormandPrince& dp, double relTol) {
  if (dp.getNumSteps() <= ReferenceSwing::kMaxSteps) return;
  throw RunError("reference swing: stopped after " + std::to_string(ReferenceSwing::kMaxSteps) +
                 " integrator steps (the budget; a swing takes a few thousand) at t = " + formatNumber(dp.getTime()) +
                 " s with relative tolerance " + formatNumber(relTol) +
                 ": the knee law is too stiff for this tolerance (loosen it, or check the knee model for a value far "
                 "too large, a unit mistake?)");
}

int signOf(double v) { return (v > 0) - (v < 0); }

// Simbody's Event::classifyTransition: leaving zero is not an event; reaching zero is.
bool isRising(double before, double after) { return signOf(before) == -1 && signOf(after) >= 0; }
bool isFalling(double before, double after) { return signOf(before) == 1 && signOf(after) <= 0; }

// Bisection on the dense output of the last step for a sign change of f; returns the
// midpoint of the final bracket (< ReferenceSwing::kEventTimeTol wide).
template <class F>
double locateCrossing(const DormandPrince& dp, F f) {
  double lo = dp.getStepStartTime(), hi = dp.getTime();
  const int loSign = signOf(f(lo));
  while (hi - lo > ReferenceSwing::kEventTimeTol) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;  // bracket at floating-point resolution
    if (signOf(f(mid)) == loSign) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

// The three trigger signals of simulateSwing's event handlers at one state: the thigh past
// its target, the knee's flexion rate, the knee inside the zone of stability (positive in it).
struct SwingSignals {
  double thigh, rate, zone;
};

// A sign change of one signal within the last step, at `time` (s).
enum class CrossingKind { kThigh, kPeak, kZone };
struct Crossing {
  double time;
  CrossingKind kind;
};

// The step's crossings in time order, as Simbody handles them (insertion sort: at most three).
void sortByTime(Crossing* crossings, int count) {
  for (int i = 1; i < count; ++i)
    for (int j = i; j > 0 && crossings[j].time < crossings[j - 1].time; --j) std::swap(crossings[j], crossings[j - 1]);
}

// The swing-end rule's state between steps: the swing ends once the thigh has reached its
// target and the knee is back in the zone after its peak above it.
class SwingEndTracker {
 public:
  explicit SwingEndTracker(double zone) : zone_(zone) {}

  bool thighReached() const { return thighReached_; }

  // The thigh reached its target at t.
  void onThighAtTarget(double t) {
    thighReached_ = true;
    result_.thighAtTargetTime = t;
  }

  // The knee's flexion peaked at t at `knee` (rad); the highest peak above the zone counts.
  void onKneePeak(double t, double knee) {
    if (knee <= zone_) return;  // wiggles inside the zone are not the swing's peak
    if (!peakSeen_ || knee > result_.peakKneeFlexion) {
      result_.peakKneeFlexion = knee;
      result_.peakKneeFlexionTime = t;
    }
    peakSeen_ = true;
  }

  // The knee's flexion crossed the zone boundary at t, into the zone (falling below the
  // boundary) or out of it.
  void onZoneBoundary(double t, bool intoZone) {
    if (!intoZone) {
      kneeInZone_ = false;
      return;
    }
    if (!peakSeen_) return;  // still on the way up from toe-off
    kneeInZone_ = true;
    result_.kneeEntersZoneTime = t;
  }

  bool hasEnded() const { return thighReached_ && kneeInZone_; }

  // The result for a swing that ended at t after `steps` integrator steps: every field set,
  // as it ends only after a peak.
  ReferenceSwingEnd end(double t, long steps) {
    result_.swingTime = t;
    result_.steps = steps;
    return result_;
  }

 private:
  double zone_;
  bool thighReached_ = false, peakSeen_ = false, kneeInZone_ = false;
  ReferenceSwingEnd result_;
};

}  // namespace

ReferenceTrajectory ReferenceSwing::integrate(const InitialConditions& initial, const std::vector<double>& sampleTimes,
                                              double relTol, double absTol) const {
  const Equations& eq = *equations_;
  for (std::size_t i = 0; i < sampleTimes.size(); ++i) {
    if (!(sampleTimes[i] >= 0) || (i > 0 && sampleTimes[i] < sampleTimes[i - 1]))
      throw std::invalid_argument("reference swing: sample times must be >= 0 and non-decreasing");
  }
  const std::vector<double> y0 = eq.makeInitialState(initial);
  DormandPrince dp(eq, relTol, absTol);
  dp.initialize(0.0, y0.data());

  ReferenceTrajectory out;
  for (auto* v : {&out.time, &out.hipFlexion, &out.kneeFlexion, &out.hipFlexionRate, &out.kneeFlexionRate,
                  &out.hipMoment, &out.kneeMoment})
    v->reserve(sampleTimes.size());
  const int socket = eq.socketIndex();
  for (double t : sampleTimes) {
    while (dp.getTime() < t) {
      dp.step(t);
      checkStepBudget(dp, relTol);
    }
    const double* y = dp.getState();
    out.time.push_back(t);
    out.hipFlexion.push_back(y[0]);
    out.kneeFlexion.push_back(eq.calcKneeFlexion(y));
    out.hipFlexionRate.push_back(y[2]);
    out.kneeFlexionRate.push_back(eq.calcKneeFlexionRate(y));
    out.hipMoment.push_back(eq.calcHipMoment(t, y));
    out.kneeMoment.push_back(eq.calcKneeMoment(t, y));
    if (socket >= 0) {
      out.socket.push_back({y[socket], y[socket + 1]});
      out.socketRate.push_back({y[socket + 2], y[socket + 3]});
    }
  }
  return out;
}

ReferenceSwingEnd ReferenceSwing::calcSwingEnd(const InitialConditions& initial, const SwingEndRule& rule,
                                               double relTol, double absTol) const {
  const Equations& eq = *equations_;
  const std::vector<double> y0 = eq.makeInitialState(initial);
  DormandPrince dp(eq, relTol, absTol);
  dp.initialize(0.0, y0.data());

  // The three trigger functions of simulateSwing's event handlers.
  const double target = rule.thighTargetFlexion, zone = rule.zoneOfStability;
  auto thighSignal = [&](double t) { return dp.interpolate(t, 0) - target; };
  // The knee at t from the whole interpolated state, by the equations' own rule (with a
  // socket, its rotation too).
  std::vector<double> yAt(static_cast<std::size_t>(eq.numStates()));
  auto kneeRate = [&](double t) {
    dp.interpolate(t, yAt.data());
    return eq.calcKneeFlexionRate(yAt.data());
  };
  auto kneeFlexionAt = [&](double t) {
    dp.interpolate(t, yAt.data());
    return eq.calcKneeFlexion(yAt.data());
  };
  auto zoneSignal = [&](double t) { return zone - kneeFlexionAt(t); };
  auto signalsAt = [&](const double* y) {
    return SwingSignals{y[0] - target, eq.calcKneeFlexionRate(y), zone - eq.calcKneeFlexion(y)};
  };

  SwingEndTracker tracker(zone);
  SwingSignals before = signalsAt(dp.getState());
  while (true) {
    if (dp.getTime() >= rule.timeLimit) {
      throw RunError("reference swing: the swing did not end within the time limit of " + formatNumber(rule.timeLimit) +
                     " s");
    }
    dp.step(rule.timeLimit);
    checkStepBudget(dp, relTol);
    const SwingSignals after = signalsAt(dp.getState());
    const bool intoZone = isRising(before.zone, after.zone);  // knee flexion fell below the zone boundary

    Crossing crossings[3];
    int count = 0;
    if (!tracker.thighReached() && isRising(before.thigh, after.thigh))
      crossings[count++] = {locateCrossing(dp, thighSignal), CrossingKind::kThigh};
    if (isFalling(before.rate, after.rate)) crossings[count++] = {locateCrossing(dp, kneeRate), CrossingKind::kPeak};
    if (intoZone || isFalling(before.zone, after.zone))
      crossings[count++] = {locateCrossing(dp, zoneSignal), CrossingKind::kZone};
    sortByTime(crossings, count);

    for (int i = 0; i < count; ++i) {
      const double t = crossings[i].time;
      switch (crossings[i].kind) {
        case CrossingKind::kThigh:
          tracker.onThighAtTarget(t);
          break;
        case CrossingKind::kPeak:
          tracker.onKneePeak(t, kneeFlexionAt(t));
          break;
        case CrossingKind::kZone:
          tracker.onZoneBoundary(t, intoZone);
          break;
      }
      if (tracker.hasEnded()) return tracker.end(t, dp.getNumSteps());
    }
    before = after;
  }
}

double ReferenceSwing::calcSwingTime(const InitialConditions& initial, const SwingEndRule& rule, double tol) const {
  return calcSwingEnd(initial, rule, tol, tol).swingTime;
}

double ReferenceSwing::calcMechanicalEnergy(double hipFlexion, double kneeFlexion, double hipFlexionRate,
                                            double kneeFlexionRate, const SocketDeflection& socket,
                                            const SocketDeflection& socketRate) const {
  const Equations& eq = *equations_;
  // The shank's line from the socket's: phi + rotation - knee + gamma.
  return eq.calcEnergy(hipFlexion, eq.toBeta(socket.calcSocketAngle(hipFlexion), kneeFlexion), hipFlexionRate,
                       socketRate.calcSocketAngle(hipFlexionRate) - kneeFlexionRate, socket, socketRate);
}

}  // namespace swingsim
