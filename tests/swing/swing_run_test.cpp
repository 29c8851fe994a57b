// SwingRun (swing/swing_run.h): a measured trial that ends before the swing-end rule is met is
// a result that says which condition was not met and by how much; a hip-moment swing that
// does not end is still an error.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/input_error.h"
#include "core/units.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "swing/knee_setup.h"
#include "swing/swing_run.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

// The trajectory's last sample is within one sample interval of the trial's end; the knee
// there moves at most a few rad/s, so the sample and the end state differ by less than this.
constexpr double kEndSampleKneeTolerance = 0.02;  // rad

SwingSetup winter() {
  const Participant p = loadParticipant("participants/winter.yaml");
  return makeSwingSetup(p, loadKneeModel(p.kneeModelPath));
}

TEST(SwingRun, MeasuredTrialCutWithTheKneeFlexedIsAResult) {
  const SwingSetup setup = winter();
  const SwingOptions options;
  const SwingResult r = SwingRun(setup, options).run();
  ASSERT_TRUE(r.trialEnd.has_value());
  const TrialEnd& e = *r.trialEnd;
  EXPECT_TRUE(std::isnan(r.swingTime));
  EXPECT_EQ(e.unmet, "knee_zone");
  // The trial's end is the measured thigh's last sample.
  EXPECT_DOUBLE_EQ(e.time, setup.participant.thighKinematics.time.back());
  EXPECT_GT(e.kneeFlexion, e.zoneOfStability);
  EXPECT_GE(e.thighPeak, e.thighTarget);  // the thigh did get there
  ASSERT_FALSE(r.trajectory.time.empty());
  EXPECT_NEAR(r.trajectory.time.back(), e.time, options.sampleInterval);
  EXPECT_NEAR(r.trajectory.kneeFlexion.back(), e.kneeFlexion, kEndSampleKneeTolerance);
  EXPECT_THAT(e.describe(), HasSubstr("the knee was not back in the zone of stability"));
}

TEST(SwingRun, MeasuredThighBelowItsTargetSaysByHowMuch) {
  SwingSetup setup = winter();
  setup.participant.swingEnd.thighTargetFlexion = 80 * kDegToRad;  // far above a walking thigh
  const SwingResult r = simulateSwing(setup);
  ASSERT_TRUE(r.trialEnd.has_value());
  EXPECT_EQ(r.trialEnd->unmet, "thigh_target");
  EXPECT_LT(r.trialEnd->thighPeak, r.trialEnd->thighTarget);
  EXPECT_THAT(r.trialEnd->describe(), HasSubstr("the thigh never reached its target flexion of 80.0 deg"));
}

TEST(SwingRun, HipMomentSwingThatDoesNotEndIsStillAnError) {
  Participant p = loadParticipant("participants/p1.yaml");
  p.hipMoment.flexionAmplitude = 5;  // far too weak to lift the thigh to its target
  p.hipMoment.extensionAmplitude = 5;
  const SwingSetup setup = makeSwingSetup(p, loadKneeModel(p.kneeModelPath));
  try {
    SwingRun(setup, SwingOptions{}).run();
    ADD_FAILURE() << "expected a RunError";
  } catch (const RunError& e) {
    EXPECT_THAT(e.what(), HasSubstr("the swing cannot end"));
  }
}

TEST(SwingRun, NoKneeLawIsAnInputError) {
  SwingSetup setup = winter();
  setup.knee = nullptr;
  EXPECT_THROW(SwingRun(setup, SwingOptions{}), InputError);
}

}  // namespace
}  // namespace swingsim
