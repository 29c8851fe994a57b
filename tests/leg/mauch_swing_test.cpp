// The Mauch cylinder (Chien 2014) as the knee of the Simbody leg: the moment is the
// cylinder force times its moment arm, the S2 latch is a state that sets in
// hyperextension and holds through the following flexion, and the energy balance holds.
#include <gtest/gtest.h>

#include "simbody_sampling.h"

#include <cmath>
#include <functional>

#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "knee/joint_stop.h"
#include "knee/knee_geometry.h"
#include "knee/mauch_cylinder.h"
#include "leg/leg_model.h"
#include "swing/knee_setup.h"
#include "swing/swing_simulation.h"

namespace swingsim {
namespace {

using namespace SimTK;

constexpr double kHipHeight = 1.0;  // m; irrelevant to the dynamics
// Bookkeeping: the Simbody accuracy is 1e-9 relative; the energies are ~10 J, and the
// stiff latch (k = 1e4 /s) adds round-off in the work integrals; 1e-6 J is 100x the
// expected drift and 1e-6 of the work the cylinder dissipates.
constexpr double kEnergyAccuracy = 1e-9;
constexpr double kEnergyTol = 1e-6;  // J

Participant loadP1() { return loadParticipant(std::string(SWINGSIM_SOURCE_DIR) + "/participants/p1.yaml"); }

const MauchCylinder& cylinderOf(const KneeModel& model) {
  return dynamic_cast<const MauchCylinder&>(model.law.part(0));
}

// The model with its cylinder's S2 starting at `latch` (the law's own initial state).
KneeModel withInitialLatch(const KneeModel& model, double latch) {
  MauchCylinderParams params = cylinderOf(model).params();
  params.initialLatch = latch;
  KneeModel out = model;
  out.law = KneeLawSum();
  out.law.add(std::make_unique<MauchCylinder>(params));
  for (std::size_t i = 1; i < model.law.size(); ++i) out.law.add(model.law.part(i).clone());
  return out;
}

using swingsim::testing::integrateAndObserve;

TEST(MauchSwing, KneeMomentIsCylinderForceTimesMomentArm) {
  const Participant p = loadP1();
  const KneeModel model = loadKneeModel(std::string(SWINGSIM_SOURCE_DIR) + "/models/mauch-4phase.yaml");
  const KneeGeometry geometry;  // Chien Eq. 1 defaults, as in the model file
  for (double latch : {0.0, 0.4, 1.0}) {
    const KneeModel latched = withInitialLatch(model, latch);
    const MauchCylinder& cylinder = cylinderOf(latched);
    KneeLawSum onlyCylinder;
    onlyCylinder.add(cylinder.clone());
    LegModel leg(calcLegGeometry(p, 0), onlyCylinder, p.hipMoment, p.hipRange, kHipHeight);
    for (double deg : {-3.0, 0.0, 5.0, 20.0, 45.0, 70.0}) {
      for (double rate : {-4.0, -0.5, 0.0, 0.7, 5.0}) {
        InitialConditions ic = p.initial;
        ic.kneeFlexion = deg * kDegToRad;
        ic.kneeFlexionRate = rate;
        State s = leg.makeInitialState(ic);
        ASSERT_DOUBLE_EQ(leg.getKneeLawStates(s)[0], latch);
        leg.getSystem().realize(s, Stage::Dynamics);
        const double x = geometry.calcPistonPosition(ic.kneeFlexion);
        const double xd = geometry.calcPistonVelocity(ic.kneeFlexion, rate);
        const double force = cylinder.calcForce(x, xd, latch);
        const double expected = geometry.calcKneeMoment(ic.kneeFlexion, force);
        EXPECT_NEAR(leg.calcKneeMoment(s), expected, 1e-9 * (1 + std::abs(expected)))
            << deg << " deg, " << rate << " rad/s, S2 " << latch;
      }
    }
  }
}

// Starting in hyperextension with S2 = 0 (valve closed), the extension-to-hyperextension
// state sets the latch; it then holds (S1 = 1 freezes Eq. 6) through the swing flexion, so
// the swing meets the low phase-2 resistance. Without the hyperextension it never sets.
TEST(MauchSwing, LatchSetsInHyperextensionAndHoldsThroughFlexion) {
  Participant p = loadP1();
  const KneeModel model = loadKneeModel(std::string(SWINGSIM_SOURCE_DIR) + "/models/mauch-4phase.yaml");
  // A stop engaging at -4 deg (Burkett: within 4 deg of full extension) lets the knee
  // stay hyperextended for a while, as at the end of stance on the bench.
  KneeModel softStop = withInitialLatch(model, 0.0);
  KneeLawSum cylinderAndStop;
  cylinderAndStop.add(softStop.law.part(0).clone());
  JointStopParams stop;
  stop.lower = -4 * kDegToRad;
  cylinderAndStop.add(std::make_unique<JointStop>(stop));
  softStop.law = cylinderAndStop;
  const KneeLawSum law = makeKneeLaw(p, softStop);
  for (bool hyperextended : {true, false}) {
    LegModel leg(calcLegGeometry(p, 0), law, p.hipMoment, p.hipRange, kHipHeight);
    InitialConditions ic = p.initial;
    ic.kneeFlexion = (hyperextended ? -2.0 : 10.0) * kDegToRad;
    ic.kneeFlexionRate = hyperextended ? -0.3 : 0.0;  // still extending, towards the stop
    const State s0 = leg.makeInitialState(ic);
    double latchAt20ms = NaN, minLatchDuringFlexion = 1, peakKnee = -1, latchAtPeak = NaN, maxLatch = 0;
    integrateAndObserve(leg.getSystem(), s0, 1e-7, 0.001, 0.25, [&](const State& s) {
      const double latch = leg.getKneeLawStates(s)[0];
      const double knee = leg.getKneeFlexion(s);
      maxLatch = std::max(maxLatch, latch);
      if (std::abs(s.getTime() - 0.02) < 1e-9) latchAt20ms = latch;
      if (s.getTime() > 0.02 && leg.getKneeFlexionRate(s) > 0.1)
        minLatchDuringFlexion = std::min(minLatchDuringFlexion, latch);
      if (knee > peakKnee) {
        peakKnee = knee;
        latchAtPeak = latch;
      }
    });
    if (hyperextended) {
      EXPECT_GT(latchAt20ms, 0.9) << "S2 must set while the knee extends in hyperextension";
      EXPECT_GT(minLatchDuringFlexion, 0.9) << "S2 must hold through the following flexion";
      // At the turning point S1 = 1/2 and the valve starts to close again (Eq. 6): the
      // latch is released as the knee extends with x > xhy.
      EXPECT_LT(latchAtPeak, 0.5);
      EXPECT_GT(peakKnee, 10 * kDegToRad) << "the swing must really flex";
    } else {
      EXPECT_LT(latchAt20ms, 0.05) << "no hyperextension, no latch";
      EXPECT_LT(maxLatch, 0.05) << "the latch must never set without hyperextension";
      EXPECT_LT(latchAtPeak, 0.05);
    }
  }
}

TEST(MauchSwing, EnergyBookkeepingHoldsWithTheCylinder) {
  const Participant p = loadP1();
  const KneeModel model = loadKneeModel(std::string(SWINGSIM_SOURCE_DIR) + "/models/mauch-4phase.yaml");
  const KneeLawSum law = makeKneeLaw(p, model);
  LegModel leg(calcLegGeometry(p, 0.05), law, p.hipMoment, p.hipRange, kHipHeight);
  double b0 = NaN, maxDrift = 0, kneeWork = 0;
  integrateAndObserve(leg.getSystem(), leg.makeInitialState(p.initial), kEnergyAccuracy, 0.002, 0.8,
                      [&](const State& s) {
                        kneeWork = leg.getKneeWork(s);
                        const double balance = leg.calcMechanicalEnergy(s) - kneeWork - leg.getHipWork(s);
                        if (std::isnan(b0)) b0 = balance;
                        maxDrift = std::max(maxDrift, std::abs(balance - b0));
                      });
  EXPECT_LT(maxDrift, kEnergyTol);
  EXPECT_LT(kneeWork, -1.0) << "the cylinder must dissipate a real amount of energy (J)";
}

TEST(MauchSwing, SwingEndsWithEitherMauchModel) {
  for (const char* file : {"/models/mauch-2phase.yaml", "/models/mauch-4phase.yaml"}) {
    const SwingSetup setup = makeSwingSetup(loadP1(), loadKneeModel(std::string(SWINGSIM_SOURCE_DIR) + file));
    const SwingResult r = simulateSwing(setup);
    EXPECT_GT(r.swingTime, 0.2) << file;
    EXPECT_LT(r.swingTime, 0.6) << file;
    ASSERT_TRUE(r.peakKneeFlexion) << file;
    EXPECT_GT(r.peakKneeFlexion->flexion, 10 * kDegToRad) << file;
  }
}

}  // namespace
}  // namespace swingsim
