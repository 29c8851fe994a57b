// The compliant socket (LegGeometry::socket, docs/socket.md) against an independent
// integration of the same leg: four generalized coordinates (hip flexion, piston, socket
// rotation, knee flexion), each body's COM written as a planar point of them by hand, the
// mass matrix and the velocity-product terms from those points by central differences
// (Lagrange: M qdd = Q - sum m J^T (Jdot qdot)), stepped by classical RK4 at 10 us. No code is
// shared with Simbody or with LegModel's mass split.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <utility>

#include "core/input_error.h"
#include "core/units.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "knee/knee_law.h"
#include "leg/leg_model.h"
#include "simbody_sampling.h"
#include "swing/knee_setup.h"
#include "swing/reference_swing.h"
#include "swing/swing_simulation.h"

namespace swingsim {
namespace {

using Vec4 = std::array<double, 4>;
using P2 = std::array<double, 2>;

Participant loadP1() { return loadParticipant(std::string(SWINGSIM_SOURCE_DIR) + "/participants/p1.yaml"); }

/// P1 with a socket of these springs and dampers (N m/rad, N m s/rad, N/m, N s/m), the rest
/// MyoSuite's.
Participant loadP1WithSocket(double rotationStiffness, double rotationDamping, double pistonStiffness,
                             double pistonDamping) {
  Participant p = loadP1();
  p.socket = SocketCompliance{};
  p.socket->rotationStiffness = rotationStiffness;
  p.socket->rotationDamping = rotationDamping;
  p.socket->pistonStiffness = pistonStiffness;
  p.socket->pistonDamping = pistonDamping;
  return p;
}

/// A plain knee damper, so the test's knee is a known function of the knee's rate.
class KneeDamper final : public KneeLaw {
 public:
  static constexpr double kDamping = 0.6;  // N m s/rad
  std::string name() const override { return "test damper"; }
  double calcMoment(const KneeKinematics& k, const double*) const override { return -kDamping * k.flexionRate; }
  bool isPassive() const override { return true; }
  std::unique_ptr<KneeLaw> clone() const override { return std::make_unique<KneeDamper>(*this); }
};

/// The leg of LegGeometry g with its socket, written from the drawing: x forward, y up, hip
/// at the origin; q = {hip flexion, piston (+ = down the thigh), socket rotation (+ = the
/// hip's sense), knee flexion (+ swings the shank back)}.
class IndependentSocketLeg {
 public:
  IndependentSocketLeg(const LegGeometry& g, const HipMomentProfile& hip) : g_(g), hip_(hip) {
    const SocketCompliance& c = *g.socket;
    // Thigh segment = residual limb + socket: take the socket out by first and second moments about the hip.
    const double socketCom = g.socketPivotBelowHip - c.comAbovePivot;
    const double thighAboutHip = g.thighInertia + g.thighMass * g.thighCom * g.thighCom;
    limbMass_ = g.thighMass - c.mass;
    limbCom_ = (g.thighMass * g.thighCom - c.mass * socketCom) / limbMass_;
    limbInertia_ = thighAboutHip - c.mass * socketCom * socketCom - c.inertia - limbMass_ * limbCom_ * limbCom_;
    // The shank with the foot at 90 deg, in the shank's frame (x forward, y up the shank).
    shankFootMass_ = g.shankMass + g.footMass;
    shankFootCom_ = {g.footMass * g.footComForward / shankFootMass_,
                     -(g.shankMass * g.shankCom + g.footMass * g.shankLength) / shankFootMass_};
    const auto sq = [](double x, double y) { return x * x + y * y; };
    shankFootInertia_ = g.shankInertia + g.shankMass * sq(shankFootCom_[0], -g.shankCom - shankFootCom_[1]) +
                        g.footInertia +
                        g.footMass * sq(g.footComForward - shankFootCom_[0], -g.shankLength - shankFootCom_[1]);
  }

  /// qdd for state (q, u) at time t.
  Vec4 calcAcceleration(double t, const Vec4& q, const Vec4& u) const {
    const SocketCompliance& c = *g_.socket;
    double m[4][4] = {}, rhs[4] = {};
    rhs[0] = hip_.calcMoment(t);
    rhs[1] = -c.pistonStiffness * q[1] - c.pistonDamping * u[1];
    rhs[2] = -c.rotationStiffness * q[2] - c.rotationDamping * u[2];
    rhs[3] = -KneeDamper::kDamping * u[3];
    const Body bodies[3] = {
        {limbMass_, limbInertia_, {1, 0, 0, 0}, [this](const Vec4& x) { return limbCom(x); }},
        {c.mass, c.inertia, {1, 0, 1, 0}, [this](const Vec4& x) { return socketCom(x); }},
        {shankFootMass_, shankFootInertia_, {1, 0, 1, -1}, [this](const Vec4& x) { return shankCom(x); }}};
    for (const Body& b : bodies) {
      const auto jac = calcJacobian(b, q);
      const P2 convective = calcConvective(b, q, u);
      for (int i = 0; i < 4; ++i) {
        rhs[i] -= b.mass * (jac[i][0] * convective[0] + jac[i][1] * (convective[1] + kGravity));
        for (int j = 0; j < 4; ++j)
          m[i][j] += b.mass * (jac[i][0] * jac[j][0] + jac[i][1] * jac[j][1]) + b.inertia * b.spin[i] * b.spin[j];
      }
    }
    return solve(m, rhs);
  }

 private:
  struct Body {
    double mass, inertia;
    Vec4 spin;  // d(angle)/dq: planar angles are linear in q
    std::function<P2(const Vec4&)> com;
  };
  static P2 down(double angle) { return {std::sin(angle), -std::cos(angle)}; }
  P2 pivot(const Vec4& q) const {
    const P2 d = down(q[0]);
    return {(g_.socketPivotBelowHip + q[1]) * d[0], (g_.socketPivotBelowHip + q[1]) * d[1]};
  }
  P2 limbCom(const Vec4& q) const { return {limbCom_ * down(q[0])[0], limbCom_ * down(q[0])[1]}; }
  P2 socketCom(const Vec4& q) const {
    const P2 p = pivot(q), d = down(q[0] + q[2]);
    return {p[0] - g_.socket->comAbovePivot * d[0], p[1] - g_.socket->comAbovePivot * d[1]};
  }
  P2 shankCom(const Vec4& q) const {
    const P2 p = pivot(q), d = down(q[0] + q[2]);
    const double toKnee = g_.thighLength - g_.socketPivotBelowHip;
    const double a = q[0] + q[2] - q[3];  // the shank's angle
    const double x = shankFootCom_[0], y = shankFootCom_[1];
    return {p[0] + toKnee * d[0] + x * std::cos(a) - y * std::sin(a),
            p[1] + toKnee * d[1] + x * std::sin(a) + y * std::cos(a)};
  }
  static std::array<P2, 4> calcJacobian(const Body& b, const Vec4& q) {
    constexpr double h = 1e-6;
    std::array<P2, 4> jac{};
    for (int i = 0; i < 4; ++i) {
      Vec4 hi = q, lo = q;
      hi[i] += h;
      lo[i] -= h;
      const P2 a = b.com(hi), z = b.com(lo);
      jac[i] = {(a[0] - z[0]) / (2 * h), (a[1] - z[1]) / (2 * h)};
    }
    return jac;
  }
  // Jdot qdot: the second derivative of the point along the velocity.
  static P2 calcConvective(const Body& b, const Vec4& q, const Vec4& u) {
    constexpr double e = 1e-4;
    Vec4 hi = q, lo = q;
    for (int i = 0; i < 4; ++i) {
      hi[i] += e * u[i];
      lo[i] -= e * u[i];
    }
    const P2 a = b.com(hi), mid = b.com(q), z = b.com(lo);
    return {(a[0] - 2 * mid[0] + z[0]) / (e * e), (a[1] - 2 * mid[1] + z[1]) / (e * e)};
  }
  static Vec4 solve(double m[4][4], double r[4]) {  // Gaussian elimination (M is positive definite)
    for (int k = 0; k < 4; ++k)
      for (int i = k + 1; i < 4; ++i) {
        const double f = m[i][k] / m[k][k];
        for (int j = k; j < 4; ++j) m[i][j] -= f * m[k][j];
        r[i] -= f * r[k];
      }
    Vec4 x{};
    for (int i = 3; i >= 0; --i) {
      double s = r[i];
      for (int j = i + 1; j < 4; ++j) s -= m[i][j] * x[j];
      x[i] = s / m[i][i];
    }
    return x;
  }

  LegGeometry g_;
  HipMomentProfile hip_;
  double limbMass_, limbCom_, limbInertia_, shankFootMass_, shankFootInertia_;
  P2 shankFootCom_;
};

void stepRk4(const IndependentSocketLeg& leg, double t, double h, Vec4& q, Vec4& u) {
  const auto add = [](const Vec4& a, const Vec4& b, double s) {
    Vec4 r;
    for (int i = 0; i < 4; ++i) r[i] = a[i] + s * b[i];
    return r;
  };
  const Vec4 k1q = u, k1u = leg.calcAcceleration(t, q, u);
  const Vec4 k2q = add(u, k1u, h / 2), k2u = leg.calcAcceleration(t + h / 2, add(q, k1q, h / 2), k2q);
  const Vec4 k3q = add(u, k2u, h / 2), k3u = leg.calcAcceleration(t + h / 2, add(q, k2q, h / 2), k3q);
  const Vec4 k4q = add(u, k3u, h), k4u = leg.calcAcceleration(t + h, add(q, k3q, h), k4q);
  for (int i = 0; i < 4; ++i) {
    q[i] += h / 6 * (k1q[i] + 2 * k2q[i] + 2 * k3q[i] + k4q[i]);
    u[i] += h / 6 * (k1u[i] + 2 * k2u[i] + 2 * k3u[i] + k4u[i]);
  }
}

TEST(SocketCompliance, SimbodyLegMatchesAnIndependentIntegrationOfTheSameLeg) {
  // P1 with MyoSuite's socket, driven by P1's hip moment for 0.3 s (the hip stays inside its
  // range, so the range stop never acts), the knee a plain damper.
  Participant p = loadP1();
  p.socket = SocketCompliance{};
  const LegGeometry g = calcLegGeometry(p, 0.02);
  const KneeDamper knee;
  const HipRange wide{-3, 3};
  LegModel leg(g, knee, p.hipMoment, wide, 1.0, false);
  ASSERT_EQ(leg.getKneeCoordinateIndex(), 3);
  const InitialConditions start = p.initial;
  SimTK::State s0 = leg.makeInitialState(start);

  constexpr double kDuration = 0.3, kStep = 1e-5;
  Vec4 q{start.hipFlexion, 0, 0, start.kneeFlexion}, u{start.hipFlexionRate, 0, 0, start.kneeFlexionRate};
  const IndependentSocketLeg reference(g, p.hipMoment);
  double worstAngle = 0, worstPiston = 0, peakPiston = 0, peakRotation = 0;
  int k = 0;
  testing::integrateAndObserve(leg.getSystem(), s0, 1e-10, 0.01, kDuration, [&](const SimTK::State& s) {
    for (; k * kStep < s.getTime() - 1e-12; ++k) stepRk4(reference, k * kStep, kStep, q, u);
    const SocketDeflection d = leg.getSocketDeflection(s);
    worstAngle = std::max({worstAngle, std::abs(leg.getHipFlexion(s) - q[0]), std::abs(d.rotation - q[2]),
                           std::abs(leg.getKneeFlexion(s) - q[3])});
    worstPiston = std::max(worstPiston, std::abs(d.piston - q[1]));
    peakPiston = std::max(peakPiston, std::abs(q[1]));
    peakRotation = std::max(peakRotation, std::abs(q[2]));
  });
  std::printf(
      "socket vs independent leg over %.1f s: worst angle %.2e rad, piston %.2e m; the socket's peak "
      "piston %.2f mm, rotation %.3f deg\n",
      kDuration, worstAngle, worstPiston, peakPiston * 1e3, peakRotation * kRadToDeg);
  // The socket moves (so the comparison is not of two rigid legs) ...
  EXPECT_GT(peakPiston, 1e-4);
  EXPECT_GT(peakRotation, 1e-3);
  // ... and both integrations agree far inside it (central differences: ~1e-8 relative).
  EXPECT_LT(worstAngle, 1e-6);
  EXPECT_LT(worstPiston, 1e-8);
}

TEST(SocketCompliance, ReferenceIntegratorMatchesTheIndependentIntegrationOfTheSameLeg) {
  // The reference integrator's socket leg (swing/reference_socket_chain.h: exact Jacobians)
  // against this file's leg (central differences, RK4): same drive and knee as above, with
  // softer socket springs and dampers so that it gives by degrees and centimetres.
  const Participant p = loadP1WithSocket(60, 2, 3000, 40);
  const LegGeometry g = calcLegGeometry(p, 0.02);
  const ReferenceSwing ref(g, KneeDamper(), p.hipMoment, HipRange{-3, 3});
  std::vector<double> times;
  for (int i = 0; i <= 30; ++i) times.push_back(0.01 * i);
  const ReferenceTrajectory tr = ref.integrate(p.initial, times, 1e-11, 1e-11);
  ASSERT_EQ(tr.socket.size(), times.size());
  constexpr double kStep = 1e-5;
  const IndependentSocketLeg independent(g, p.hipMoment);
  Vec4 q{p.initial.hipFlexion, 0, 0, p.initial.kneeFlexion}, u{p.initial.hipFlexionRate, 0, 0, 0};
  double worstAngle = 0, worstPiston = 0, peakPiston = 0, peakRotation = 0;
  int k = 0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    for (; k * kStep < times[i] - 1e-12; ++k) stepRk4(independent, k * kStep, kStep, q, u);
    worstAngle = std::max({worstAngle, std::abs(tr.hipFlexion[i] - q[0]), std::abs(tr.socket[i].rotation - q[2]),
                           std::abs(tr.kneeFlexion[i] - q[3]), std::abs(tr.kneeFlexionRate[i] - u[3]) * 0.01});
    worstPiston = std::max(worstPiston, std::abs(tr.socket[i].piston - q[1]));
    peakPiston = std::max(peakPiston, std::abs(q[1]));
    peakRotation = std::max(peakRotation, std::abs(q[2]));
  }
  std::printf(
      "reference socket leg vs independent leg over 0.3 s: worst angle %.2e rad, piston %.2e m; peak "
      "piston %.2f mm, rotation %.2f deg\n",
      worstAngle, worstPiston, peakPiston * 1e3, peakRotation * kRadToDeg);
  EXPECT_GT(peakPiston, 1e-3);
  EXPECT_GT(peakRotation, 0.02);
  EXPECT_LT(worstAngle, 1e-6);
  EXPECT_LT(worstPiston, 1e-8);
}

TEST(SocketCompliance, ReferenceSocketLegKeepsItsEnergyWithoutDampersOrDrive) {
  // No knee law, no dampers, no hip moment, the hip stop out of reach: kinetic + potential +
  // the socket springs' energy stays put while the socket swaps energy with the leg.
  const Participant p = loadP1WithSocket(80, 0, 2000, 0);
  const LegGeometry g = calcLegGeometry(p, 0.0);
  HipMomentProfile noHipMoment;
  noHipMoment.flexionAmplitude = 0;
  noHipMoment.extensionAmplitude = 0;
  const ReferenceSwing ref(g, KneeLawSum(), noHipMoment, HipRange{-100, 100});
  InitialConditions start = p.initial;
  start.hipFlexion = 0.5;
  start.kneeFlexion = 0.8;
  const double e0 = ref.calcMechanicalEnergy(start.hipFlexion, start.kneeFlexion, 0, 0);
  std::vector<double> times;
  for (int i = 1; i <= 40; ++i) times.push_back(0.025 * i);
  const ReferenceTrajectory tr = ref.integrate(start, times, 1e-11, 1e-11);
  double peakRotation = 0, peakPiston = 0, worst = 0;
  for (std::size_t i = 0; i < tr.size(); ++i) {
    peakRotation = std::max(peakRotation, std::abs(tr.socket[i].rotation));
    peakPiston = std::max(peakPiston, std::abs(tr.socket[i].piston));
    const double e = ref.calcMechanicalEnergy(tr.hipFlexion[i], tr.kneeFlexion[i], tr.hipFlexionRate[i],
                                              tr.kneeFlexionRate[i], tr.socket[i], tr.socketRate[i]);
    worst = std::max(worst, std::abs(e - e0));
  }
  std::printf(
      "reference socket leg, 1 s undamped: energy drift %.2e J of %.3f J; peak rotation %.2f deg, piston "
      "%.2f mm\n",
      worst, std::abs(e0), peakRotation * kRadToDeg, peakPiston * 1e3);
  EXPECT_GT(peakRotation, 0.01);  // the socket takes part
  EXPECT_GT(peakPiston, 1e-3);
  EXPECT_LT(worst, 1e-8);  // J: ~10 x tolerance x the leg's energy scale, as the rigid leg's test
}

TEST(SocketCompliance, AtZeroDeflectionTheLegCarriesTheThighSegmentsMass) {
  Participant p = loadP1();
  p.socket = SocketCompliance{};
  const LegGeometry rigid = calcLegGeometry(loadP1(), 0.03), socket = calcLegGeometry(p, 0.03);
  const KneeLawSum none;
  LegModel a(rigid, none, p.hipMoment, p.hipRange, 1.0, false), b(socket, none, p.hipMoment, p.hipRange, 1.0, false);
  SimTK::State sa = a.makeInitialState(p.initial), sb = b.makeInitialState(p.initial);
  EXPECT_NEAR(a.calcMechanicalEnergy(sa), b.calcMechanicalEnergy(sb), 1e-12);
  EXPECT_NEAR(a.getMatter().calcSystemMass(sa), b.getMatter().calcSystemMass(sb), 1e-12);
  const SimTK::Vec3 ca = a.getMatter().calcSystemMassCenterLocationInGround(sa),
                    cb = b.getMatter().calcSystemMassCenterLocationInGround(sb);
  EXPECT_LT((ca - cb).norm(), 1e-12);
}

TEST(SocketCompliance, AStiffSocketSwingsAsTheRigidLegAndTheDefaultOneGivesAsItsPhysicsSays) {
  // Stiffer and stiffer, the swing tends to the rigid leg's; MyoSuite's socket gives and
  // lengthens P1's swing by a fraction of a millisecond (docs/socket.md measures it).
  const Participant rigid = loadP1();
  const KneeModel knee = loadKneeModel(rigid.kneeModelPath);
  const auto swing = [&](const Participant& p) { return simulateSwing(makeSwingSetup(p, knee)); };
  const SwingResult base = swing(rigid);
  Participant soft = rigid;
  soft.socket = SocketCompliance{};
  const SwingResult myo = swing(soft);
  Participant stiff = soft;
  stiff.socket->pistonStiffness *= 100;
  stiff.socket->rotationStiffness *= 100;
  const SwingResult stiffer = swing(stiff);
  std::printf("P1 swing: rigid %.6f s, MyoSuite socket %.6f s, 100x stiffer %.6f s\n", base.swingTime, myo.swingTime,
              stiffer.swingTime);
  EXPECT_GT(std::abs(myo.swingTime - base.swingTime), 1e-5);
  EXPECT_LT(std::abs(stiffer.swingTime - base.swingTime), 0.1 * std::abs(myo.swingTime - base.swingTime));
}

TEST(SocketCompliance, TheTrajectorysLandmarksFollowTheSocketsDeflection) {
  // calcPlanarPoseXY (what the trajectory files and the toe clearance use) against Simbody's
  // own kinematics of the deflected leg.
  Participant p = loadP1();
  p.socket = SocketCompliance{};
  const LegGeometry g = calcLegGeometry(p, 0.04);
  const KneeLawSum none;
  const double hipHeight = 0.97;
  LegModel leg(g, none, p.hipMoment, p.hipRange, hipHeight, false);
  SimTK::State s = leg.makeInitialState(p.initial);
  const double hip = 0.3, piston = 0.012, rotation = -0.05, knee = 0.9;
  s.updQ()[0] = hip;
  s.updQ()[1] = piston;
  s.updQ()[2] = rotation;
  s.updQ()[3] = knee;
  leg.getSystem().realize(s, SimTK::Stage::Position);
  ASSERT_NEAR(leg.getSocketDeflection(s).piston, piston, 0);
  const LegPose simbody = leg.calcPose(s);
  const PlanarPose planar = calcPlanarPoseXY(g, hipHeight, hip, knee, {piston, rotation});
  for (const auto& [a, b] : {std::pair{simbody.knee, planar.knee}, std::pair{simbody.ankle, planar.ankle},
                             std::pair{simbody.toe, planar.toe}}) {
    EXPECT_NEAR(a[0], b[0], 1e-14);
    EXPECT_NEAR(a[1], b[1], 1e-14);
  }
  // The deflection moves the toe by millimetres to centimetres: the check is not of a rigid leg.
  const PlanarPose rigid = calcPlanarPoseXY(g, hipHeight, hip, knee);
  EXPECT_GT(std::hypot(rigid.toe[0] - planar.toe[0], rigid.toe[1] - planar.toe[1]), 0.02);
}

TEST(SocketCompliance, ASocketHeavierThanTheThighIsRefused) {
  Participant p = loadP1();
  p.socket = SocketCompliance{};
  p.socket->mass = p.thigh.mass + 0.1;
  EXPECT_THROW(calcLegGeometry(p, 0.0), InputError);
  p.socket->mass = 0.85;
  p.socket->pivotAboveKnee = p.thigh.length + 0.01;  // the pivot above the hip
  EXPECT_THROW(calcLegGeometry(p, 0.0), InputError);
}

}  // namespace
}  // namespace swingsim
