// SwingRun (swing/swing_run.h): a measured trial that ends before the swing-end rule is met is
// a result that says which condition was not met and by how much; a hip-moment swing that
// does not end is still an error, and so is a knee folded past 180 deg. What the swing did
// not have (a knee peak, a clearance) is absent.
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

// A zone of stability above anything the knee reaches: the knee never peaks above it, so
// the swing has no peak and no toe clearance (measured from the peak), and says so: absent,
// never a marker number.
TEST(SwingRun, KneeWithoutAPeakAboveTheZoneHasNoPeakAndNoClearance) {
  SwingSetup setup = winter();
  setup.participant.swingEnd.zoneOfStability = 150 * kDegToRad;
  const SwingResult r = simulateSwing(setup);
  ASSERT_TRUE(r.trialEnd.has_value());
  EXPECT_EQ(r.trialEnd->unmet, "knee_peak");
  EXPECT_FALSE(r.peakKneeFlexion);
  EXPECT_FALSE(r.minToeClearance);
  EXPECT_FALSE(r.bounceHeight);
  EXPECT_FALSE(r.trialEnd->dwellDone);  // only the settle_dwell condition has it
}

TEST(SwingRun, AnEndedSwingHasItsPeakAndClearance) {
  Participant p = loadParticipant("participants/p1.yaml");
  const SwingResult r = simulateSwing(makeSwingSetup(p, loadKneeModel(p.kneeModelPath)));
  ASSERT_TRUE(r.peakKneeFlexion);
  EXPECT_GT(r.peakKneeFlexion->flexion, p.swingEnd.zoneOfStability);
  EXPECT_GT(r.peakKneeFlexion->time, 0);
  EXPECT_LT(r.peakKneeFlexion->time, r.swingTime);
  EXPECT_TRUE(r.minToeClearance);
}

// A knee flung from toe-off far faster than any swing's folds past 180 deg: a failed run
// that says what happened and when, not a result. (The measured thigh drive: under a hip
// moment the flung shank throws the thigh out of the hip's range first.)
TEST(SwingRun, KneePastItsPhysicalRangeIsAFailedRun) {
  SwingSetup setup = winter();
  setup.participant.initial.kneeFlexionRate = 3000 * kDegToRad;  // the most the CLI accepts
  setup.participant.initial.kneeStart = KneeStart::kInitial;     // not the record's knee at toe-off
  try {
    const SwingResult r = simulateSwing(setup);
    ADD_FAILURE() << "expected a RunError; the swing had " << r.trajectory.size() << " samples";
  } catch (const RunError& e) {
    EXPECT_THAT(e.what(), HasSubstr("winter at lowering 0 m: the knee flexion passed 180 deg at "));
    EXPECT_THAT(e.what(), HasSubstr("beyond the knee's physical range"));
    EXPECT_THAT(e.what(), HasSubstr("likely cause: a measured thigh motion"));
  }
}

TEST(SwingRun, NoKneeLawIsAnInputError) {
  SwingSetup setup = winter();
  setup.knee = nullptr;
  EXPECT_THROW(SwingRun(setup, SwingOptions{}), InputError);
}

}  // namespace
}  // namespace swingsim
