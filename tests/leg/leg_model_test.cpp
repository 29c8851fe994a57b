#include "leg/leg_model.h"

#include <gtest/gtest.h>

#include "simbody_sampling.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "swing/knee_setup.h"

namespace swingsim {
namespace {

using namespace SimTK;

constexpr double kHipHeight = 1.0;  // m; irrelevant to the dynamics

Participant load(const std::string& stem) {
  return loadParticipant(std::string(SWINGSIM_SOURCE_DIR) + "/participants/" + stem + ".yaml");
}

HipMomentProfile makeZeroHipMoment() {
  HipMomentProfile profile;
  profile.flexionAmplitude = 0;
  profile.extensionAmplitude = 0;
  return profile;
}

HipRange makeWideHipRange() {
  HipRange range;
  range.minFlexion = -100;  // rad: the stop never engages
  range.maxFlexion = 100;
  return range;
}

using swingsim::testing::integrateAndObserve;

// Mean period from the downward zero crossings of a sampled oscillation (linear
// interpolation between samples: near a crossing a sinusoid has no curvature, so the
// crossing-time error is O((omega dt)^2 dt) ~ 1e-9 s for dt = 1 ms, omega < 10 rad/s).
double calcMeanPeriod(const std::vector<double>& time, const std::vector<double>& angle) {
  std::vector<double> crossings;
  for (std::size_t i = 1; i < angle.size(); ++i) {
    if (angle[i - 1] > 0 && angle[i] <= 0) {
      crossings.push_back(time[i - 1] + (time[i] - time[i - 1]) * angle[i - 1] / (angle[i - 1] - angle[i]));
    }
  }
  if (crossings.size() < 2) return NaN;
  return (crossings.back() - crossings.front()) / (crossings.size() - 1);
}

constexpr double kPeriodAccuracy = 1e-12;  // Simbody accuracy for the period tests
constexpr double kSampleInterval = 1e-3;   // s
// Relative period error allowed: finite amplitude (amplitude^2 / 16 = 6e-8 at 1e-3 rad),
// crossing interpolation (~1e-9 s over a ~1 s period) and the integrator.
constexpr double kPeriodRelTol = 2e-7;

TEST(LegModel, CompoundPendulumSmallAnglePeriod) {
  // One rigid segment on a hip pin, built with LegModel's conventions (x forward, y up,
  // COM at -a on the body's y axis, Izz about the COM shifted to the pin): Burkett P1's
  // thigh. The small-angle period is 2 pi sqrt(I_hip / (m g a)), I_hip = Izz + m a^2.
  const double mass = 3.350, comDistance = 0.410 - 0.284, inertia = 0.0264;
  MultibodySystem system;
  SimbodyMatterSubsystem matter(system);
  GeneralForceSubsystem forces(system);
  Force::UniformGravity(forces, matter, Vec3(0, -kGravity, 0));
  const Vec3 com(0, -comDistance, 0);
  MobilizedBody::Pin thigh(matter.Ground(), Transform(Vec3(0, kHipHeight, 0)),
                           Body::Rigid(MassProperties(mass, com, Inertia(inertia).shiftFromMassCenter(com, mass))),
                           Transform());
  system.realizeTopology();
  State state = system.getDefaultState();
  constexpr double kAmplitude = 1e-3;  // rad
  thigh.setOneQ(state, 0, kAmplitude);

  std::vector<double> time, angle;
  integrateAndObserve(system, state, kPeriodAccuracy, kSampleInterval, 5.0, [&](const State& s) {
    time.push_back(s.getTime());
    angle.push_back(thigh.getOneQ(s, 0));
  });
  const double expected =
      2 * Pi * std::sqrt((inertia + mass * comDistance * comDistance) / (mass * kGravity * comDistance));
  const double period = calcMeanPeriod(time, angle);
  EXPECT_NEAR(period / expected - 1, 0, kPeriodRelTol) << "period " << period << " s, formula " << expected << " s";
  std::printf("Simbody compound pendulum: period %.9f s, formula %.9f s, relative error %.1e\n", period, expected,
              period / expected - 1);
}

TEST(LegModel, SmallOscillationNormalModesOfTheFreeLeg) {
  // The whole LegModel (thigh + shank + welded foot), knee and hip free: about the hanging
  // equilibrium it is a linear double compound pendulum, M q'' + K q = 0 in (hip angle phi,
  // absolute angle beta of the shank+foot COM line), with (Lagrange, linearized)
  //   M = [[I1 + m1 a1^2 + m2 L1^2, m2 L1 r2], [m2 L1 r2, J2]],  K = g diag(m1 a1 + m2 L1, m2 r2).
  // Started exactly on one mode shape, the hip oscillates at that mode's frequency alone.
  const Participant p = load("p1");
  const LegGeometry g = calcLegGeometry(p, 0.0);
  const double m2 = g.shankMass + g.footMass;
  const double comX = g.footMass * g.footComForward;                          // m2 r2 sin gamma
  const double comY = g.shankMass * g.shankCom + g.footMass * g.shankLength;  // m2 r2 cos gamma
  const double r2 = std::hypot(comX, comY) / m2, gamma = std::atan2(comX, comY);
  const double m11 = g.thighInertia + g.thighMass * g.thighCom * g.thighCom + m2 * g.thighLength * g.thighLength;
  const double m12 = m2 * g.thighLength * r2;
  const double m22 = g.shankInertia + g.shankMass * g.shankCom * g.shankCom + g.footInertia +
                     g.footMass * (g.footComForward * g.footComForward + g.shankLength * g.shankLength);
  const double k1 = kGravity * (g.thighMass * g.thighCom + m2 * g.thighLength), k2 = kGravity * m2 * r2;
  // det(K - lambda M) = 0.
  const double a = m11 * m22 - m12 * m12, b = -(k1 * m22 + k2 * m11), c = k1 * k2;
  const double root = std::sqrt(b * b - 4 * a * c);
  const KneeLawSum noKneeLaw;
  for (double lambda : {(-b - root) / (2 * a), (-b + root) / (2 * a)}) {
    LegModel leg(g, noKneeLaw, makeZeroHipMoment(), makeWideHipRange(), kHipHeight);
    // Mode shape from the first row of (K - lambda M) v = 0.
    const double v1 = lambda * m12, v2 = k1 - lambda * m11;
    // rad, of the larger component. The nonlinear correction to a double pendulum's mode
    // period is O(amplitude^2) like the simple pendulum's amplitude^2/16, but with a larger
    // coefficient (2.3e-6 measured at 1e-3 rad): 1e-4 rad keeps it near 2e-8.
    constexpr double kAmplitude = 1e-4;
    const double scale = kAmplitude / std::max(std::abs(v1), std::abs(v2));
    InitialConditions initial;
    initial.hipFlexion = scale * v1;
    initial.kneeFlexion = scale * v1 - scale * v2 + gamma;  // theta = phi - beta + gamma
    std::vector<double> time, hip;
    integrateAndObserve(leg.getSystem(), leg.makeInitialState(initial), kPeriodAccuracy, kSampleInterval, 3.0,
                        [&](const State& s) {
                          time.push_back(s.getTime());
                          hip.push_back(leg.getHipFlexion(s));
                        });
    const double expected = 2 * Pi / std::sqrt(lambda);
    const double period = calcMeanPeriod(time, hip);
    EXPECT_NEAR(period / expected - 1, 0, kPeriodRelTol) << "mode period " << period << " s, formula " << expected;
    std::printf("LegModel normal mode: period %.9f s, formula %.9f s, relative error %.1e\n", period, expected,
                period / expected - 1);
  }
}

// Energy bookkeeping. Simbody's RK-Merson keeps each step's local error below `accuracy`
// relative to the states (angles and rates of order 1..10), and the energy is smooth in
// the state with dE/dy of the order of the leg's energy scale m g L ~ 10 J, so an energy
// error of accuracy x 10 J is one step's worth; 10x that allows the accumulation over the
// few hundred steps of a swing (local errors of a smooth problem do not add up coherently
// in the energy). Measured drift: ~0.3 x accuracy x 10 J.
constexpr double kEnergyAccuracy = 1e-9;
constexpr double kEnergyScale = 10;  // J
constexpr double kEnergyTol = 10 * kEnergyAccuracy * kEnergyScale;

TEST(LegModel, EnergyConservedWithKneeLawsAndHipMomentOff) {
  const Participant p = load("p2");
  const KneeLawSum noKneeLaw;
  LegModel leg(calcLegGeometry(p, 0.05), noKneeLaw, makeZeroHipMoment(), makeWideHipRange(), kHipHeight);
  InitialConditions initial;
  initial.hipFlexion = -0.4;
  initial.kneeFlexion = 0.8;
  initial.hipFlexionRate = 2.0;
  double e0 = NaN, maxDrift = 0, kneeMin = 1e9, kneeMax = -1e9;
  integrateAndObserve(leg.getSystem(), leg.makeInitialState(initial), kEnergyAccuracy, 0.005, 2.0, [&](const State& s) {
    const double e = leg.calcMechanicalEnergy(s);
    if (std::isnan(e0)) e0 = e;
    maxDrift = std::max(maxDrift, std::abs(e - e0));
    kneeMin = std::min(kneeMin, leg.getKneeFlexion(s));
    kneeMax = std::max(kneeMax, leg.getKneeFlexion(s));
  });
  EXPECT_LT(maxDrift, kEnergyTol);
  EXPECT_EQ(leg.getKneeWork(leg.makeInitialState(initial)), 0.0);
  EXPECT_GT(kneeMax - kneeMin, 0.5) << "the knee must swing through a real range";
  std::printf("free leg energy drift over 2 s: %.2e J (tolerance %.1e J)\n", maxDrift, kEnergyTol);
}

TEST(LegModel, EnergyBookkeepingWithDampingFrictionStopsAndHipDrive) {
  // KE + PE - (work of the knee moment) - (work of the hip moment) is constant when every
  // law is on: damping table, friction below 4 deg, the hyperextension stop, the hip
  // moment profile and the hip range stop (narrowed so that it engages).
  const Participant p = load("p1");
  const KneeLawSum law = makeKneeLaw(p, loadKneeModel(p.kneeModelPath));
  HipRange narrow;
  narrow.minFlexion = -20 * kDegToRad;
  narrow.maxFlexion = 22 * kDegToRad;
  LegModel leg(calcLegGeometry(p, 0.0), law, p.hipMoment, narrow, kHipHeight);
  double b0 = NaN, maxDrift = 0, kneeMin = 1e9, hipMax = -1e9, kneeWork = 0, hipWork = 0;
  integrateAndObserve(leg.getSystem(), leg.makeInitialState(p.initial), kEnergyAccuracy, 0.002, 1.2,
                      [&](const State& s) {
                        kneeWork = leg.getKneeWork(s);
                        hipWork = leg.getHipWork(s);
                        const double balance = leg.calcMechanicalEnergy(s) - kneeWork - hipWork;
                        if (std::isnan(b0)) b0 = balance;
                        maxDrift = std::max(maxDrift, std::abs(balance - b0));
                        kneeMin = std::min(kneeMin, leg.getKneeFlexion(s));
                        hipMax = std::max(hipMax, leg.getHipFlexion(s));
                      });
  EXPECT_LT(maxDrift, kEnergyTol);
  // Every law did something, so leaving a work term out would break the balance.
  EXPECT_LT(kneeMin, 0.0) << "the knee must reach its hyperextension stop";
  EXPECT_GT(hipMax, narrow.maxFlexion) << "the thigh must reach its range stop";
  EXPECT_LT(kneeWork, -1e6 * kEnergyTol) << "the knee must dissipate";
  EXPECT_GT(std::abs(hipWork), 1e6 * kEnergyTol);
  std::printf("bookkeeping drift over 1.2 s: %.2e J (knee work %.3f J, hip work %.3f J, tolerance %.1e J)\n", maxDrift,
              kneeWork, hipWork, kEnergyTol);
}

TEST(LegModel, MovingHipPendulumSwingsAsUnderGravityPlusTheHipsAcceleration) {
  // The hip carrier's Translation mobilizer: the thigh held still, the hip rising at a = 1 g
  // (y = a t^2 / 2, reproduced exactly by the quintic smoothing spline), the free knee
  // swings the shank+foot as a compound pendulum under g + a: period
  // 2 pi sqrt(J / (m r (g + a))). The pose's hip must follow the path.
  LegGeometry g = calcLegGeometry(load("p1"), 0.0);
  g.footComForward = 0;  // composite COM on the shank axis: equilibrium at knee = 0
  const double m2r2 = g.shankMass * g.shankCom + g.footMass * g.shankLength;
  const double j2 = g.shankInertia + g.shankMass * g.shankCom * g.shankCom + g.footInertia +
                    g.footMass * g.shankLength * g.shankLength;
  constexpr double kRise = kGravity;  // m/s^2
  constexpr double kDuration = 5.0;   // s
  ThighKinematics k;
  for (int i = 0; i <= 100; ++i) {
    const double t = kDuration * i / 100.0;
    k.time.push_back(t);
    k.hipFlexion.push_back(0.0);
    k.pelvisX.push_back(0.1 * t);  // a steady walk forward: no force, but the pose must show it
    k.pelvisY.push_back(0.5 * kRise * t * t);
    k.pelvisTilt.push_back(0.0);
  }
  const ThighMotion thigh(k);
  const HipPath hip(k, std::array<double, 2>{0.0, 0.0});
  const KneeLawSum noKnee;
  LegModel leg(g, noKnee, makeZeroHipMoment(), makeWideHipRange(), kHipHeight, false, &thigh, &hip);
  ASSERT_TRUE(leg.hasMovingHip());
  EXPECT_EQ(leg.getKneeCoordinateIndex(), 4);
  InitialConditions initial;
  constexpr double kAmplitude = 1e-3;  // rad
  initial.kneeFlexion = kAmplitude;
  const State state = leg.makeInitialState(initial);
  std::vector<double> time, knee;
  double hipPoseError = 0;
  integrateAndObserve(leg.getSystem(), state, kPeriodAccuracy, kSampleInterval, kDuration, [&](const State& s) {
    time.push_back(s.getTime());
    knee.push_back(leg.getKneeFlexion(s));
    const LegPose pose = leg.calcPose(s);
    const double t = s.getTime();
    hipPoseError = std::max(
        {hipPoseError, std::abs(pose.hip[0] - 0.1 * t), std::abs(pose.hip[1] - (kHipHeight + 0.5 * kRise * t * t))});
  });
  const double expected = 2 * Pi * std::sqrt(j2 / (m2r2 * (kGravity + kRise)));
  const double period = calcMeanPeriod(time, knee);
  std::printf("Simbody moving hip, support rising at 1 g: knee period %.9f s, formula (g + a) %.9f s\n", period,
              expected);
  EXPECT_NEAR(period / expected - 1, 0, kPeriodRelTol);
  // m: the spline reproduces a line and a parabola to rounding (values up to 120 m at 5 s).
  constexpr double kPoseTol = 1e-9;
  EXPECT_LT(hipPoseError, kPoseTol);
}

TEST(LegModel, FixedHipHasNoCarrier) {
  const Participant p = load("p1");
  const KneeLawSum noKnee;
  LegModel leg(calcLegGeometry(p, 0.0), noKnee, makeZeroHipMoment(), makeWideHipRange(), kHipHeight);
  EXPECT_FALSE(leg.hasMovingHip());
  EXPECT_EQ(leg.getKneeCoordinateIndex(), 1);
  EXPECT_EQ(leg.makeInitialState(InitialConditions{}).getNQ(), 2);
}

}  // namespace
}  // namespace swingsim
