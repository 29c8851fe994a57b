// Swing events: force crossings against their closed form on linear ramps, a force that
// hovers at the threshold, swings cut by the file's start and end, the kinematic rules
// against the closed form of a synthetic gait and against the force plates of the public
// OpenSim walks (both feet, three IK files), and every bad input's message.
#include "io/swing_events.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include "core/input_error.h"
#include "core/units.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

const std::string kRoot = SWINGSIM_SOURCE_DIR;
const std::string kGrf = kRoot + "/studies/data/opensim-subject01/subject01_walk1_grf.mot";
const std::string kIk2392 = kRoot + "/studies/data/opensim-subject01/gait2392_subject01_walk1_ik.mot";
const std::string kIk2354 = kRoot + "/studies/data/opensim-subject01/gait2354_subject01_walk1_ik.mot";
const std::string kIk10dof = kRoot + "/tests/data/opensim-gait10dof/subject01_walk_IK.mot";

/// The brief's target for a kinematic event: within 2 frames of the force's at 60 Hz, s.
constexpr double kTwoFrames = 2.0 / 60.0;
/// Linear interpolation of a linear ramp is exact up to rounding, s.
constexpr double kRoundingS = 1e-9;

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

/// A motion table in memory: labels, then rows from `row(t)` at t = t0, t0 + step, ... <= t1.
MotionTable makeTable(const std::string& labels, double t0, double t1, double step,
                      const std::function<std::string(double)>& row, const std::string& path) {
  std::string text = "synthetic\ninDegrees=yes\nendheader\n" + labels + "\n";
  const int n = static_cast<int>(std::floor((t1 - t0) / step + 1e-6));
  for (int k = 0; k <= n; ++k) {
    const double t = std::round((t0 + k * step) * 1e6) / 1e6;  // whole microseconds, as a capture system writes
    text += number(t) + "\t" + row(t) + "\n";
  }
  return parseMotionTable(text, path);
}

// A synthetic gait, period 1 s: stance on phases [0, 0.6), swing on [0.6, 1). The knee
// rises in a raised cosine from 5 to 60 deg flexion and back over the swing (OpenSim's sign:
// knee_angle = -flexion); the hip swings sinusoidally, most flexed at phase 0.95.
constexpr double kSwingStart = 0.6, kSwingLength = 0.4;
double phaseOf(double t) { return t - std::floor(t); }
double kneeFlexionDeg(double t) {
  const double s = (phaseOf(t) - kSwingStart) / kSwingLength;
  return s < 0 ? 5 : 5 + 55 * 0.5 * (1 - std::cos(2 * kPi * s));
}
double hipFlexionDeg(double t) { return 25 * std::cos(2 * kPi * (phaseOf(t) - 0.95)); }
MotionTable syntheticGait(double t0, double t1) {
  return makeTable("time\thip_flexion_r\tknee_angle_r", t0, t1, 0.01,
                   [](double t) { return number(hipFlexionDeg(t)) + "\t" + number(-kneeFlexionDeg(t)); }, "gait.mot");
}
MotionColumns rightColumns(bool tilt) {
  MotionColumns c;
  c.hip = "hip_flexion_r";
  c.knee = "knee_angle_r";
  c.kneeSign = -1;
  if (tilt) c.pelvisTilt = "pelvis_tilt";
  return c;
}
/// Closed form: the knee's fastest flexion is mid-rise of the raised cosine.
double syntheticToeOff(int cycle) { return cycle + kSwingStart + kSwingLength / 4; }
/// Independent of the sampled rule: the ankle's forward distance evaluated densely.
double syntheticHeelContact(int cycle) {
  const auto forward = [](double t) {
    const double th = hipFlexionDeg(t) * kDegToRad, kn = kneeFlexionDeg(t) * kDegToRad;
    return std::sin(th) + std::sin(th - kn);
  };
  double best = cycle + 0.8;
  for (double t = cycle + 0.8; t < cycle + 1.2; t += 1e-5)
    if (forward(t) > forward(best)) best = t;
  return best;
}
/// The parabola through three rows of a smooth peak sampled at 100 Hz finds it to well
/// under a frame; 1 ms is a tenth of one.
constexpr double kVertexS = 1e-3;

TEST(SwingEvents, KinematicRulesMatchTheSyntheticGaitsClosedForm) {
  const auto swings = findSwings(syntheticGait(0, 2.3), rightColumns(false), std::nullopt);
  ASSERT_EQ(swings.size(), 2u);
  for (int c = 0; c < 2; ++c) {
    EXPECT_NEAR(swings[c].toeOff, syntheticToeOff(c), kVertexS);
    EXPECT_NEAR(swings[c].heelContact, syntheticHeelContact(c), kVertexS);
    EXPECT_EQ(swings[c].toeOffSource, "kinematics");
    EXPECT_EQ(swings[c].heelContactSource, "kinematics");
  }
}

TEST(SwingEvents, ASwingCutByTheFilesStartOrEndIsLeftOut) {
  // Starts mid-rise of the first swing (0.65 s): its toe-off is not in the file.
  const auto late = findSwings(syntheticGait(0.65, 2.3), rightColumns(false), std::nullopt);
  ASSERT_EQ(late.size(), 1u);
  EXPECT_NEAR(late[0].toeOff, syntheticToeOff(1), kVertexS);
  // Ends before the second swing's heel contact (about 1.98 s).
  const auto early = findSwings(syntheticGait(0, 1.9), rightColumns(false), std::nullopt);
  ASSERT_EQ(early.size(), 1u);
  EXPECT_NEAR(early[0].toeOff, syntheticToeOff(0), kVertexS);
  const auto events = findKinematicEvents(syntheticGait(0, 1.9), rightColumns(false));
  EXPECT_EQ(events.toeOffs.size(), 2u);  // the cut swing's toe-off is found, its heel contact is not
  EXPECT_EQ(events.heelContacts.size(), 1u);
}

TEST(SwingEvents, AStanceOnlyRecordingHasNoSwing) {
  // Two strides' worth of the knee's loading flexion alone, 5 to 20 deg (a raised cosine over
  // the first 0.4 s of each second), the hip as in the synthetic gait: no swing in it.
  const auto knee = [](double t) { return phaseOf(t) < 0.4 ? 5 + 7.5 * (1 - std::cos(2 * kPi * phaseOf(t) / 0.4)) : 5.0; };
  const MotionTable stance = makeTable("time\thip_flexion_r\tknee_angle_r", 0, 2, 0.01,
                                       [&](double t) { return number(hipFlexionDeg(t)) + "\t" + number(-knee(t)); }, "stance.mot");
  const SwingEventTimes events = findKinematicEvents(stance, rightColumns(false));
  EXPECT_TRUE(events.toeOffs.empty());
  EXPECT_TRUE(events.heelContacts.empty());
}

/// A GRF table of one foot's vertical force `force(t)` at `rate` Hz.
MotionTable grfTable(double t0, double t1, double step, const std::function<double(double)>& force) {
  return makeTable("time\tground_force_vy\t1_ground_force_vy", t0, t1, step,
                   [&](double t) { return number(force(t)) + "\t0"; }, "grf.mot");
}

TEST(SwingEvents, ForceCrossingsOnLinearRampsAreTheirClosedForm) {
  // 500 N falling linearly to 0 over 0.3-0.4 s, rising again over 0.8-0.9 s.
  const auto force = [](double t) {
    if (t <= 0.3) return 500.0;
    if (t <= 0.4) return 500 * (0.4 - t) / 0.1;
    if (t <= 0.8) return 0.0;
    if (t <= 0.9) return 500 * (t - 0.8) / 0.1;
    return 500.0;
  };
  const MotionTable still = makeTable("time\thip_flexion_r\tknee_angle_r", 0, 1.2, 1.0 / 60, [](double) { return "10\t-5"; }, "still.mot");
  const auto swings = findSwings(still, rightColumns(false), grfTable(0, 1.2, 1.0 / 600, force), GrfSettings{});
  ASSERT_EQ(swings.size(), 1u);
  EXPECT_NEAR(swings[0].toeOff, 0.3 + 0.1 * (500 - 20) / 500, kRoundingS);
  EXPECT_NEAR(swings[0].heelContact, 0.8 + 0.1 * 20 / 500, kRoundingS);
  EXPECT_EQ(swings[0].toeOffSource, "grf");
  EXPECT_EQ(swings[0].heelContactSource, "grf");
  GrfSettings higher;
  higher.thresholdN = 100;
  const auto at100 = findGrfEvents(grfTable(0, 1.2, 1.0 / 600, force), higher);
  ASSERT_EQ(at100.toeOffs.size(), 1u);
  EXPECT_NEAR(at100.toeOffs[0], 0.3 + 0.1 * (500 - 100) / 500, kRoundingS);
}

TEST(SwingEvents, AForceHoveringAtTheThresholdGivesOneEventAfterWhichItStays) {
  // 100 Hz: 500 N, then 25, 15, 25, 15 N (crossings 10 ms apart), then 0 N; 500 N again at 0.81 s.
  const auto force = [](double t) {
    const int row = static_cast<int>(std::lround(t * 100));
    if (row <= 30) return 500.0;
    if (row <= 34) return row % 2 ? 25.0 : 15.0;
    return row <= 80 ? 0.0 : 500.0;
  };
  const MotionTable still = makeTable("time\thip_flexion_r\tknee_angle_r", 0, 1.2, 1.0 / 60, [](double) { return "10\t-5"; }, "still.mot");
  const auto swings = findSwings(still, rightColumns(false), grfTable(0, 1.2, 0.01, force), GrfSettings{});
  ASSERT_EQ(swings.size(), 1u);
  EXPECT_NEAR(swings[0].toeOff, 0.335, kRoundingS);  // the last fall below 20 N (25 -> 15 N at 0.33-0.34 s)
  EXPECT_NEAR(swings[0].heelContact, 0.80 + 0.01 * 20 / 500, kRoundingS);
}

TEST(SwingEvents, ForceWhereItCoversTheTimeKinematicsAfter) {
  // Force plates under the first swing only (0-1.2 s), lifted 0.02 s after the kinematic toe-off.
  const auto force = [](double t) { return t > 0.72 && t < 0.97 ? 0.0 : 600.0; };
  const auto swings = findSwings(syntheticGait(0, 2.3), rightColumns(false), grfTable(0, 1.2, 0.005, force), GrfSettings{});
  ASSERT_EQ(swings.size(), 2u);
  EXPECT_EQ(swings[0].toeOffSource, "grf");
  EXPECT_EQ(swings[0].heelContactSource, "grf");
  EXPECT_GT(swings[0].toeOff, 0.72);
  EXPECT_LT(swings[0].heelContact, 0.97);
  EXPECT_EQ(swings[1].toeOffSource, "kinematics");
  EXPECT_NEAR(swings[1].toeOff, syntheticToeOff(1), kVertexS);
}

/// The distance from each force event inside the kinematics' time to the kinematic event of
/// its kind within kEventMatchS, s (kinematic minus force); `unseen` counts those with none.
std::vector<double> eventDistances(const std::vector<double>& force, const std::vector<double>& kinematic, double t0,
                                   double t1, std::size_t& unseen) {
  std::vector<double> d;
  for (double f : force) {
    if (f < t0 || f > t1) continue;
    const auto near = std::find_if(kinematic.begin(), kinematic.end(), [&](double k) { return std::abs(k - f) <= kEventMatchS; });
    if (near == kinematic.end())
      ++unseen;
    else
      d.push_back(*near - f);
  }
  return d;
}

struct WalkCase {
  std::string ik, side, force;
  std::size_t events;  ///< force events inside the IK's time with a kinematic one
  std::size_t unseen;  ///< force events inside the IK's time of a swing that the file's start cuts
};

// The measured distances are in docs/swing-events.md. The IK files and the GRF file share the
// lab clock: the GRF and the Gait10dof IK start at 0 s, the Gait2392/2354 IK later, and every
// matched event lands within 33 ms. Unseen: the Gait2392 IK starts (0.5 s) after the right
// swing's peak, so its heel contact (0.618 s) has no swing peak before it; the Gait10dof IK
// starts (0 s) mid-rise of the right knee, so its toe-off (0.165 s) has no rise start.
TEST(SwingEvents, KinematicEventsLandWithinTwoFramesOfTheForcePlates) {
  const MotionTable grf = readMotionTable(kGrf);
  const std::vector<WalkCase> cases = {{kIk2392, "r", "ground_force_vy", 2, 1},  {kIk2392, "l", "1_ground_force_vy", 4, 0},
                                       {kIk2354, "r", "ground_force_vy", 2, 0},  {kIk2354, "l", "1_ground_force_vy", 2, 0},
                                       {kIk10dof, "r", "ground_force_vy", 3, 1}, {kIk10dof, "l", "1_ground_force_vy", 4, 0}};
  for (const WalkCase& c : cases) {
    const MotionTable ik = readMotionTable(c.ik);
    MotionColumns columns = rightColumns(true);
    columns.hip = "hip_flexion_" + c.side;
    columns.knee = "knee_angle_" + c.side;
    GrfSettings settings;
    settings.verticalForce = c.force;
    const SwingEventTimes f = findGrfEvents(grf, settings);
    const SwingEventTimes k = findKinematicEvents(ik, columns);
    const double t0 = ik.columns.front().front(), t1 = ik.columns.front().back();
    std::size_t unseen = 0;
    std::vector<double> d = eventDistances(f.toeOffs, k.toeOffs, t0, t1, unseen);
    const std::vector<double> heel = eventDistances(f.heelContacts, k.heelContacts, t0, t1, unseen);
    std::string shown;
    for (double x : d) shown += " toe-off " + std::to_string(std::lround(x * 1000)) + " ms";
    for (double x : heel) shown += " heel contact " + std::to_string(std::lround(x * 1000)) + " ms";
    std::printf("%s %s:%s\n", c.ik.substr(c.ik.rfind('/') + 1).c_str(), c.side.c_str(), shown.c_str());
    d.insert(d.end(), heel.begin(), heel.end());
    EXPECT_EQ(d.size(), c.events) << c.ik << " " << c.side;
    EXPECT_EQ(unseen, c.unseen) << c.ik << " " << c.side;
    for (double x : d) EXPECT_LE(std::abs(x), kTwoFrames) << c.ik << " " << c.side << ":" << shown;
  }
}

TEST(SwingEvents, TheShippedWalkGivesForceSwingsThenKinematicOnes) {
  GrfSettings settings;
  settings.path = kGrf;
  const auto swings = findSwings(readMotionTable(kIk2392), rightColumns(true), settings);
  ASSERT_GE(swings.size(), 2u);
  // The right foot's force falls below 20 N between rows at 1.4083 and 1.4100 s, rises above between 1.8517 and 1.8533 s.
  EXPECT_GT(swings[0].toeOff, 1.4083);
  EXPECT_LT(swings[0].toeOff, 1.4100);
  EXPECT_GT(swings[0].heelContact, 1.8517);
  EXPECT_LT(swings[0].heelContact, 1.8533);
  EXPECT_EQ(swings[0].toeOffSource, "grf");
  for (std::size_t i = 1; i < swings.size(); ++i) {
    EXPECT_GT(swings[i].toeOff, 2.5);  // after the force plates' last row
    EXPECT_EQ(swings[i].toeOffSource, "kinematics");
    EXPECT_EQ(swings[i].heelContactSource, "kinematics");
  }
}

std::string inputErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

TEST(SwingEvents, BadInputNamesFileKeyExpectedAndFound) {
  const MotionTable gait = syntheticGait(0, 2.3);
  GrfSettings wrongLabel;
  wrongLabel.verticalForce = "2_ground_force_vy";
  const std::string noColumn = inputErrorOf([&] { findSwings(gait, rightColumns(false), grfTable(0, 2, 0.01, [](double) { return 0.0; }), wrongLabel); });
  EXPECT_THAT(noColumn, HasSubstr("grf.mot:4: 2_ground_force_vy: column is missing (available: time, ground_force_vy, 1_ground_force_vy)"));

  MotionColumns wrongHip = rightColumns(false);
  wrongHip.hip = "hip_flexion";
  EXPECT_THAT(inputErrorOf([&] { findSwings(gait, wrongHip, std::nullopt); }),
              HasSubstr("gait.mot:4: hip_flexion: column is missing (available: time, hip_flexion_r, knee_angle_r)"));

  const MotionTable later = grfTable(5, 6, 0.01, [](double) { return 0.0; });
  EXPECT_THAT(inputErrorOf([&] { findSwings(gait, rightColumns(false), later, GrfSettings{}); }),
              HasSubstr("grf.mot:5: time: expected times overlapping the kinematics' (gait.mot: 0 to 2.3 s) (got 5 to 6 s)"));

  GrfSettings zero;
  zero.thresholdN = 0;
  EXPECT_THAT(inputErrorOf([&] { findSwings(gait, rightColumns(false), later, zero); }),
              HasSubstr("grf.mot: ground_force_vy: threshold_N: expected a positive force, N (got 0)"));
}

}  // namespace
}  // namespace swingsim
