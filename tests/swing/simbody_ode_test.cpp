// SimbodyOde: the Simbody leg's (q, u, z) as an ODE for our Dormand-Prince (the default
// swing integrator). Its derivatives are Simbody's own, it realizes nothing twice for the
// same (t, y), and integrating it agrees with Simbody's Runge-Kutta-Merson on the same
// system, Mauch S2 state included.
#include "swing/simbody_ode.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "leg/leg_model.h"
#include "swing/knee_setup.h"
#include "swing/swing_simulation.h"

namespace swingsim {
namespace {

using namespace SimTK;

Participant loadP1() { return loadParticipant(std::string(SWINGSIM_SOURCE_DIR) + "/participants/p1.yaml"); }

TEST(SimbodyOde, DerivativesAreSimbodysAndTheSameStateIsNotRealizedTwice) {
  const Participant p = loadP1();
  const KneeLawSum knee = makeKneeLaw(p, loadKneeModel(p.kneeModelPath));
  LegModel leg(calcLegGeometry(p, 0.05), knee, p.hipMoment, p.hipRange, 1.0);
  InitialConditions initial = p.initial;
  initial.hipFlexionRate = 1.5;
  initial.kneeFlexionRate = -2.0;
  const State s0 = leg.makeInitialState(initial);
  State work = s0;
  SimbodyOde ode(leg.getSystem(), work);
  ASSERT_EQ(ode.numStates(), s0.getNQ() + s0.getNU() + s0.getNZ());
  std::vector<double> y(ode.numStates()), dydt(ode.numStates());
  ode.readState(s0, y.data());
  const double t = 0.07;
  ode.calcDerivatives(t, y.data(), dydt.data());
  EXPECT_EQ(ode.getNumRealizations(), 1);

  State check = s0;
  check.updTime() = t;
  leg.getSystem().realize(check, Stage::Acceleration);
  for (int i = 0; i < s0.getNQ(); ++i) EXPECT_EQ(dydt[i], check.getQDot()[i]) << i;
  for (int i = 0; i < s0.getNU(); ++i) EXPECT_EQ(dydt[s0.getNQ() + i], check.getUDot()[i]) << i;

  ode.realizeAt(t, y.data());  // the same (t, y): no new realization
  EXPECT_EQ(ode.getNumRealizations(), 1);
  y[0] += 1e-9;
  ode.realizeAt(t, y.data());
  EXPECT_EQ(ode.getNumRealizations(), 2);
}

// Swings do not integrate the work (nothing reads it there): no Z states for a law
// without states, and asking for the work says so instead of reading garbage.
TEST(SimbodyOde, LegWithoutWorkTrackingHasOnlyTheLawStates) {
  const Participant p = loadP1();
  const KneeLawSum damping = makeKneeLaw(p, loadKneeModel(p.kneeModelPath));
  const LegModel plain(calcLegGeometry(p, 0.0), damping, p.hipMoment, p.hipRange, 1.0, /*trackWork=*/false);
  const State s = plain.makeInitialState(p.initial);
  EXPECT_EQ(s.getNZ(), 0);
  EXPECT_EQ(plain.getKneeLawStates(s), nullptr);
  EXPECT_THROW(plain.getKneeWork(s), std::logic_error);
  EXPECT_THROW(plain.getHipWork(s), std::logic_error);
  const LegModel tracked(calcLegGeometry(p, 0.0), damping, p.hipMoment, p.hipRange, 1.0);
  // The work of each knee law part (damping table, stop, friction), then the hip's.
  ASSERT_EQ(tracked.numKneeWorkParts(), 3);
  EXPECT_EQ(tracked.makeInitialState(p.initial).getNZ(), 4);

  const KneeLawSum mauch =
      makeKneeLaw(p, loadKneeModel(std::string(SWINGSIM_SOURCE_DIR) + "/models/mauch-4phase.yaml"));
  const LegModel latch(calcLegGeometry(p, 0.0), mauch, p.hipMoment, p.hipRange, 1.0, /*trackWork=*/false);
  EXPECT_EQ(latch.makeInitialState(p.initial).getNZ(), mauch.numStates());
}

// Dormand-Prince over SimbodyOde against Simbody's RK-Merson on the same Mauch leg (S2
// latch as a Z state), both far tighter than the agreement asked for.
TEST(SimbodyOde, DormandPrinceAgreesWithSimbodysIntegratorOnTheMauchLeg) {
  constexpr double kTol = 1e-11;   // both integrators
  constexpr double kAgree = 1e-7;  // rad, rad/s and S2 after 0.3 s
  const Participant p = loadP1();
  const KneeModel model = loadKneeModel(std::string(SWINGSIM_SOURCE_DIR) + "/models/mauch-4phase.yaml");
  const KneeLawSum knee = makeKneeLaw(p, model);
  LegModel leg(calcLegGeometry(p, 0.0), knee, p.hipMoment, p.hipRange, 1.0);
  const State s0 = leg.makeInitialState(p.initial);
  ASSERT_GT(s0.getNZ(), 0) << "the Mauch law carries S2 as a state";
  constexpr double kEnd = 0.3;  // s: past the knee's peak flexion

  State work = s0;
  SimbodyOde ode(leg.getSystem(), work);
  std::vector<double> y(ode.numStates());
  ode.readState(s0, y.data());
  DormandPrince dp(ode, kTol, kTol);
  dp.initialize(0, y.data());
  dp.integrateTo(kEnd);

  RungeKuttaMersonIntegrator rkm(leg.getSystem());
  rkm.setAccuracy(kTol);
  rkm.setFinalTime(kEnd);
  rkm.initialize(s0);
  while (rkm.stepTo(kEnd) != Integrator::EndOfSimulation && rkm.getTime() < kEnd) {
  }
  std::vector<double> yRkm(ode.numStates());
  ode.readState(rkm.getState(), yRkm.data());
  for (int i = 0; i < ode.numStates(); ++i) EXPECT_NEAR(dp.getState()[i], yRkm[i], kAgree) << "state " << i;
}

}  // namespace
}  // namespace swingsim
