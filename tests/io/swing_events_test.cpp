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
#include <map>
#include <string>

#include "core/input_error.h"
#include "core/units.h"
#include "opensim_trials.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

using testing::inputErrorOf;
const std::string& kGrf = testing::kWalkGrf;
const std::string& kIk2392 = testing::kWalkIk2392;
const std::string& kIk2354 = testing::kWalkIk2354;
const std::string& kIk10dof = testing::kWalkIk10dof;

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
  return makeTable(
      "time\thip_flexion_r\tknee_angle_r", t0, t1, 0.01,
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
  // A 1 s stride is walking; its rules' events are the closed form less their measured bias.
  const SwingList list = listSwings(syntheticGait(0, 2.3), rightColumns(false), std::nullopt);
  EXPECT_EQ(list.gait, Gait::kWalking);
  const auto& swings = list.swings;
  ASSERT_EQ(swings.size(), 2u);
  for (int c = 0; c < 2; ++c) {
    EXPECT_NEAR(swings[c].toeOff, syntheticToeOff(c) - kWalkingToeOffBiasS, kVertexS);
    EXPECT_NEAR(swings[c].heelContact, syntheticHeelContact(c) - kWalkingHeelContactBiasS, kVertexS);
    EXPECT_EQ(swings[c].toeOffSource, "kinematics");
    EXPECT_EQ(swings[c].heelContactSource, "kinematics");
    EXPECT_FALSE(swings[c].toeOffDisagreement.has_value());
  }
}

TEST(SwingEvents, ASwingCutByTheFilesStartOrEndIsLeftOut) {
  // Starts after the first swing's fastest flexion (0.75 s): its toe-off is not in the file.
  const auto late = findSwings(syntheticGait(0.75, 2.3), rightColumns(false), std::nullopt);
  ASSERT_EQ(late.size(), 1u);
  EXPECT_NEAR(late[0].toeOff, syntheticToeOff(1) - kWalkingToeOffBiasS, kVertexS);
  // Starts mid-rise before it (0.65 s): the knee still speeds up, so the fastest flexion, and
  // the toe-off, lie inside the file: the first swing counts.
  const auto cutRise = findSwings(syntheticGait(0.65, 2.3), rightColumns(false), std::nullopt);
  ASSERT_EQ(cutRise.size(), 2u);
  EXPECT_NEAR(cutRise[0].toeOff, syntheticToeOff(0) - kWalkingToeOffBiasS, kVertexS);
  // Ends before the second swing's heel contact (about 2.02 s).
  const auto early = findSwings(syntheticGait(0, 1.9), rightColumns(false), std::nullopt);
  ASSERT_EQ(early.size(), 1u);
  EXPECT_NEAR(early[0].toeOff, syntheticToeOff(0) - kWalkingToeOffBiasS, kVertexS);
  const auto events = findKinematicEvents(syntheticGait(0, 1.9), rightColumns(false));
  EXPECT_EQ(events.toeOffs.size(), 2u);  // the cut swing's toe-off is found, its heel contact is not
  EXPECT_EQ(events.heelContacts.size(), 1u);
}

TEST(SwingEvents, AStanceOnlyRecordingHasNoSwing) {
  // Two strides' worth of the knee's loading flexion alone, 5 to 20 deg (a raised cosine over
  // the first 0.4 s of each second), the hip as in the synthetic gait: no swing in it.
  const auto knee = [](double t) {
    return phaseOf(t) < 0.4 ? 5 + 7.5 * (1 - std::cos(2 * kPi * phaseOf(t) / 0.4)) : 5.0;
  };
  const MotionTable stance = makeTable(
      "time\thip_flexion_r\tknee_angle_r", 0, 2, 0.01,
      [&](double t) { return number(hipFlexionDeg(t)) + "\t" + number(-knee(t)); }, "stance.mot");
  const SwingEventTimes events = findKinematicEvents(stance, rightColumns(false));
  EXPECT_TRUE(events.toeOffs.empty());
  EXPECT_TRUE(events.heelContacts.empty());
}

/// A GRF table of one foot's vertical force `force(t)` at `rate` Hz.
MotionTable grfTable(double t0, double t1, double step, const std::function<double(double)>& force) {
  return makeTable(
      "time\tground_force_vy\t1_ground_force_vy", t0, t1, step, [&](double t) { return number(force(t)) + "\t0"; },
      "grf.mot");
}

/// The synthetic gait's first swing, as the walking rules place it, s.
const double kSynthToeOff = syntheticToeOff(0) - kWalkingToeOffBiasS;
const double kSynthHeel = syntheticHeelContact(0) - kWalkingHeelContactBiasS;

TEST(SwingEvents, ForceCrossingsOnLinearRampsAreTheirClosedForm) {
  // 500 N falling linearly to 0 over the 0.1 s before the kinematic toe-off, rising again over
  // the 0.1 s after the kinematic heel contact: crossings 4 ms and 4 ms from them.
  const double fall = kSynthToeOff - 0.1, rise = kSynthHeel;
  const auto force = [&](double t) {
    if (t <= fall) return 500.0;
    if (t <= fall + 0.1) return 500 * (fall + 0.1 - t) / 0.1;
    if (t <= rise) return 0.0;
    if (t <= rise + 0.1) return 500 * (t - rise) / 0.1;
    return 500.0;
  };
  const auto swings =
      findSwings(syntheticGait(0, 1.6), rightColumns(false), grfTable(0, 1.6, 1.0 / 600, force), GrfSettings{});
  ASSERT_EQ(swings.size(), 1u);
  EXPECT_NEAR(swings[0].toeOff, fall + 0.1 * (500 - 20) / 500, kRoundingS);
  EXPECT_NEAR(swings[0].heelContact, rise + 0.1 * 20 / 500, kRoundingS);
  EXPECT_EQ(swings[0].toeOffSource, "grf");
  EXPECT_EQ(swings[0].heelContactSource, "grf");
  ASSERT_TRUE(swings[0].toeOffDisagreement.has_value());
  EXPECT_NEAR(*swings[0].toeOffDisagreement, -0.1 * 20 / 500, kVertexS);
  EXPECT_NEAR(*swings[0].heelContactDisagreement, 0.1 * 20 / 500, kVertexS);
  GrfSettings higher;
  higher.thresholdN = 100;
  const auto at100 = findGrfEvents(grfTable(0, 1.6, 1.0 / 600, force), higher);
  ASSERT_EQ(at100.toeOffs.size(), 1u);
  EXPECT_NEAR(at100.toeOffs[0], fall + 0.1 * (500 - 100) / 500, kRoundingS);
}

TEST(SwingEvents, AForceHoveringAtTheThresholdGivesOneEventAfterWhichItStays) {
  // 100 Hz: 500 N, then 25, 15, 25, 15 N (crossings 10 ms apart) from 0.71 s, then 0 N; 500 N again at 1.03 s.
  const auto force = [](double t) {
    const int row = static_cast<int>(std::lround(t * 100));
    if (row <= 70) return 500.0;
    if (row <= 74) return row % 2 ? 25.0 : 15.0;
    return row <= 102 ? 0.0 : 500.0;
  };
  const auto swings =
      findSwings(syntheticGait(0, 1.6), rightColumns(false), grfTable(0, 1.6, 0.01, force), GrfSettings{});
  ASSERT_EQ(swings.size(), 1u);
  EXPECT_NEAR(swings[0].toeOff, 0.735, kRoundingS);  // the last fall below 20 N (25 -> 15 N at 0.73-0.74 s)
  EXPECT_NEAR(swings[0].heelContact, 1.02 + 0.01 * 20 / 500, kRoundingS);
}

TEST(SwingEvents, ForceWhereItCoversTheTimeKinematicsAfter) {
  // Force plates under the first swing only (0-1.2 s), lifted 0.01 s before the kinematic toe-off.
  const auto force = [](double t) { return t > kSynthToeOff - 0.01 && t < kSynthHeel ? 0.0 : 600.0; };
  const auto swings =
      findSwings(syntheticGait(0, 2.3), rightColumns(false), grfTable(0, 1.2, 0.005, force), GrfSettings{});
  ASSERT_EQ(swings.size(), 2u);
  EXPECT_EQ(swings[0].toeOffSource, "grf");
  EXPECT_EQ(swings[0].heelContactSource, "grf");
  EXPECT_LT(swings[0].toeOff, kSynthToeOff);
  EXPECT_GT(swings[0].heelContact, kSynthHeel - 0.005);
  EXPECT_EQ(swings[1].toeOffSource, "kinematics");
  EXPECT_NEAR(swings[1].toeOff, syntheticToeOff(1) - kWalkingToeOffBiasS, kVertexS);
}

/// The distance from each force event inside the kinematics' time to the kinematic event of
/// its kind within `window`, s (kinematic minus force); `unseen` counts those with none.
std::vector<double> eventDistances(const std::vector<double>& force, const std::vector<double>& kinematic, double t0,
                                   double t1, std::size_t& unseen, double window = 0.15) {
  std::vector<double> d;
  for (double f : force) {
    if (f < t0 || f > t1) continue;
    const auto near =
        std::find_if(kinematic.begin(), kinematic.end(), [&](double k) { return std::abs(k - f) <= window; });
    if (near == kinematic.end()) {
      std::printf("  unseen force event at %.4f s\n", f);
      ++unseen;
    } else
      d.push_back(*near - f);
  }
  return d;
}

const std::string& kRajagopalIk = testing::kRajagopalRunIk;
const std::string& kRajagopalGrf = testing::kRajagopalRunGrf;
const std::string& kHamnerIk = testing::kHamnerRunIk;
const std::string& kHamnerGrf = testing::kHamnerRunGrf;

struct TrialCase {
  std::string subject, ik, grf, side, force;
  double kneeSign;
  Gait gait;
  std::size_t events;  ///< force events inside the IK's time with a kinematic one
  std::size_t unseen;  ///< force events inside the IK's time of a swing that the file's ends cut
};

MotionColumns legColumns(const std::string& side, double kneeSign) {
  MotionColumns columns = rightColumns(true);
  columns.hip = "hip_flexion_" + side;
  columns.knee = "knee_angle_" + side;
  columns.kneeSign = kneeSign;
  return columns;
}

const std::vector<TrialCase>& publicTrials() {
  static const std::vector<TrialCase> cases = {
      {"walk", kIk2392, kGrf, "r", "ground_force_vy", -1, Gait::kWalking, 2, 1},
      {"walk", kIk2392, kGrf, "l", "1_ground_force_vy", -1, Gait::kWalking, 4, 0},
      {"walk", kIk2354, kGrf, "r", "ground_force_vy", -1, Gait::kWalking, 2, 0},
      {"walk", kIk2354, kGrf, "l", "1_ground_force_vy", -1, Gait::kWalking, 2, 0},
      {"walk", kIk10dof, kGrf, "r", "ground_force_vy", -1, Gait::kWalking, 4, 0},
      {"walk", kIk10dof, kGrf, "l", "1_ground_force_vy", -1, Gait::kWalking, 4, 0},
      {"rajagopal", kRajagopalIk, kRajagopalGrf, "r", "R_ground_force_vy", 1, Gait::kRunning, 14, 0},
      {"rajagopal", kRajagopalIk, kRajagopalGrf, "l", "L_ground_force_vy", 1, Gait::kRunning, 13, 1},
      {"hamner", kHamnerIk, kHamnerGrf, "r", "ground_force_vy", -1, Gait::kRunning, 28, 0},
      {"hamner", kHamnerIk, kHamnerGrf, "l", "1_ground_force_vy", -1, Gait::kRunning, 28, 2},
  };
  return cases;
}

/// Each kinematic event's distance to the force's, s (kinematic minus force), bias-corrected.
struct Distances {
  std::vector<double> toeOff, heel;
};

Distances distancesOf(const TrialCase& c, std::size_t& unseen) {
  const MotionTable grf = readMotionTable(c.grf);
  const MotionTable ik = readMotionTable(c.ik);
  GrfSettings settings;
  settings.verticalForce = c.force;
  const SwingEventTimes f = findGrfEvents(grf, settings);
  const SwingEventTimes k = findKinematicEvents(ik, legColumns(c.side, c.kneeSign));
  const double t0 = std::max(ik.columns.front().front(), grf.columns.front().front());
  const double t1 = std::min(ik.columns.front().back(), grf.columns.front().back());
  return {eventDistances(f.toeOffs, k.toeOffs, t0, t1, unseen),
          eventDistances(f.heelContacts, k.heelContacts, t0, t1, unseen)};
}

double meanOf(const std::vector<double>& x) {
  double sum = 0;
  for (double v : x) sum += v;
  return x.empty() ? 0 : sum / static_cast<double>(x.size());
}

// The measured distances are in docs/swing-events.md (this test prints them). The IK and GRF
// files of each trial share the lab clock. Unseen: the Gait2392 IK starts (0.5 s) after the
// right swing's peak, so its heel contact (0.618 s) has no swing peak before it (the Gait10dof
// IK starts (0 s) mid-rise of the right knee: its toe-off (0.165 s) is the fastest flexion
// of the rise inside the file, seen); the runs' files end (4.99 s, 9.97 s) before the swing peak after a left toe-off
// (4.892 s, 9.963 s), and Hamner's starts (0 s) after the left swing's peak, before its heel
// contact (0.067 s). The gait is detected from the stride on every file.
TEST(SwingEvents, KinematicRulesAgainstTheForcePlatesPerGait) {
  std::map<std::string, Distances> bySubject;
  for (const TrialCase& c : publicTrials()) {
    EXPECT_EQ(listSwings(readMotionTable(c.ik), legColumns(c.side, c.kneeSign), std::nullopt).gait, c.gait) << c.ik;
    std::size_t unseen = 0;
    const Distances d = distancesOf(c, unseen);
    std::string shown;
    for (double x : d.toeOff) shown += " " + std::to_string(std::lround(x * 1000));
    shown += " | heel contact ms:";
    for (double x : d.heel) shown += " " + std::to_string(std::lround(x * 1000));
    std::printf("%s %s toe-off ms:%s\n", c.ik.substr(c.ik.rfind('/') + 1).c_str(), c.side.c_str(), shown.c_str());
    EXPECT_EQ(d.toeOff.size() + d.heel.size(), c.events) << c.ik << " " << c.side;
    EXPECT_EQ(unseen, c.unseen) << c.ik << " " << c.side;
    const double accuracy = c.gait == Gait::kRunning ? kRunningAccuracyS : kWalkingAccuracyS;
    for (const auto* list : {&d.toeOff, &d.heel})
      for (double x : *list) EXPECT_LE(std::abs(x), accuracy + 5e-4) << c.ik << " " << c.side << ":" << shown;
    Distances& s = bySubject[c.subject];
    s.toeOff.insert(s.toeOff.end(), d.toeOff.begin(), d.toeOff.end());
    s.heel.insert(s.heel.end(), d.heel.begin(), d.heel.end());
  }
  // The bias left after the correction, per subject: the walk's is in-sample (the correction
  // was measured on it), the runs' each within a frame (10 ms at 100 Hz) of zero although each
  // subject's own bias differs from the pooled one that was removed.
  for (const auto& [subject, d] : bySubject) {
    std::printf("%s: mean after correction: toe-off %+.1f ms (n %zu), heel contact %+.1f ms (n %zu)\n", subject.c_str(),
                meanOf(d.toeOff) * 1000, d.toeOff.size(), meanOf(d.heel) * 1000, d.heel.size());
    EXPECT_LT(std::abs(meanOf(d.toeOff)), 0.005) << subject;
    EXPECT_LT(std::abs(meanOf(d.heel)), 0.005) << subject;
  }
}

// A stated gait that detection (the stride, or one swing's knee peak) contradicts is kept (the
// user may know better) and said; a stated gait detection agrees with says nothing.
TEST(SwingEvents, AStatedGaitThatDetectionContradictsIsSaid) {
  for (const TrialCase& c : publicTrials()) {
    SCOPED_TRACE(c.ik);
    const MotionTable ik = readMotionTable(c.ik);
    const MotionColumns columns = legColumns(c.side, c.kneeSign);
    const Gait other = c.gait == Gait::kRunning ? Gait::kWalking : Gait::kRunning;
    const SwingList wrong = listSwings(ik, columns, std::nullopt, other);
    EXPECT_EQ(wrong.gait, other);
    EXPECT_EQ(wrong.gaitBasis, "stated");
    const std::string expected = std::string("the gait is stated as ") + gaitName(other) +
                                 " but the trial looks like " + gaitName(c.gait) + " (";
    bool said = false;
    for (const auto& note : wrong.notes) said = said || note.rfind(expected, 0) == 0;
    std::string all;
    for (const auto& note : wrong.notes) all += "\n  " + note;
    EXPECT_TRUE(said) << "no note begins \"" << expected << "\"; notes:" << all;
    for (const auto& note : listSwings(ik, columns, std::nullopt, c.gait).notes)
      EXPECT_EQ(note.find("the gait is stated as"), std::string::npos) << note;
  }
}

// A force file on a clock 60 ms late (another system's trigger) is refused, and the message
// says by how much and what to shift; the shift it gives makes the files agree.
TEST(SwingEvents, AClockOffsetIsRefusedWithTheShiftThatFixesIt) {
  const MotionTable ik = readMotionTable(kIk2392);
  const MotionColumns columns = legColumns("l", -1);
  GrfSettings settings;
  settings.path = kGrf;
  settings.verticalForce = "1_ground_force_vy";
  MotionTable late = readMotionTable(kGrf);
  for (double& time : late.columns.front()) time += 0.060;
  std::string message;
  try {
    listSwings(ik, columns, late, settings);
  } catch (const InputError& e) {
    message = e.what();
  }
  ASSERT_FALSE(message.empty()) << "a force 60 ms late was accepted";
  EXPECT_NE(message.find("later than the kinematics'"), std::string::npos) << message;
  const std::string cue = "shift the force file's time column by ";
  const std::size_t at = message.find(cue);
  ASSERT_NE(at, std::string::npos) << message;
  const double shift = std::stod(message.substr(at + cue.size()));
  EXPECT_NEAR(shift, -0.060, 0.025) << "the kinematic events' own accuracy (docs/swing-events.md)";
  MotionTable shifted = late;
  for (double& time : shifted.columns.front()) time += shift;
  EXPECT_NO_THROW(listSwings(ik, columns, shifted, settings));
}

TEST(SwingEvents, TheFastestFlexionRuleWouldPlaceARunnersToeOffLate) {
  // Why running has a rule of its own: the walking rule on a run lands 60-120 ms late.
  const MotionTable ik = readMotionTable(kHamnerIk);
  const MotionTable grf = readMotionTable(kHamnerGrf);
  GrfSettings settings;
  const SwingEventTimes f = findGrfEvents(grf, settings);
  const SwingEventTimes walkingRule = findKinematicEvents(ik, legColumns("r", -1), Gait::kWalking);
  std::size_t unseen = 0;
  const std::vector<double> d = eventDistances(f.toeOffs, walkingRule.toeOffs, 0, 9.97, unseen);
  ASSERT_GE(d.size(), 10u);
  for (double x : d) EXPECT_GT(x - kWalkingToeOffBiasS, 0.05);
}

TEST(SwingEvents, TheShippedWalkGivesForceSwingsThenKinematicOnes) {
  GrfSettings settings;
  settings.path = kGrf;
  const auto swings = findSwings(readMotionTable(kIk2392), rightColumns(true), settings);
  ASSERT_GE(swings.size(), 2u);
  // The right foot's force falls below 20 N between rows at 1.4083 and 1.4100 s, rises above between 1.8517 and 1.8533
  // s.
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

TEST(SwingEvents, BadInputNamesFileKeyExpectedAndFound) {
  const MotionTable gait = syntheticGait(0, 2.3);
  GrfSettings wrongLabel;
  wrongLabel.verticalForce = "2_ground_force_vy";
  const std::string noColumn = inputErrorOf(
      [&] { findSwings(gait, rightColumns(false), grfTable(0, 2, 0.01, [](double) { return 0.0; }), wrongLabel); });
  EXPECT_THAT(
      noColumn,
      HasSubstr(
          "grf.mot:4: 2_ground_force_vy: column is missing (available: time, ground_force_vy, 1_ground_force_vy)"));

  MotionColumns wrongHip = rightColumns(false);
  wrongHip.hip = "hip_flexion";
  EXPECT_THAT(inputErrorOf([&] { findSwings(gait, wrongHip, std::nullopt); }),
              HasSubstr("gait.mot:4: hip_flexion: column is missing (available: time, hip_flexion_r, knee_angle_r)"));

  const MotionTable later = grfTable(5, 6, 0.01, [](double) { return 0.0; });
  EXPECT_THAT(
      inputErrorOf([&] { findSwings(gait, rightColumns(false), later, GrfSettings{}); }),
      HasSubstr("grf.mot:5: time: expected times overlapping the kinematics' (gait.mot: 0 to 2.3 s) (got 5 to 6 s)"));

  GrfSettings zero;
  zero.thresholdN = 0;
  EXPECT_THAT(inputErrorOf([&] { findSwings(gait, rightColumns(false), later, zero); }),
              HasSubstr("grf.mot: ground_force_vy: threshold_N: expected a positive force, N (got 0)"));

  // Issue 57: a threshold above the force's peak found no event and said only "no complete
  // swing" (rc 0); it is refused naming the peak.
  const auto stance = [](double t) { return t < 0.6 || t > 1.0 ? 700.0 : 0.0; };
  GrfSettings aboveThePeak;
  aboveThePeak.thresholdN = 900;
  const std::string message = "threshold_N: expected a threshold below the force's peak, 700 N (got 900 N";
  EXPECT_THAT(
      inputErrorOf([&] { findSwings(gait, rightColumns(false), grfTable(0, 2.3, 0.002, stance), aboveThePeak); }),
      HasSubstr("grf.mot: ground_force_vy: " + message));
  EXPECT_THAT(inputErrorOf([&] { findGrfEvents(grfTable(0, 2.3, 0.002, stance), aboveThePeak); }), HasSubstr(message));
}

/// `table` from its row `first` on: a recording started later.
MotionTable cutFrom(const MotionTable& table, std::size_t first) {
  MotionTable out = table;
  for (auto& c : out.columns) c.erase(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(first));
  out.rowLines.erase(out.rowLines.begin(), out.rowLines.begin() + static_cast<std::ptrdiff_t>(first));
  return out;
}

// `swing: K` without a force file: the kinematics number each swing as the force plates do,
// or refuse the number. Every public trial, both feet, its IK started at every frame of its
// first stride (as if the recording had begun later): where the kinematic list is not
// refused, its K-th swing is the force list's K-th (the same toe-off within 50 ms); where
// it is, selectSwing says why and what to give instead, and the force list selects.
TEST(SwingEvents, KinematicNumberingIsTheForcesOrRefused) {
  int refused = 0, checked = 0;
  for (const TrialCase& c : publicTrials()) {
    const MotionTable ik = readMotionTable(c.ik), grf = readMotionTable(c.grf);
    const MotionColumns columns = legColumns(c.side, c.kneeSign);
    GrfSettings settings;
    settings.path = c.grf;
    settings.verticalForce = c.force;
    const std::vector<double>& t = ik.columns.front();
    const std::size_t stride =
        static_cast<std::size_t>(std::lround((c.gait == Gait::kRunning ? 0.7 : 1.2) / (t[1] - t[0])));
    for (std::size_t first = 0; first < stride && first + 10 < t.size(); first += c.subject == "walk" ? 1 : 3) {
      const MotionTable cut = cutFrom(ik, first);
      const SwingList kin = listSwings(cut, columns, std::nullopt, c.gait);
      SwingList force;
      try {
        force = listSwings(cut, columns, grf, settings, c.gait);
      } catch (const InputError&) {  // the force file's own checks refuse this cut (too little stance left)
        continue;
      }
      const std::string where = c.ik + " " + c.side + " from " + std::to_string(cut.columns.front().front()) + " s";
      EXPECT_TRUE(force.numberingAmbiguity.empty()) << where;  // the force covers every trial's start
      if (!kin.numberingAmbiguity.empty()) {
        ++refused;
        EXPECT_THAT(inputErrorOf([&] { selectSwing(kin, cut, columns.knee, 1); }),
                    HasSubstr("number this file's swings one apart from the kinematics: give its force file"))
            << where;
        continue;
      }
      const std::size_t n = std::min(kin.swings.size(), force.swings.size());
      EXPECT_GE(n + 1, force.swings.size()) << where;  // at most the last swing, cut by the end, differs
      for (std::size_t k = 0; k < n; ++k, ++checked)
        EXPECT_NEAR(kin.swings[k].toeOff, force.swings[k].toeOff, kEventToleranceS) << where << " swing " << k + 1;
    }
  }
  std::printf("numbered as the force: %d swings; refused: %d starts\n", checked, refused);
  EXPECT_GT(checked, 100);
  EXPECT_GT(refused, 0);
}

}  // namespace
}  // namespace swingsim
