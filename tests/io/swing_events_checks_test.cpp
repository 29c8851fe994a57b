// A force file is checked before its events are believed, and its events against the leg's
// own kinematics: the plausible mistakes a newcomer makes with a lab's files, each made on
// the public OpenSim trials as they are (walking and running), must be refused with the file,
// the column and what was found, or, where the user asks, fall back to the kinematics with
// that said. None may give a swing list.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "core/input_error.h"
#include "core/units.h"
#include "io/swing_events.h"
#include "opensim_trials.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

using testing::inputErrorOf;
const std::string& kWalkGrf = testing::kWalkGrf;
const std::string& kWalkIk = testing::kWalkIk2392;
const std::string& kRunIk = testing::kRajagopalRunIk;
const std::string& kRunGrf = testing::kRajagopalRunGrf;
const std::string& kHamnerIk = testing::kHamnerRunIk;
const std::string& kHamnerGrf = testing::kHamnerRunGrf;

MotionColumns leg(const std::string& side, double kneeSign) {
  MotionColumns c;
  c.hip = "hip_flexion_" + side;
  c.knee = "knee_angle_" + side;
  c.kneeSign = kneeSign;
  c.pelvisTilt = "pelvis_tilt";
  return c;
}
GrfSettings force(const std::string& column, const std::string& path) {
  GrfSettings g;
  g.path = path;
  g.verticalForce = column;
  return g;
}

/// The right leg of the public walk against `grf` (its right foot's column unless named).
std::string walkError(const MotionTable& grf, const std::string& column = "ground_force_vy") {
  return inputErrorOf([&] { listSwings(readMotionTable(kWalkIk), leg("r", -1), grf, force(column, grf.path)); });
}
/// The right leg of the public run against `grf`.
std::string runError(const MotionTable& grf, const std::string& column = "R_ground_force_vy") {
  return inputErrorOf([&] { listSwings(readMotionTable(kRunIk), leg("r", 1), grf, force(column, grf.path)); });
}

MotionTable scaled(MotionTable t, const std::string& column, double factor) {
  for (double& v : t.columns[t.index(column)]) v *= factor;
  return t;
}

TEST(SwingEventChecks, TheOtherFootsForceColumnIsRefusedNamingTheLegItMatches) {
  const std::string walk = walkError(readMotionTable(kWalkGrf), "1_ground_force_vy");
  EXPECT_THAT(walk, HasSubstr("subject01_walk1_grf.mot: 1_ground_force_vy: expected the force's stance and swing to "
                              "match the leg's kinematics"));
  EXPECT_THAT(
      walk,
      HasSubstr(
          "they match the other leg's (hip_flexion_l, knee_angle_l): is 1_ground_force_vy the other foot's force?"));
  const std::string run = runError(readMotionTable(kRunGrf), "L_ground_force_vy");
  EXPECT_THAT(run,
              HasSubstr("rajagopal_grf_run.mot: L_ground_force_vy: expected the force's stance and swing to match"));
  EXPECT_THAT(run, HasSubstr("running rules"));
  EXPECT_THAT(run, HasSubstr("they match the other leg's (hip_flexion_l, knee_angle_l)"));
  // The second runner, left leg against the right foot's column.
  const std::string hamner = inputErrorOf([&] {
    listSwings(readMotionTable(kHamnerIk), leg("l", -1), readMotionTable(kHamnerGrf),
               force("ground_force_vy", kHamnerGrf));
  });
  EXPECT_THAT(hamner, HasSubstr("they match the other leg's (hip_flexion_r, knee_angle_r)"));
}

TEST(SwingEventChecks, AnotherTrialsForceFileIsRefused) {
  // The runner's force under the walk's kinematics: the clocks overlap (0.23-5.32 s, 0.5-4 s).
  const std::string e = walkError(readMotionTable(kRunGrf), "R_ground_force_vy");
  EXPECT_THAT(
      e, HasSubstr("rajagopal_grf_run.mot: R_ground_force_vy: expected the force's stance and swing to match the leg's "
                   "kinematics (" +
                   kWalkIk +
                   ": hip_flexion_r, knee_angle_r, walking rules, detected: median stride 1.217 s, "
                   "over 0.85 s) (got: "));
  EXPECT_THAT(
      e, HasSubstr("another trial's force file, a clock offset, the other foot's column, or the wrong gait's rules "
                   "(state it: --gait, a study's gait:)?"));
}

TEST(SwingEventChecks, AClockOffsetIsRefused) {
  MotionTable late = readMotionTable(kWalkGrf);
  for (double& t : late.columns.front()) t += 2.0;
  EXPECT_THAT(walkError(late), HasSubstr("expected the force's stance and swing to match the leg's kinematics"));
  MotionTable runLate = readMotionTable(kRunGrf);
  for (double& t : runLate.columns.front()) t += 2.0;
  EXPECT_THAT(runError(runLate), HasSubstr("expected the force's stance and swing to match the leg's kinematics"));
}

TEST(SwingEventChecks, AForceThatNeverLetsGoIsRefused) {
  // Both feet's forces summed (a treadmill's one plate): never below 20 N while walking.
  MotionTable total = readMotionTable(kWalkGrf);
  std::vector<double>& right = total.columns[total.index("ground_force_vy")];
  const std::vector<double>& left = total.column("1_ground_force_vy");
  for (std::size_t k = 0; k < right.size(); ++k) right[k] += left[k];
  // Inside the time both feet were on the plates (0.5-2.5 s of the 0-2.5 s file).
  MotionTable cut = total;
  for (auto& column : cut.columns) column.erase(column.begin(), column.begin() + 300);
  cut.rowLines.erase(cut.rowLines.begin(), cut.rowLines.begin() + 300);
  const std::string e = walkError(cut);
  EXPECT_THAT(
      e, HasSubstr("falls in a stance of the force (the force never falls below the threshold: both feet on one plate, "
                   "or a total force?)"));
}

TEST(SwingEventChecks, AForceInKilonewtonsNegatedOrAllZeroIsRefused) {
  const MotionTable grf = readMotionTable(kWalkGrf);
  EXPECT_THAT(
      walkError(scaled(grf, "ground_force_vy", 1e-3)),
      HasSubstr("subject01_walk1_grf.mot: ground_force_vy: expected a vertical force in newtons: a stance peaks at 1-3 "
                "body weights, at least 200 N (got a peak of"));
  EXPECT_THAT(walkError(scaled(grf, "ground_force_vy", 1e-3)), HasSubstr("in kN?"));
  EXPECT_THAT(walkError(scaled(grf, "ground_force_vy", -1)),
              HasSubstr("negated? OpenSim's vertical force pushes up, +y"));
  EXPECT_THAT(walkError(scaled(grf, "ground_force_vy", 0)),
              HasSubstr("(got a peak of 0 N over the kinematics' time: no load at all)"));
  EXPECT_THAT(runError(scaled(readMotionTable(kRunGrf), "R_ground_force_vy", 1e-3)), HasSubstr("in kN?"));
}

TEST(SwingEventChecks, AHorizontalComponentNamedAsVerticalIsRefused) {
  // The fore-aft force (a lab frame with z up reads a horizontal component as y).
  EXPECT_THAT(walkError(readMotionTable(kWalkGrf), "ground_force_vx"),
              HasSubstr("ground_force_vx: expected a vertical force, which never pulls the foot down"));
  EXPECT_THAT(runError(readMotionTable(kRunGrf), "R_ground_force_vx"), HasSubstr("a horizontal component"));
}

TEST(SwingEventChecks, ATimeColumnInMillisecondsOrASlowForceIsRefused) {
  MotionTable ms = readMotionTable(kWalkGrf);
  for (double& t : ms.columns.front()) t *= 1000;
  EXPECT_THAT(walkError(ms), HasSubstr("expected a force sampled at least as often as the kinematics (60 Hz)"));
  EXPECT_THAT(walkError(ms), HasSubstr("is the time column in ms? OpenSim's is in s"));
  // 10 Hz force (every 60th row of the 600 Hz file) under 60 Hz kinematics.
  const MotionTable full = readMotionTable(kWalkGrf);
  MotionTable slow = full;
  for (auto& column : slow.columns) {
    std::vector<double> kept;
    for (std::size_t k = 0; k < column.size(); k += 60) kept.push_back(column[k]);
    column = kept;
  }
  EXPECT_THAT(walkError(slow), HasSubstr("(got a step of 0.1 s, 10 Hz)"));
}

TEST(SwingEventChecks, KinematicsWhoseUnitOrKneeSignIsWrongAreRefusedInEveryCommand) {
  MotionTable radiansRead = readMotionTable(kWalkIk);
  radiansRead.inDegrees = false;  // degrees under inDegrees=no
  EXPECT_THAT(
      inputErrorOf([&] { listSwings(radiansRead, leg("r", -1), std::nullopt); }),
      HasSubstr("knee_angle_r: the knee moves through 71.26986685 rad over the file (from -70.26237926 to 1.00748759; "
                "a swing "
                "flexes it by tens of degrees): the column looks like degrees, but the header says inDegrees=no"));
  MotionTable degreesRead = readMotionTable(kWalkIk);
  for (const char* c : {"hip_flexion_r", "knee_angle_r", "pelvis_tilt"})
    for (double& v : degreesRead.columns[degreesRead.index(c)]) v *= kDegToRad;  // radians under inDegrees=yes
  EXPECT_THAT(inputErrorOf([&] { listSwings(degreesRead, leg("r", -1), std::nullopt); }),
              HasSubstr("the column looks like radians, but the header says inDegrees=yes"));
  EXPECT_THAT(inputErrorOf([&] { listSwings(readMotionTable(kWalkIk), leg("r", 1), std::nullopt); }),
              HasSubstr("knee_angle_r: expected knee flexion, positive when bent"));
  EXPECT_THAT(inputErrorOf([&] { listSwings(readMotionTable(kRunIk), leg("r", -1), std::nullopt); }),
              HasSubstr("set knee_sign: 1 (motion_columns, thigh_kinematics) or --knee-sign 1 (swingsim swings)"));
}

TEST(SwingEventChecks, AskedForTheFallbackTheKinematicsGiveTheEventsAndSaySo) {
  GrfSettings other = force("1_ground_force_vy", kWalkGrf);
  other.fallbackToKinematics = true;
  const SwingList list = listSwings(readMotionTable(kWalkIk), leg("r", -1), readMotionTable(kWalkGrf), other);
  ASSERT_FALSE(list.swings.empty());
  for (const FoundSwing& s : list.swings) {
    EXPECT_EQ(s.toeOffSource, "kinematics");
    EXPECT_EQ(s.heelContactSource, "kinematics");
  }
  ASSERT_EQ(list.notes.size(), 1u);
  EXPECT_THAT(list.notes[0], HasSubstr("events from the kinematics, not the force (fallback_to_kinematics): "));
  EXPECT_THAT(list.notes[0], HasSubstr("1_ground_force_vy: expected the force's stance and swing to match"));
  // The same kinematic swings as without a force file.
  const SwingList alone = listSwings(readMotionTable(kWalkIk), leg("r", -1), std::nullopt);
  ASSERT_EQ(alone.swings.size(), list.swings.size());
  EXPECT_DOUBLE_EQ(alone.swings[0].toeOff, list.swings[0].toeOff);
}

TEST(SwingEventChecks, TheRightFilesPassWithTheirDisagreementsListed) {
  const SwingList run =
      listSwings(readMotionTable(kRunIk), leg("r", 1), std::optional<GrfSettings>(force("R_ground_force_vy", kRunGrf)));
  ASSERT_EQ(run.swings.size(), 7u);
  EXPECT_EQ(run.gait, Gait::kRunning);
  for (const FoundSwing& s : run.swings) {
    EXPECT_EQ(s.toeOffSource, "grf");
    ASSERT_TRUE(s.toeOffDisagreement && s.heelContactDisagreement);
    EXPECT_LE(std::abs(*s.toeOffDisagreement), kRunningAccuracyS + 5e-4);
    EXPECT_LE(std::abs(*s.heelContactDisagreement), kRunningAccuracyS + 5e-4);
  }
  // 100 Hz: 2 frames are 20 ms, under the running rules' 22 ms.
  EXPECT_TRUE(run.kinematicAccuracyBeyondTwoFrames);
  const SwingList hamner = listSwings(readMotionTable(kHamnerIk), leg("r", -1),
                                      std::optional<GrfSettings>(force("ground_force_vy", kHamnerGrf)));
  EXPECT_EQ(hamner.swings.size(), 13u);
  EXPECT_FALSE(hamner.kinematicAccuracyBeyondTwoFrames);  // 60 Hz: 33 ms
}

}  // namespace
}  // namespace swingsim
