// The messages a swing can end with (swing/run_error_text.h): who (participant and
// lowering), the state in degrees, the numbers rounded as documented, and the cause that
// fits the case (which part of the end rule failed, hip moment or measured thigh drive).
#include "swing/run_error_text.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "swing/knee_setup.h"

namespace swingsim {
namespace {

using ::testing::EndsWith;
using ::testing::HasSubstr;
using ::testing::StartsWith;

// P1 at 0.05 m, a leg built for it, and a state at t = 0.1234 s with the hip at 0.2 rad
// (11.5 deg) rising at 1 rad/s (57 deg/s) and the knee at 0.5 rad (28.6 deg) extending at
// 2 rad/s (-115 deg/s).
struct Fixture {
  SwingSetup setup;
  SwingOptions options;
  std::unique_ptr<LegModel> leg;
  SimTK::State state;

  explicit Fixture(SwingDrive drive = SwingDrive::kHipMoment) {
    const Participant p = loadParticipant("participants/p1.yaml");
    setup = makeSwingSetup(p, loadKneeModel(p.kneeModelPath));
    setup.lowering = 0.05;
    leg = std::make_unique<LegModel>(calcLegGeometry(p, setup.lowering, setup.added), *setup.knee, p.hipMoment,
                                     p.hipRange, calcHipHeight(p), false);
    InitialConditions at;
    at.hipFlexion = 0.2;
    at.hipFlexionRate = 1.0;
    at.kneeFlexion = 0.5;
    at.kneeFlexionRate = -2.0;
    state = leg->makeInitialState(at);
    state.updTime() = 0.1234;
    setup.participant.drive = drive;  // only the wording reads it
  }
  RunErrorText text() const { return RunErrorText(setup, options, *leg, 0.8); }
};

constexpr const char* kState = "at t = 0.1234 s: hip flexion 11.5 deg (57 deg/s), knee flexion 28.6 deg (-115 deg/s)";

TEST(RunErrorText, DescribesTheStateInDegreesRounded) {
  const Fixture f;
  EXPECT_EQ(describeState(*f.leg, f.state), kState);
}

TEST(RunErrorText, IntegratorFailureAndDivergenceNameTheParticipantStateAndCause) {
  const Fixture f;
  const std::string failed = f.text().integratorFailed(f.state, std::runtime_error("step size too small")).what();
  EXPECT_EQ(failed,
            std::string("P1: the integrator failed ") + kState +
                " (likely cause: a knee or hip law too stiff for the accuracy, or an unphysical input; step size "
                "too small)");
  EXPECT_EQ(std::string(f.text().diverged(f.state).what()),
            std::string("P1: the simulation diverged ") + kState +
                " (likely cause: an unphysical input such as a near-zero inertia)");
}

TEST(RunErrorText, OverBudgetSaysWhichBudgetAndWhatToChange) {
  Fixture f;
  f.options.maxRealizations = 1000;
  const std::string realizations = f.text().overBudget(RunBudget::Spent::kRealizations, 1234, f.state).what();
  EXPECT_THAT(realizations,
              StartsWith("P1 at lowering 0.05 m: the swing was stopped after 1234 realizations (the budget "
                         "of one swing is 1000; a normal swing takes a few hundred) " +
                         std::string(kState)));
  EXPECT_THAT(realizations, HasSubstr(std::string(integratorName(f.options.integrator)) + " at accuracy 1e-05"));
  EXPECT_THAT(realizations, EndsWith("check the knee model " + f.setup.participant.kneeModelPath +
                                     " for a value far too large (a unit mistake?)"));
  f.options.maxWallSeconds = 2.5;
  EXPECT_THAT(
      f.text().overBudget(RunBudget::Spent::kWallClock, 1234, f.state).what(),
      HasSubstr("stopped after 2.5 s of computing (the limit for one swing; a normal swing takes milliseconds)"));
}

TEST(RunErrorText, RangeMessagesGiveTheLimitsAndTheCauseForTheDrive) {
  const Fixture hip;
  EXPECT_THAT(hip.text().hipLeftRange(hip.state).what(),
              StartsWith("P1 at lowering 0.05 m: the hip left its range of "));
  const std::string knee = hip.text().kneeLeftRange(hip.state, 0.123456).what();
  EXPECT_THAT(knee, StartsWith("P1 at lowering 0.05 m: the knee flexion passed 180 deg at 0.1235 s, beyond the knee's "
                               "physical range"));
  EXPECT_THAT(knee, HasSubstr("(likely cause: a hip moment far too large for this leg"));
  const Fixture thigh(SwingDrive::kThighKinematics);
  EXPECT_THAT(thigh.text().kneeLeftRange(thigh.state, 0.1).what(),
              HasSubstr("(likely cause: a measured thigh motion far more violent than a swing's"));
}

TEST(RunErrorText, CannotEndGivesTheShortfallRounded) {
  const Fixture f;
  const std::string m = f.text().cannotEnd(f.state, -2.5, 0.41234567, 1.23456789).what();
  EXPECT_THAT(m, StartsWith("P1 at lowering 0.05 m: the swing cannot end (decided " + std::string(kState) +
                            ", before the time limit of 0.8 s): the thigh never reached its target flexion of "));
  EXPECT_THAT(
      m, HasSubstr("with the hip moment constant at -2.5 N m from t = 0.4123 s, the leg's energy is 1.2346 J short"));
}

TEST(RunErrorText, DidNotEndNamesThePartOfTheEndRuleThatFailed) {
  const Fixture f;
  SwingLog log(0.05);
  const auto message = [&](const Fixture& at) { return std::string(at.text().didNotEnd(at.state, log).what()); };
  const std::string prefix =
      "P1 at lowering 0.05 m: the swing did not end within the time limit of 0.8 s; " + std::string(kState) + "; ";
  EXPECT_THAT(message(f), StartsWith(prefix + "the thigh never reached its target flexion of "));
  EXPECT_THAT(message(f), EndsWith(" deg (hip moment too small for this leg?)"));
  EXPECT_THAT(message(Fixture(SwingDrive::kThighKinematics)),
              EndsWith("(set swing_end: thigh_target_flexion_deg below the measured thigh's peak)"));
  log.thighReached = true;
  EXPECT_EQ(message(f), prefix + "the knee never reached a flexion peak above the zone of stability");
  log.peakSeen = true;
  EXPECT_THAT(message(f), StartsWith(prefix + "the knee never came back inside the zone of stability (< "));
  log.enteredOnce = true;
  log.bounces = 3;
  EXPECT_THAT(message(f), HasSubstr("the knee did not settle: it left the zone of stability"));
  EXPECT_THAT(message(f), HasSubstr("3 times and never stayed inside it for the settle dwell of " +
                                    formatNumber(f.setup.participant.swingEnd.settleDwell) + " s"));
}

}  // namespace
}  // namespace swingsim
