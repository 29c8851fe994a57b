#include "swing/reference_swing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/input_error.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "swing/knee_setup.h"
#include "swing/swing_simulation.h"

namespace swingsim {
namespace {

// Both integrators run far tighter than the agreement asked for, so a disagreement
// means different equations, not integration error.
constexpr double kSimbodyAccuracy = 1e-10;  // Simbody RK-Merson relative accuracy
constexpr double kReferenceTol = 1e-11;     // Dormand-Prince local relative and absolute tolerance
// Issue 2, Verification 4: the trajectories agree to 1e-6 rad.
constexpr double kAngleTol = 1e-6;  // rad
// Simbody localizes each event within its window; the reference to 1e-12 s. With a 1e-9 s
// window the swing ends may differ by the window plus the trajectory difference divided by
// the knee's rate through the zone boundary (> 1 rad/s): 1e-6 s is a safe bound.
constexpr double kEventWindow = 1e-9;  // s
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

Comparison compare(const Participant& p, const KneeLaw& law, double lowering, const LegGeometry* referenceGeometry = nullptr) {
  SwingSetup setup;
  setup.participant = p;
  setup.knee = &law;
  setup.lowering = lowering;
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
  c.simbodyPeakTime = sim.peakKneeFlexionTime;
  c.referencePeakTime = end.peakKneeFlexionTime;
  c.simbodyPeak = sim.peakKneeFlexion;
  c.referencePeak = end.peakKneeFlexion;
  return c;
}

class ReferenceVsSimbody : public ::testing::TestWithParam<std::tuple<const char*, double>> {};

TEST_P(ReferenceVsSimbody, TrajectoryAndSwingTimeAgree) {
  const auto [stem, lowering] = GetParam();
  const Participant p = load(stem);
  const KneeLawSum law = makeKneeLaw(p, loadKneeModel(p.kneeModelPath));
  const Comparison c = compare(p, law, lowering);
  ASSERT_GT(c.samples, 100u) << "the swing should be sampled every 2 ms for a few hundred ms";
  EXPECT_LT(c.maxHipDiff, kAngleTol);
  EXPECT_LT(c.maxKneeDiff, kAngleTol);
  EXPECT_NEAR(c.referenceSwingTime, c.simbodySwingTime, kSwingTimeTol);
  EXPECT_NEAR(c.referencePeakTime, c.simbodyPeakTime, kSwingTimeTol);
  EXPECT_NEAR(c.referencePeak, c.simbodyPeak, kAngleTol);
  RecordProperty("max_hip_diff_rad", std::to_string(c.maxHipDiff));
  RecordProperty("max_knee_diff_rad", std::to_string(c.maxKneeDiff));
  std::printf("%s lowering %.2f m: max |hip diff| %.2e rad, max |knee diff| %.2e rad over %zu samples; "
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

TEST(ReferenceSwing, DisagreesWhenTheLegDiffers) {
  // The comparison can fail: 1 % more shank mass in the reference moves the knee by far
  // more than the tolerance.
  const Participant p = load("p1");
  const KneeLawSum law = makeKneeLaw(p, loadKneeModel(p.kneeModelPath));
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
  const Comparison c = compare(p, law, 0.05);
  EXPECT_LT(c.maxHipDiff, kAngleTol);
  EXPECT_LT(c.maxKneeDiff, kAngleTol);
  EXPECT_NEAR(c.referenceSwingTime, c.simbodySwingTime, kSwingTimeTol);
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
  const double e0 = reference.calcMechanicalEnergy(tr.hipFlexion[0], tr.kneeFlexion[0], tr.hipFlexionRate[0],
                                                   tr.kneeFlexionRate[0]);
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
  const KneeLawSum law = makeKneeLaw(p, loadKneeModel(p.kneeModelPath));
  const ReferenceSwing reference(calcLegGeometry(p, 0.0), law, p.hipMoment, p.hipRange);
  EXPECT_THROW(reference.calcSwingTime(p.initial, p.swingEnd, 1e-8), RunError);
}

TEST(ReferenceSwing, RejectsDecreasingSampleTimes) {
  const Participant p = load("p1");
  const ReferenceSwing reference(calcLegGeometry(p, 0.0), KneeLawSum(), p.hipMoment, p.hipRange);
  EXPECT_THROW(reference.integrate(p.initial, {0.0, 0.2, 0.1}, 1e-8, 1e-8), std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
