// The pneumatic knee (models/pneumatic-knee.yaml) in a whole swing: Simbody and the
// independent reference integrator agree, the swing ends, and the cylinder never gives the
// leg more than the air it compressed held (energy bookkeeping).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "../leg/simbody_sampling.h"
#include "core/units.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "knee/pneumatic_cylinder.h"
#include "leg/leg_model.h"
#include "swing/knee_setup.h"
#include "swing/reference_swing.h"
#include "swing/swing_simulation.h"

namespace swingsim {
namespace {

// As tests/swing/reference_swing_test.cpp: both integrators far tighter than the agreement
// asked for, so a disagreement means different equations.
constexpr double kSimbodyAccuracy = 1e-10;
constexpr double kReferenceTol = 1e-11;
constexpr double kAngleTol = 1e-6;      // rad (docs/verification.md)
constexpr double kEventWindow = 1e-9;   // s
constexpr double kSwingTimeTol = 1e-6;  // s

Participant loadP1() { return loadParticipant(std::string(SWINGSIM_SOURCE_DIR) + "/participants/p1.yaml"); }
KneeModel loadPneumatic() { return loadKneeModel(std::string(SWINGSIM_SOURCE_DIR) + "/models/pneumatic-knee.yaml"); }

TEST(PneumaticKneeSwing, ReferenceIntegratorAgreesWithSimbody) {
  const Participant p = loadP1();
  const auto law = std::make_shared<const KneeLawSum>(makeKneeLaw(p, loadPneumatic()));
  SwingOptions options = makeSimbodyIntegratorOptions(kSimbodyAccuracy);
  options.sampleInterval = 0.002;
  options.eventWindow = kEventWindow;
  const SwingResult sim = simulateSwing(makeSwingSetup(p, law, 0.0), options);
  const ReferenceSwing reference(calcLegGeometry(p, 0.0), *law, p.hipMoment, p.hipRange);
  const ReferenceTrajectory tr = reference.integrate(p.initial, sim.trajectory.time, kReferenceTol, kReferenceTol);
  double maxKneeDiff = 0, maxHipDiff = 0;
  for (std::size_t i = 0; i < tr.size(); ++i) {
    maxHipDiff = std::max(maxHipDiff, std::abs(tr.hipFlexion[i] - sim.trajectory.hipFlexion[i]));
    maxKneeDiff = std::max(maxKneeDiff, std::abs(tr.kneeFlexion[i] - sim.trajectory.kneeFlexion[i]));
  }
  const ReferenceSwingEnd end = reference.calcSwingEnd(p.initial, p.swingEnd, kReferenceTol, kReferenceTol);
  ASSERT_TRUE(sim.peakKneeFlexion);
  EXPECT_LT(maxHipDiff, kAngleTol);
  EXPECT_LT(maxKneeDiff, kAngleTol);
  // The air rebounds the knee out of the zone; the reference's end is the first entry into
  // it (it has no settle dwell), which the Simbody swing records as its first zone entry.
  const std::optional<double> firstEntry = calcFirstZoneEntry(sim);
  ASSERT_TRUE(firstEntry);
  EXPECT_NEAR(end.swingTime, *firstEntry, kSwingTimeTol);
  EXPECT_NEAR(end.peakKneeFlexion, sim.peakKneeFlexion->flexion, kAngleTol);
  EXPECT_LT(sim.swingTime, p.swingEnd.timeLimit);
  std::printf(
      "pneumatic knee P1: max |knee diff| %.2e rad, |hip diff| %.2e rad; swing time Simbody %.9f s; first zone "
      "entry Simbody %.9f s, reference %.9f s; peak %.2f deg\n",
      maxKneeDiff, maxHipDiff, sim.swingTime, *firstEntry, end.swingTime, sim.peakKneeFlexion->flexion * kRadToDeg);
}

TEST(PneumaticKneeSwing, CylinderGivesBackNoMoreThanItsAirHeld) {
  // The cylinder's work on the leg plus the change of its stored energy is what its valves
  // took: never positive. 1e-9 J is far above the round-off at accuracy 1e-9, far below the
  // joules the air holds.
  constexpr double kRoundOff = 1e-9;  // J
  const Participant p = loadP1();
  const KneeLawSum law = makeKneeLaw(p, loadPneumatic());
  const KneeLaw& cylinder = law.part(0);
  ASSERT_EQ(cylinder.name(), "pneumatic cylinder");
  LegModel leg(calcLegGeometry(p, 0), law, p.hipMoment, p.hipRange, 1.0);
  double phi0 = NAN, maxBalance = -1e9, maxStored = 0, lastBalance = 0;
  swingsim::testing::integrateAndObserve(leg.getSystem(), leg.makeInitialState(p.initial), 1e-9, 0.002, 0.8,
                                         [&](const SimTK::State& s) {
                                           KneeKinematics knee;
                                           knee.flexion = leg.getKneeFlexion(s);
                                           const double phi = cylinder.calcStoredEnergy(knee, leg.getKneeLawStates(s));
                                           if (std::isnan(phi0)) phi0 = phi;
                                           lastBalance = leg.getKneePartWork(s, 0) + phi - phi0;
                                           maxBalance = std::max(maxBalance, lastBalance);
                                           maxStored = std::max(maxStored, phi);
                                         });
  EXPECT_LE(maxBalance, kRoundOff) << "the cylinder gave the leg energy its air did not hold";
  EXPECT_LT(lastBalance, -0.01) << "its valves must take a real amount of energy (J)";
  EXPECT_GT(maxStored, 0.01) << "the air must hold a real amount of energy (J)";
  std::printf("pneumatic knee P1 over 0.8 s: most energy in the air %.3f J, taken by the valves %.3f J\n", maxStored,
              -lastBalance);
}

}  // namespace
}  // namespace swingsim
