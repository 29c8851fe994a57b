#include "swing/reference_swing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "core/units.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "knee/knee_expression.h"
#include "leg/hip_path.h"
#include "leg/thigh_motion.h"
#include "swing/knee_setup.h"
#include "swing/swing_simulation.h"

namespace swingsim {
namespace {

// Both integrators run far tighter than the agreement asked for, so a disagreement
// means different equations, not integration error.
constexpr double kSimbodyAccuracy = 1e-10;  // Simbody RK-Merson relative accuracy
constexpr double kReferenceTol = 1e-11;     // Dormand-Prince local relative and absolute tolerance
// Simbody and the independent reference trajectories agree to 1e-6 rad (docs/verification.md).
constexpr double kAngleTol = 1e-6;  // rad
// Simbody localizes each event within its window; the reference to 1e-12 s. With a 1e-9 s
// window the swing ends may differ by the window plus the trajectory difference divided by
// the knee's rate through the zone boundary (> 1 rad/s): 1e-6 s is a safe bound.
constexpr double kEventWindow = 1e-9;   // s
constexpr double kSwingTimeTol = 1e-6;  // s

Participant load(const std::string& stem) {
  return loadParticipant(std::string(SWINGSIM_SOURCE_DIR) + "/participants/" + stem + ".yaml");
}

struct Comparison {
  double maxHipDiff = 0, maxKneeDiff = 0;
  double simbodySwingTime = 0, referenceSwingTime = 0;
  double simbodyPeakTime = 0, referencePeakTime = 0;
  double simbodyPeak = 0, referencePeak = 0;
  std::size_t samples = 0;
};

Comparison compare(const Participant& p, std::shared_ptr<const KneeLaw> shared, double lowering,
                   const LegGeometry* referenceGeometry = nullptr) {
  const SwingSetup setup = makeSwingSetup(p, shared, lowering);
  const KneeLaw& law = *shared;
  // Simbody's own integrator: the reference runs on our Dormand-Prince, so the two share
  // neither equations nor integration code.
  SwingOptions options = makeSimbodyIntegratorOptions(kSimbodyAccuracy);
  options.sampleInterval = 0.002;
  options.eventWindow = kEventWindow;
  const SwingResult sim = simulateSwing(setup, options);

  const LegGeometry geometry = referenceGeometry ? *referenceGeometry : calcLegGeometry(p, lowering);
  const ReferenceSwing reference(geometry, law, p.hipMoment, p.hipRange);
  const ReferenceTrajectory tr = reference.integrate(p.initial, sim.trajectory.time, kReferenceTol, kReferenceTol);
  Comparison c;
  c.samples = tr.size();
  for (std::size_t i = 0; i < tr.size(); ++i) {
    c.maxHipDiff = std::max(c.maxHipDiff, std::abs(tr.hipFlexion[i] - sim.trajectory.hipFlexion[i]));
    c.maxKneeDiff = std::max(c.maxKneeDiff, std::abs(tr.kneeFlexion[i] - sim.trajectory.kneeFlexion[i]));
  }
  const ReferenceSwingEnd end = reference.calcSwingEnd(p.initial, p.swingEnd, kReferenceTol, kReferenceTol);
  c.simbodySwingTime = sim.swingTime;
  c.referenceSwingTime = end.swingTime;
  EXPECT_TRUE(sim.peakKneeFlexion);  // every ended swing has its peak
  c.simbodyPeakTime = sim.peakKneeFlexion.value_or(KneePeak{}).time;
  c.referencePeakTime = end.peakKneeFlexionTime;
  c.simbodyPeak = sim.peakKneeFlexion.value_or(KneePeak{}).flexion;
  c.referencePeak = end.peakKneeFlexion;
  return c;
}

class ReferenceVsSimbody : public ::testing::TestWithParam<std::tuple<const char*, double>> {};

TEST_P(ReferenceVsSimbody, TrajectoryAndSwingTimeAgree) {
  const auto [stem, lowering] = GetParam();
  const Participant p = load(stem);
  const auto law = std::make_shared<const KneeLawSum>(makeKneeLaw(p, loadKneeModel(p.kneeModelPath)));
  const Comparison c = compare(p, law, lowering);
  ASSERT_GT(c.samples, 100u) << "the swing should be sampled every 2 ms for a few hundred ms";
  EXPECT_LT(c.maxHipDiff, kAngleTol);
  EXPECT_LT(c.maxKneeDiff, kAngleTol);
  EXPECT_NEAR(c.referenceSwingTime, c.simbodySwingTime, kSwingTimeTol);
  EXPECT_NEAR(c.referencePeakTime, c.simbodyPeakTime, kSwingTimeTol);
  EXPECT_NEAR(c.referencePeak, c.simbodyPeak, kAngleTol);
  RecordProperty("max_hip_diff_rad", std::to_string(c.maxHipDiff));
  RecordProperty("max_knee_diff_rad", std::to_string(c.maxKneeDiff));
  std::printf(
      "%s lowering %.2f m: max |hip diff| %.2e rad, max |knee diff| %.2e rad over %zu samples; "
      "swing time Simbody %.9f s, reference %.9f s (diff %.1e s)\n",
      stem, lowering, c.maxHipDiff, c.maxKneeDiff, c.samples, c.simbodySwingTime, c.referenceSwingTime,
      c.referenceSwingTime - c.simbodySwingTime);
}

INSTANTIATE_TEST_SUITE_P(Participants, ReferenceVsSimbody,
                         ::testing::Combine(::testing::Values("p1", "p2", "p3", "p4"), ::testing::Values(0.0, 0.1)),
                         // Readable names (p1_lowered_100mm), not the char pointer's address.
                         [](const ::testing::TestParamInfo<ReferenceVsSimbody::ParamType>& info) {
                           const long mm = std::lround(std::get<1>(info.param) * 1000);
                           return std::string(std::get<0>(info.param)) + "_lowered_" + std::to_string(mm) + "mm";
                         });

TEST(ReferenceSwing, ASocketLegMatchesSimbodyWithP1sKnee) {
  // A loose socket (docs/socket.md; rotation 100 N m/rad and 10 N m s/rad, piston 5000 N/m
  // and 200 N s/m): Simbody's Slider and Pin against the reference's own four-coordinate
  // equations (swing/reference_socket_chain.h), through the whole swing and its end.
  Participant p = load("p1");
  p.socket = SocketCompliance{};
  p.socket->rotationStiffness = 100;
  p.socket->rotationDamping = 10;
  p.socket->pistonStiffness = 5000;
  p.socket->pistonDamping = 200;
  const auto law = std::make_shared<const KneeLawSum>(makeKneeLaw(p, loadKneeModel(p.kneeModelPath)));
  const Comparison c = compare(p, law, 0.03);
  ASSERT_GT(c.samples, 100u);
  std::printf(
      "P1 with a loose socket: max |hip diff| %.2e rad, max |knee diff| %.2e rad; swing time Simbody %.9f s, "
      "reference %.9f s\n",
      c.maxHipDiff, c.maxKneeDiff, c.simbodySwingTime, c.referenceSwingTime);
  EXPECT_LT(c.maxHipDiff, kAngleTol);
  EXPECT_LT(c.maxKneeDiff, kAngleTol);
  EXPECT_NEAR(c.referenceSwingTime, c.simbodySwingTime, kSwingTimeTol);
  EXPECT_NEAR(c.referencePeak, c.simbodyPeak, kAngleTol);
  // The socket changes the swing by far more than the agreement.
  const Comparison rigid = compare(load("p1"), law, 0.03);
  EXPECT_GT(std::abs(rigid.simbodySwingTime - c.simbodySwingTime), 100 * kSwingTimeTol);
}

TEST(ReferenceSwing, DisagreesWhenTheLegDiffers) {
  // The comparison can fail: 1 % more shank mass in the reference moves the knee by far
  // more than the tolerance.
  const Participant p = load("p1");
  const auto law = std::make_shared<const KneeLawSum>(makeKneeLaw(p, loadKneeModel(p.kneeModelPath)));
  LegGeometry heavier = calcLegGeometry(p, 0.0);
  heavier.shankMass *= 1.01;
  const Comparison c = compare(p, law, 0.0, &heavier);
  EXPECT_GT(c.maxKneeDiff, 100 * kAngleTol);
  std::printf("reference with 1 %% heavier shank: max |knee diff| %.2e rad\n", c.maxKneeDiff);
}

// A knee law with its own state (like the Mauch S2 latch): a lagged viscous damper,
// z' = (knee rate - z) / tau, moment -c z. Its state must be integrated by both sides.
class LaggedDamper final : public KneeLaw {
 public:
  std::string name() const override { return "lagged damper"; }
  int numStates() const override { return 1; }
  void initialStates(double* z) const override { z[0] = 0; }
  double calcMoment(const KneeKinematics&, const double* z) const override { return -kDamping * z[0]; }
  void calcStateDerivatives(const KneeKinematics& knee, const double* z, double* zdot) const override {
    zdot[0] = (knee.flexionRate - z[0]) / kLag;
  }
  std::unique_ptr<KneeLaw> clone() const override { return std::make_unique<LaggedDamper>(*this); }

 private:
  static constexpr double kDamping = 0.3;  // N m s/rad
  static constexpr double kLag = 0.02;     // s
};

TEST(ReferenceSwing, IntegratesKneeLawStatesLikeSimbody) {
  const Participant p = load("p2");
  KneeLawSum law = makeKneeLaw(p, loadKneeModel(p.kneeModelPath));
  law.add(std::make_unique<LaggedDamper>());
  const Comparison c = compare(p, std::make_shared<const KneeLawSum>(std::move(law)), 0.05);
  EXPECT_LT(c.maxHipDiff, kAngleTol);
  EXPECT_LT(c.maxKneeDiff, kAngleTol);
  EXPECT_NEAR(c.referenceSwingTime, c.simbodySwingTime, kSwingTimeTol);
}

// A user's expression (knee/knee_expression.h) that reads the hip's angle and rate and the
// time: both integrators must hand the law the same hip state and time since toe-off.
TEST(ReferenceSwing, PassesTheHipAndTheTimeToAUsersExpressionLikeSimbody) {
  const Participant p = load("p1");
  KneeLawSum law = makeKneeLaw(p, loadKneeModel(p.kneeModelPath));
  law.add(std::make_unique<KneeExpressionMoment>(
      KneeExpressionParams{"hip and time",
                           "-a * hip_rad * knee_rate_rad_s - b * time_s * sin(hip_rate_rad_s)",
                           {{"a", "", 0.3}, {"b", "", 0.5}}}));
  const Comparison c = compare(p, std::make_shared<const KneeLawSum>(std::move(law)), 0.0);
  EXPECT_LT(c.maxHipDiff, kAngleTol);
  EXPECT_LT(c.maxKneeDiff, kAngleTol);
  EXPECT_NEAR(c.referenceSwingTime, c.simbodySwingTime, kSwingTimeTol);
  // ...and the term acts: without it the swing is another.
  const auto plain = std::make_shared<const KneeLawSum>(makeKneeLaw(p, loadKneeModel(p.kneeModelPath)));
  const Comparison without = compare(p, plain, 0.0);
  EXPECT_GT(std::abs(without.simbodySwingTime - c.simbodySwingTime), 1e-3);
}

TEST(ReferenceSwing, ConservesEnergyWithKneeLawsAndHipMomentOff) {
  // Free double pendulum: the energy error is the integrator's. One step's local error
  // (<= tol relative to states of order 1..10) moves the energy by about tol x the leg's
  // energy scale (m g L ~ 10 J); 10x that allows the accumulation over ~200 steps.
  constexpr double kTol = 1e-10;
  const Participant p = load("p3");
  HipMomentProfile noHipMoment;
  noHipMoment.flexionAmplitude = 0;
  noHipMoment.extensionAmplitude = 0;
  HipRange wide;
  wide.minFlexion = -100;
  wide.maxFlexion = 100;
  const ReferenceSwing reference(calcLegGeometry(p, 0.0), KneeLawSum(), noHipMoment, wide);
  InitialConditions initial;
  initial.hipFlexion = -0.4;
  initial.kneeFlexion = 0.8;
  initial.hipFlexionRate = 2.0;
  std::vector<double> times;
  for (int i = 0; i <= 200; ++i) times.push_back(0.01 * i);
  const ReferenceTrajectory tr = reference.integrate(initial, times, kTol, kTol);
  const double e0 =
      reference.calcMechanicalEnergy(tr.hipFlexion[0], tr.kneeFlexion[0], tr.hipFlexionRate[0], tr.kneeFlexionRate[0]);
  constexpr double kEnergyScale = 10;  // J: m g L of the leg
  const double energyTol = 10 * kTol * kEnergyScale;
  double maxDrift = 0, kneeRange = 0;
  for (std::size_t i = 0; i < tr.size(); ++i) {
    const double e = reference.calcMechanicalEnergy(tr.hipFlexion[i], tr.kneeFlexion[i], tr.hipFlexionRate[i],
                                                    tr.kneeFlexionRate[i]);
    maxDrift = std::max(maxDrift, std::abs(e - e0));
    kneeRange = std::max(kneeRange, std::abs(tr.kneeFlexion[i] - initial.kneeFlexion));
  }
  EXPECT_LT(maxDrift, energyTol);
  std::printf("reference free-leg energy drift over 2 s: %.2e J (tolerance %.1e J)\n", maxDrift, energyTol);
  EXPECT_GT(kneeRange, 0.3) << "the knee must actually swing for this to test anything";
}

TEST(ReferenceSwing, SwingEndTimeOutThrows) {
  // A hip moment far too small never brings the thigh to its target.
  Participant p = load("p1");
  p.hipMoment.flexionAmplitude = 0;
  p.hipMoment.extensionAmplitude = 0;
  p.swingEnd.timeLimit = 0.3;
  const auto law = std::make_shared<const KneeLawSum>(makeKneeLaw(p, loadKneeModel(p.kneeModelPath)));
  const ReferenceSwing reference(calcLegGeometry(p, 0.0), *law, p.hipMoment, p.hipRange);
  EXPECT_THROW(reference.calcSwingTime(p.initial, p.swingEnd, 1e-8), RunError);
}

TEST(ReferenceSwing, RejectsDecreasingSampleTimes) {
  const Participant p = load("p1");
  const ReferenceSwing reference(calcLegGeometry(p, 0.0), KneeLawSum(), p.hipMoment, p.hipRange);
  EXPECT_THROW(reference.integrate(p.initial, {0.0, 0.2, 0.1}, 1e-8, 1e-8), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------
// The moving hip (docs/moving-hip.md): a prescribed support acceleration.

// Mean period from the downward zero crossings of a sampled oscillation (linear
// interpolation between samples; see tests/leg/leg_model_test.cpp).
double calcMeanPeriod(const std::vector<double>& time, const std::vector<double>& angle) {
  std::vector<double> crossings;
  for (std::size_t i = 1; i < angle.size(); ++i)
    if (angle[i - 1] > 0 && angle[i] <= 0)
      crossings.push_back(time[i - 1] + (time[i] - time[i - 1]) * angle[i - 1] / (angle[i - 1] - angle[i]));
  if (crossings.size() < 2) return std::nan("");
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

TEST(ReferenceSwing, PendulumOnARisingSupportSwingsAsUnderGravityPlusItsAcceleration) {
  // The thigh held still and the hip rising with constant acceleration a: the shank+foot is
  // a compound pendulum hanging from a support accelerating upward, which in the support's
  // frame feels gravity g + a: small-oscillation period 2 pi sqrt(J / (m r (g + a))), J its
  // inertia about the knee, m r its mass moment. The hip path y = a t^2 / 2 is a quadratic,
  // which the quintic smoothing spline reproduces exactly (zero residual, zero penalty).
  LegGeometry g = calcLegGeometry(load("p1"), 0.0);
  g.footComForward = 0;  // the composite COM on the shank axis: equilibrium at knee = 0
  const double m2r2 = g.shankMass * g.shankCom + g.footMass * g.shankLength;
  const double j2 = g.shankInertia + g.shankMass * g.shankCom * g.shankCom + g.footInertia +
                    g.footMass * g.shankLength * g.shankLength;
  constexpr double kRise = kGravity;  // m/s^2, 1 g: the period shrinks by sqrt(2)
  constexpr double kDuration = 5.0;   // s, several periods (~1 s each)
  ThighKinematics k;
  for (int i = 0; i <= 100; ++i) {
    const double t = kDuration * i / 100.0;
    k.time.push_back(t);
    k.hipFlexion.push_back(0.0);
    k.pelvisX.push_back(0.0);
    k.pelvisY.push_back(0.5 * kRise * t * t);
    k.pelvisTilt.push_back(0.0);
  }
  const ThighMotion thigh(k);
  const HipPath hip(k, std::array<double, 2>{0.0, 0.0});
  const ReferenceSwing reference(g, KneeLawSum(), thigh, hip);
  InitialConditions initial;
  constexpr double kAmplitude = 1e-3;  // rad: small oscillation
  initial.kneeFlexion = kAmplitude;
  std::vector<double> times;
  for (int i = 0; i <= 5000; ++i) times.push_back(1e-3 * i);
  const ReferenceTrajectory tr = reference.integrate(initial, times, 1e-12, 1e-12);
  const double period = calcMeanPeriod(tr.time, tr.kneeFlexion);
  const double expected = 2 * 3.141592653589793 * std::sqrt(j2 / (m2r2 * (kGravity + kRise)));
  const double fixedHip = 2 * 3.141592653589793 * std::sqrt(j2 / (m2r2 * kGravity));
  std::printf("pendulum on a support rising at 1 g: period %.9f s, formula (g + a) %.9f s, fixed support %.6f s\n",
              period, expected, fixedHip);
  // Relative error: finite amplitude (amplitude^2 / 16 = 6e-8), crossing interpolation
  // (~1e-9 s over ~0.7 s) and the integrator; the fixed-support period is 41 % longer.
  constexpr double kPeriodRelTol = 2e-7;
  EXPECT_NEAR(period / expected - 1, 0, kPeriodRelTol);
}

constexpr double kMovingHipKneeTol = 0.01 * kDegToRad;  // rad: the brief's agreement, 1/50 of a marker's resolution

// Simbody's swing (simulateSwing, the participant's moving hip) against the reference given
// the same thigh spline and hip path: the largest knee difference, rad.
double compareMovingHip(const Participant& p, const std::shared_ptr<const KneeLaw>& shared, SwingResult& sim) {
  const KneeLaw& law = *shared;
  const SwingSetup setup = makeSwingSetup(p, shared);
  SwingOptions options = makeSimbodyIntegratorOptions(kSimbodyAccuracy);
  options.sampleInterval = 0.002;
  options.requireSwingEnd = false;  // the knee's whole course, ended or not
  sim = simulateSwing(setup, options);
  const ThighMotion thigh(p.thighKinematics);
  const HipPath hip(p.thighKinematics, p.hipOffsetInPelvis);
  const ReferenceSwing reference(calcLegGeometry(p, 0.0), law, thigh, hip);
  // Sample times short of the measurement's end: SimTK's spline (ThighMotion's) refuses a
  // time past its last sample, where an integrator stage aimed at the end can land by rounding.
  std::vector<double> times;
  for (double t : sim.trajectory.time)
    if (t < thigh.getEndTime() - 1e-6) times.push_back(t);
  const ReferenceTrajectory ref = reference.integrate(p.initial, times, kReferenceTol, kReferenceTol);
  double kneeDiff = 0;
  for (std::size_t i = 0; i < ref.size(); ++i)
    kneeDiff = std::max(kneeDiff, std::abs(ref.kneeFlexion[i] - sim.trajectory.kneeFlexion[i]));
  return kneeDiff;
}

TEST(ReferenceSwing, MovingHipMatchesSimbodyOnARunningLikePelvis) {
  // A smooth synthetic run: forward at 3.5 m/s, the pelvis bobbing 3 cm at 18 rad/s (about a
  // runner's step rate), a vertical acceleration of 0.03 x 18^2 = 9.7 m/s^2 ~ 1 g, tilting
  // 0.1 rad; the thigh flexing from -10 to 30 deg over 0.5 s.
  Participant p = load("p1");
  p.drive = SwingDrive::kThighKinematics;
  p.hipOffsetInPelvis = std::array<double, 2>{-0.07, -0.07};
  ThighKinematics& k = p.thighKinematics;
  for (int i = 0; i <= 50; ++i) {
    const double t = 0.01 * i;
    k.time.push_back(t);
    k.hipFlexion.push_back((-10 + 40 * 0.5 * (1 - std::cos(3.141592653589793 * t / 0.5))) * kDegToRad);
    k.pelvisX.push_back(3.5 * t);
    k.pelvisY.push_back(1.0 + 0.03 * std::sin(18 * t));
    k.pelvisTilt.push_back(0.1 * std::sin(18 * t));
  }
  p.initial.kneeFlexion = 40 * kDegToRad;
  p.initial.kneeFlexionRate = 3.0;
  const auto law = std::make_shared<const KneeLawSum>(makeKneeLaw(p, loadKneeModel(p.kneeModelPath)));
  SwingResult sim;
  const double kneeDiff = compareMovingHip(p, law, sim);
  std::printf("running-like pelvis: max |knee diff| Simbody vs reference %.2e deg over %zu samples\n",
              kneeDiff * kRadToDeg, sim.trajectory.size());
  ASSERT_GT(sim.trajectory.size(), 100u);
  EXPECT_LT(kneeDiff, kMovingHipKneeTol);
}

// The right swing of OpenSim's subject01 walk (Gait2392 IK, studies/data/opensim-subject01):
// toe-off ~1.41 s to heel strike ~1.85 s, read here with its own few lines.
struct IkSwing {
  ThighKinematics kinematics;
  std::vector<double> kneeFlexion;  // rad, measured (knee_angle_r with sign -1)
};
IkSwing readSubject01RightSwing() {
  std::ifstream in(std::string(SWINGSIM_SOURCE_DIR) +
                   "/studies/data/opensim-subject01/gait2392_subject01_walk1_ik.mot");
  std::string line;
  while (std::getline(in, line) && line.rfind("endheader", 0) != 0) {
  }
  std::getline(in, line);
  std::map<std::string, std::size_t> column;
  {
    std::stringstream header(line);
    std::string name;
    for (std::size_t i = 0; header >> name; ++i) column[name] = i;
  }
  IkSwing swing;
  ThighKinematics& k = swing.kinematics;
  k.path = "gait2392_subject01_walk1_ik.mot";
  constexpr double kToeOff = 1.41, kHeelStrike = 1.85;  // s
  double start = 0;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::vector<double> v;
    double x;
    while (row >> x) v.push_back(x);
    const double t = v.at(column.at("time"));
    if (t < kToeOff - 1e-9 || t > kHeelStrike + 1e-9) continue;
    const double tilt = v.at(column.at("pelvis_tilt")) * kDegToRad;
    if (k.time.empty()) start = t;  // the first frame in the window is toe-off, t = 0
    k.time.push_back(t - start);
    k.hipFlexion.push_back(v.at(column.at("hip_flexion_r")) * kDegToRad + tilt);  // the thigh in space
    k.pelvisX.push_back(v.at(column.at("pelvis_tx")));
    k.pelvisY.push_back(v.at(column.at("pelvis_ty")));
    k.pelvisTilt.push_back(tilt);
    swing.kneeFlexion.push_back(-v.at(column.at("knee_angle_r")) * kDegToRad);
  }
  return swing;
}

double rmse(const std::vector<double>& a, const std::vector<double>& b, std::size_t n) {
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(sum / static_cast<double>(n));
}

TEST(ReferenceSwing, MovingHipMatchesSimbodyOnSubject01sMeasuredPelvis) {
  // P1's prosthesis swung by subject01's measured thigh and pelvis; the hip centre in the
  // pelvis frame from the scaled Gait2354 model (hip_r's pelvis_offset, x and y).
  const IkSwing ik = readSubject01RightSwing();
  ASSERT_GT(ik.kinematics.time.size(), 20u);
  Participant p = load("p1");
  p.drive = SwingDrive::kThighKinematics;
  p.thighKinematics = ik.kinematics;
  p.hipOffsetInPelvis = std::array<double, 2>{-0.0724376, -0.0677245};
  const double dt = ik.kinematics.time[1] - ik.kinematics.time[0];
  p.initial.kneeFlexion = ik.kneeFlexion[0];
  p.initial.kneeFlexionRate = (ik.kneeFlexion[1] - ik.kneeFlexion[0]) / dt;
  const auto law = std::make_shared<const KneeLawSum>(makeKneeLaw(p, loadKneeModel(p.kneeModelPath)));
  SwingResult moving;
  const double kneeDiff = compareMovingHip(p, law, moving);
  ASSERT_GT(moving.trajectory.size(), 100u);
  EXPECT_LT(kneeDiff, kMovingHipKneeTol);

  // What the moving hip changes (docs/moving-hip.md): the same swing with the hip fixed, and
  // each against the measured knee at the measurement's own times.
  Participant fixedHip = p;
  fixedHip.thighKinematics.pelvisX.clear();
  fixedHip.thighKinematics.pelvisY.clear();
  fixedHip.thighKinematics.pelvisTilt.clear();
  const SwingSetup setup = makeSwingSetup(fixedHip, law);
  SwingOptions options = makeSimbodyIntegratorOptions(kSimbodyAccuracy);
  options.sampleInterval = 0.002;
  options.requireSwingEnd = false;
  const SwingResult fixed = simulateSwing(setup, options);
  const std::size_t n = std::min(fixed.trajectory.size(), moving.trajectory.size());
  const double between = rmse(fixed.trajectory.kneeFlexion, moving.trajectory.kneeFlexion, n);
  double maxBetween = 0;
  for (std::size_t i = 0; i < n; ++i)
    maxBetween = std::max(maxBetween, std::abs(fixed.trajectory.kneeFlexion[i] - moving.trajectory.kneeFlexion[i]));
  // The model knees at the measured samples (the trajectory is every 2 ms; the IK every 16.7 ms).
  const auto atSamples = [&](const SwingTrajectory& tr, std::vector<double>& model, std::vector<double>& measured) {
    for (std::size_t j = 0; j < ik.kinematics.time.size(); ++j) {
      const double t = ik.kinematics.time[j];
      if (t > tr.time.back()) break;
      std::size_t i = 1;
      while (i + 1 < tr.size() && tr.time[i] < t) ++i;
      const double w = (t - tr.time[i - 1]) / (tr.time[i] - tr.time[i - 1]);
      model.push_back(tr.kneeFlexion[i - 1] + w * (tr.kneeFlexion[i] - tr.kneeFlexion[i - 1]));
      measured.push_back(ik.kneeFlexion[j]);
    }
  };
  std::vector<double> fixedModel, fixedMeasured, movingModel, movingMeasured;
  atSamples(fixed.trajectory, fixedModel, fixedMeasured);
  atSamples(moving.trajectory, movingModel, movingMeasured);
  const double fixedVsMeasured = rmse(fixedModel, fixedMeasured, fixedModel.size());
  const double movingVsMeasured = rmse(movingModel, movingMeasured, movingModel.size());
  std::printf(
      "subject01 right swing on P1's knee: Simbody vs reference max |knee diff| %.2e deg; "
      "fixed vs moving hip knee RMSE %.3f deg (max %.3f deg) over %.3f s; vs measured knee: fixed %.2f deg, "
      "moving %.2f deg RMSE (%zu samples)\n",
      kneeDiff * kRadToDeg, between * kRadToDeg, maxBetween * kRadToDeg, moving.trajectory.time[n - 1],
      fixedVsMeasured * kRadToDeg, movingVsMeasured * kRadToDeg, movingModel.size());
  EXPECT_GT(maxBetween, kMovingHipKneeTol)
      << "walking's pelvis motion must show in the knee for this to measure anything";
}

}  // namespace
}  // namespace swingsim
