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
#include "reference_agreement.h"
#include "swing/knee_setup.h"
#include "swing/reference_swing.h"
#include "swing/swing_simulation.h"

namespace swingsim {
namespace {

using namespace swingsim::testing;  // the reference agreement's tolerances

Participant loadP1() { return loadParticipant(std::string(SWINGSIM_SOURCE_DIR) + "/participants/p1.yaml"); }
KneeModel loadPneumatic() { return loadKneeModel(std::string(SWINGSIM_SOURCE_DIR) + "/models/pneumatic-knee.yaml"); }

TEST(PneumaticKneeSwing, ReferenceIntegratorAgreesWithSimbody) {
  const Participant p = loadP1();
  const ReferenceAgreement a =
      compareWithReference(p, std::make_shared<const KneeLawSum>(makeKneeLaw(p, loadPneumatic())));
  ASSERT_TRUE(a.sim.peakKneeFlexion);
  EXPECT_LT(a.maxHipDiff, kAngleTol);
  EXPECT_LT(a.maxKneeDiff, kAngleTol);
  // The air rebounds the knee out of the zone; the reference's end is the first entry into
  // it (it has no settle dwell), which the Simbody swing records as its first zone entry.
  const std::optional<double> firstEntry = calcFirstZoneEntry(a.sim);
  ASSERT_TRUE(firstEntry);
  EXPECT_NEAR(a.end.swingTime, *firstEntry, kSwingTimeTol);
  EXPECT_NEAR(a.end.peakKneeFlexion, a.sim.peakKneeFlexion->flexion, kAngleTol);
  EXPECT_LT(a.sim.swingTime, p.swingEnd.timeLimit);
  std::printf(
      "pneumatic knee P1: max |knee diff| %.2e rad, |hip diff| %.2e rad; swing time Simbody %.9f s; first zone "
      "entry Simbody %.9f s, reference %.9f s; peak %.2f deg\n",
      a.maxKneeDiff, a.maxHipDiff, a.sim.swingTime, *firstEntry, a.end.swingTime,
      a.sim.peakKneeFlexion->flexion * kRadToDeg);
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
