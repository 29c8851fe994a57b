// Every bad-input case of the participant file gives `file:line: key: what (got V)`.
#include "io/participant_loader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <regex>

#include "../cli/run_swingsim.h"
#include "core/input_error.h"
#include "core/output_files.h"
#include "core/units.h"
#include "io/motion_file.h"
#include "io/swing_events.h"
#include "participant_text.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

const std::string& kGood = testing::kParticipantText;

std::string errorFor(const std::string& text) { return testing::participantError(text); }
std::string replaced(const std::string& from, const std::string& to) { return testing::replacedIn(kGood, from, to); }

TEST(ParticipantLoader, GoodFileLoadsWithDefaultsAndResolvedPaths) {
  Participant p = parseParticipant(kGood, "participants/px.yaml");
  EXPECT_EQ(p.name, "PX");
  EXPECT_DOUBLE_EQ(p.thigh.length, 0.410);
  EXPECT_DOUBLE_EQ(p.kneeFriction, 10);
  EXPECT_EQ(p.kneeModelPath, "participants/../models/damping-table-default.yaml");
  EXPECT_EQ(p.comRule, ComRule::kFixedFromProximal);
}

TEST(ParticipantLoader, BundledParticipantsLoad) {
  for (const char* f : {"participants/p1.yaml", "participants/p2.yaml", "participants/p3.yaml", "participants/p4.yaml",
                        "participants/winter.yaml"}) {
    EXPECT_NO_THROW(loadParticipant(f)) << f;
  }
}

struct BadCase {
  const char* what;
  std::string text;
  const char* expected;
};

TEST(ParticipantLoader, EveryBadInputNamesFileLineKeyAndValue) {
  const std::vector<BadCase> cases = {
      {"unknown key", kGood + "colour: blue\n", "participants/px.yaml:16: colour: unknown key"},
      {"missing key", replaced("knee_friction_Nm: 10\n", ""), "knee_friction_Nm: required key is missing"},
      {"wrong type", replaced("body_mass_kg: 75", "body_mass_kg: heavy"),
       "participants/px.yaml:3: body_mass_kg: expected a number (got 'heavy')"},
      {"NaN", replaced("mass_kg: 3.350", "mass_kg: .nan"),
       "px.yaml:5: segments.thigh.mass_kg: expected a finite number"},
      {"inf", replaced("length_m: 0.515", "length_m: .inf"), "segments.shank.length_m: expected a finite number"},
      {"negative mass", replaced("mass_kg: 0.785", "mass_kg: -0.785"),
       "segments.shank.mass_kg: must be positive (got -0.785)"},
      {"negative length", replaced("length_m: 0.240", "length_m: -0.24"),
       "segments.foot.length_m: must be positive (got -0.24)"},
      {"negative inertia", replaced("inertia_kgm2: 0.0264", "inertia_kgm2: -1"),
       "segments.thigh.inertia_kgm2: must be positive (got -1)"},
      {"COM outside segment", replaced("com_from_distal_m: 0.284", "com_from_distal_m: 0.5"),
       "segments.thigh.com_from_distal_m: the COM must lie on the segment"},
      {"comma decimal", replaced("height_m: 1.80", "height_m: 1,80"),
       "height_m: expected a number with a decimal point"},
      {"duplicate key", kGood + "name: PY\n", "px.yaml:16: name: key appears twice"},
      {"bad choice", kGood + "com_rule: middle\n",
       "com_rule: expected one of: fixed_from_proximal, proportional (got 'middle')"},
      {"non-increasing hip table",
       replaced("  profile: biphasic_sine\n  flexion_amplitude_Nm: 30\n  flexion_duration_s: 0.2\n  "
                "extension_amplitude_Nm: 15\n  extension_duration_s: 0.2\n",
                "  profile: table\n  time_s: [0, 0.1, 0.1, 0.3]\n  moment_Nm: [0, 20, 10, 0]\n"),
       "hip_moment.time_s: times must strictly increase (got 0.1 after 0.1)"},
      {"table length mismatch",
       replaced("  profile: biphasic_sine\n  flexion_amplitude_Nm: 30\n  flexion_duration_s: 0.2\n  "
                "extension_amplitude_Nm: 15\n  extension_duration_s: 0.2\n",
                "  profile: table\n  time_s: [0, 0.1, 0.2]\n  moment_Nm: [0, 20]\n"),
       "hip_moment.moment_Nm: expected one moment per time (3) (got 2 values)"},
      {"empty file", "", "expected a YAML mapping"},
      {"binary garbage", std::string("\x01\x02\xff\xfe\x00zz", 7), "px.yaml:"},
  };
  for (const auto& c : cases) {
    EXPECT_THAT(errorFor(c.text), HasSubstr(c.expected)) << c.what;
  }
}

TEST(ParticipantLoader, MessagesFollowFileLineKeyFormat) {
  const std::regex format(R"(^participants/px\.yaml:[0-9]+: [a-z_.\[\]0-9]+: .+ \(got .+\)$)");
  EXPECT_TRUE(std::regex_match(errorFor(replaced("body_mass_kg: 75", "body_mass_kg: -75")), format))
      << errorFor(replaced("body_mass_kg: 75", "body_mass_kg: -75"));
}

TEST(ParticipantLoader, LoweringBeyondTheShankIsAClearError) {
  Participant p = loadParticipant("participants/p1.yaml");
  EXPECT_NO_THROW(calcLegGeometry(p, calcMaxLowering(p)));
  try {
    calcLegGeometry(p, 0.6);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("leaves no room for the shank of P1"));
    EXPECT_THAT(e.what(), HasSubstr("(got 0.6)"));
  }
}

// Round trip (MuJoCo's xml write/read tests): every participant file of the repository, and
// one with a tabulated hip moment, loads -> writes -> loads to the same participant, and
// writing it again gives the same text.
TEST(ParticipantFormat, LoadWriteLoadGivesTheSameParticipant) {
  std::vector<Participant> participants;
  for (const char* f : {"participants/p1.yaml", "participants/p2.yaml", "participants/p3.yaml", "participants/p4.yaml",
                        "participants/winter.yaml"})  // winter: the measured thigh drive
    participants.push_back(loadParticipant(f));
  Participant table = participants.front();
  table.hipMoment.kind = HipMomentProfile::Kind::kTable;
  table.hipMoment.times = {0, 0.1, 0.25};
  table.hipMoment.moments = {10, -3.5, 0};
  table.comRule = ComRule::kProportional;
  table.initial.kneeFlexionRate = 1.234;
  participants.push_back(table);
  for (const Participant& p : participants) {
    const std::string text = formatParticipantYaml(p, "participants");
    const Participant back = parseParticipant(text, "participants/roundtrip.yaml");
    EXPECT_EQ(formatParticipantYaml(back, "participants"), text) << p.name;
    EXPECT_EQ(back.name, p.name);
    EXPECT_EQ(back.source, p.source);
    EXPECT_EQ(back.kneeModelPath, p.kneeModelPath);
    EXPECT_EQ(back.comRule, p.comRule);
    EXPECT_EQ(back.hipMoment.kind, p.hipMoment.kind);
    EXPECT_EQ(back.hipMoment.times, p.hipMoment.times);
    EXPECT_EQ(back.hipMoment.moments, p.hipMoment.moments);
    EXPECT_EQ(back.drive, p.drive) << p.name;
    EXPECT_EQ(back.thighKinematics.hipFlexion, p.thighKinematics.hipFlexion) << p.name;
    for (const auto& [a, b] :
         std::vector<std::pair<double, double>>{{back.height, p.height},
                                                {back.bodyMass, p.bodyMass},
                                                {back.thigh.mass, p.thigh.mass},
                                                {back.shank.comFromDistal, p.shank.comFromDistal},
                                                {back.foot.inertia, p.foot.inertia},
                                                {back.kneeFriction, p.kneeFriction},
                                                {back.initial.hipFlexion, p.initial.hipFlexion},
                                                {back.initial.kneeFlexionRate, p.initial.kneeFlexionRate},
                                                {back.hipRange.maxFlexion, p.hipRange.maxFlexion},
                                                {back.swingEnd.zoneOfStability, p.swingEnd.zoneOfStability},
                                                {back.hipMoment.timeScale, p.hipMoment.timeScale},
                                                {back.hipMoment.flexionAmplitude, p.hipMoment.flexionAmplitude},
                                                {back.minShankLength, p.minShankLength}})
      EXPECT_EQ(a, b) << p.name;  // exact: numbers are written to read back to the same double
  }
}

TEST(ParticipantLoader, HipOffsetInPelvisReadsAndWritesBack) {
  EXPECT_FALSE(parseParticipant(kGood, "participants/px.yaml").hipOffsetInPelvis);
  const Participant p =
      parseParticipant(kGood + "hip_offset_in_pelvis_m: [-0.0724, -0.0677]\n", "participants/px.yaml");
  ASSERT_TRUE(p.hipOffsetInPelvis);
  EXPECT_DOUBLE_EQ((*p.hipOffsetInPelvis)[0], -0.0724);
  EXPECT_DOUBLE_EQ((*p.hipOffsetInPelvis)[1], -0.0677);
  const std::string text = formatParticipantYaml(p, "participants");
  EXPECT_THAT(text, HasSubstr("hip_offset_in_pelvis_m: [-0.0724, -0.0677]"));
  EXPECT_EQ(parseParticipant(text, "participants/px.yaml").hipOffsetInPelvis, p.hipOffsetInPelvis);
}

TEST(ParticipantLoader, HipOffsetInPelvisNeedsTwoNumbersInMetres) {
  EXPECT_THAT(errorFor(kGood + "hip_offset_in_pelvis_m: [-0.07]\n"),
              HasSubstr("hip_offset_in_pelvis_m: expected [x, y] in metres, each within 1.5 m (got 1 values)"));
  EXPECT_THAT(errorFor(kGood + "hip_offset_in_pelvis_m: [-72.4, -67.7]\n"),
              HasSubstr("hip_offset_in_pelvis_m: expected [x, y] in metres"));
}

// ---- thigh_kinematics from OpenSim pipeline output --------------------------------------

const std::string kRoot = SWINGSIM_SOURCE_DIR;
const std::string kGait10Ik = kRoot + "/tests/data/opensim-gait10dof/subject01_walk_IK.mot";

/// Winter's participant (a thigh-driven swing) with `thigh` as its thigh_kinematics value.
std::string winterWith(const std::string& thigh) {
  std::string text = readFile(kRoot + "/participants/winter.yaml");
  const std::string key = "thigh_kinematics: ../studies/data/winter-swing/swing1.csv";
  const auto at = text.find(key);
  EXPECT_NE(at, std::string::npos);
  return text.replace(at, key.size(), "thigh_kinematics: " + thigh);
}

std::string thighError(const std::string& thigh) {
  try {
    parseParticipant(winterWith(thigh), kRoot + "/participants/w.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// Rows are kept as read: only the degree-to-radian product rounds (a few ulps).
constexpr double kRowTol = 1e-12;

TEST(ParticipantThighMotion, PlainMotFileReadsOpenSimRightLegWithThePelvis) {
  const Participant p = parseParticipant(winterWith(kGait10Ik), kRoot + "/participants/w.yaml");
  const MotionTable table = readMotionTable(kGait10Ik);
  const ThighKinematics& t = p.thighKinematics;
  EXPECT_FALSE(t.columns.has_value());
  ASSERT_EQ(t.time.size(), table.rows());  // the whole file, from its first row
  ASSERT_EQ(t.pelvisTilt.size(), table.rows());
  for (std::size_t r = 0; r < table.rows(); r += 25) {
    EXPECT_NEAR(t.time[r], table.column("time")[r] - table.column("time")[0], kRowTol);
    EXPECT_NEAR(t.hipFlexion[r], (table.column("hip_flexion_r")[r] + table.column("pelvis_tilt")[r]) * kDegToRad,
                kRowTol);
    EXPECT_EQ(t.pelvisX[r], table.column("pelvis_tx")[r]);  // metres, not converted
    EXPECT_EQ(t.pelvisY[r], table.column("pelvis_ty")[r]);
  }
}

TEST(ParticipantThighMotion, MapFormCutsTheFileAndRoundTrips) {
  const Participant p =
      parseParticipant(winterWith("{file: " + kGait10Ik +
                                  ", hip: hip_flexion_r, knee: knee_angle_r, knee_sign: -1, toe_off_s: 1.35, "
                                  "heel_contact_s: 1.8}"),
                       kRoot + "/participants/w.yaml");
  const ThighKinematics& t = p.thighKinematics;
  ASSERT_TRUE(t.columns.has_value());
  EXPECT_EQ(t.columns->toeOffTime, 1.35);
  EXPECT_TRUE(t.pelvisTilt.empty());  // not named in the map
  EXPECT_DOUBLE_EQ(t.time.back(), 1.8 - 1.35);
  EXPECT_EQ(t.time.front(), 0);

  const std::string dir = kRoot + "/participants";
  const std::string text = formatParticipantYaml(p, dir);
  EXPECT_THAT(text, HasSubstr("thigh_kinematics: {file: ../tests/data/opensim-gait10dof/subject01_walk_IK.mot"));
  const Participant back = parseParticipant(text, dir + "/roundtrip.yaml");
  EXPECT_EQ(formatParticipantYaml(back, dir), text);
  EXPECT_EQ(back.thighKinematics.hipFlexion, t.hipFlexion);
  EXPECT_EQ(back.thighKinematics.columns->heelContactTime, 1.8);
}

TEST(ParticipantThighMotion, SwingNumberCutsTheKthSwingAndKeepsTheKnee) {
  // `swing: K` as a study's record takes it: the K-th complete swing the file holds.
  const std::string map =
      "{file: " + kGait10Ik + ", hip: hip_flexion_r, knee: knee_angle_r, knee_sign: -1, pelvis_tilt: pelvis_tilt";
  const Participant p = parseParticipant(winterWith(map + ", swing: 1}"), kRoot + "/participants/w.yaml");
  const ThighKinematics& t = p.thighKinematics;
  MotionColumns columns = *t.columns;
  const MotionTable table = readMotionTable(kGait10Ik);
  const FoundSwing first = listSwings(table, columns, std::nullopt).swings.at(0);
  EXPECT_NEAR(t.time.back(), first.duration(), 1e-12);
  EXPECT_EQ(t.swing, 1);
  // The measured knee comes with the thigh: the knee's state at toe-off (leg/toe_off_state.h).
  ASSERT_EQ(t.kneeFlexion.size(), t.time.size());
  EXPECT_GT(t.kneeFlexion.front(), 20 * kDegToRad);  // the knee has begun to flex at toe-off
  const std::string dir = kRoot + "/participants";
  const std::string text = formatParticipantYaml(p, dir);
  EXPECT_THAT(text, HasSubstr("swing: 1}"));
  EXPECT_EQ(parseParticipant(text, dir + "/roundtrip.yaml").thighKinematics.time, t.time);
  EXPECT_THAT(thighError(map + ", swing: 1, toe_off_s: 0.2}"), HasSubstr("thigh_kinematics.swing: either swing"));
  EXPECT_THAT(thighError(map + ", swing: 4}"),
              HasSubstr("subject01_walk_IK.mot: swing: expected a swing number from 1 to 2"));
}

TEST(ParticipantThighMotion, TheStatedGaitPicksTheSwingsEventRules) {
  // One running swing of the public Rajagopal run: stated running, the running rules (toe-off
  // at the knee's extension minimum); stated walking, the walking rules, whose toe-off lands
  // 60-120 ms later in a run, so the swing is shorter.
  const std::string map = "{file: " + kRoot +
                          "/tests/data/opensim-running/rajagopal_subject01_run_ik.mot, hip: hip_flexion_r, "
                          "knee: knee_angle_r, knee_sign: 1, pelvis_tilt: pelvis_tilt, swing: 1}";
  const auto durationAt = [&](const std::string& gait) {
    std::string text = winterWith(map);
    const std::string stated = "toe_clearance:\n  gait: walking";
    const auto at = text.find(stated);
    EXPECT_NE(at, std::string::npos);
    text.replace(at, stated.size(), "toe_clearance:\n  gait: " + gait);
    return parseParticipant(text, kRoot + "/participants/w.yaml").thighKinematics.time.back();
  };
  const MotionTable table = readMotionTable(kRoot + "/tests/data/opensim-running/rajagopal_subject01_run_ik.mot");
  MotionColumns columns = openSimLegColumns(table, "r");
  columns.kneeSign = 1;
  EXPECT_NEAR(durationAt("running"), listSwings(table, columns, std::nullopt, Gait::kRunning).swings.at(0).duration(),
              1e-12);
  EXPECT_NEAR(durationAt("walking"), listSwings(table, columns, std::nullopt, Gait::kWalking).swings.at(0).duration(),
              1e-12);
  EXPECT_LT(durationAt("walking"), durationAt("running") - 0.05);
}

TEST(ParticipantThighMotion, BadInputNamesTheMapFormAndTheLabelsThere) {
  // A .mot without OpenSim's right-leg labels, given by name: the message names the map form.
  std::string rows;
  for (int k = 0; k < 12; ++k) rows += std::to_string(0.01 * k) + "\t1\t" + std::to_string(5 * k) + "\n";
  const std::string motion = testing::writeSuiteTempFile("swingsim_participant_test", "other.mot",
                                                         "other\ninDegrees=yes\nendheader\ntime\thip\tknee\n" + rows);
  const std::string plain = thighError(motion);
  EXPECT_THAT(plain, HasSubstr("other.mot:4: hip_flexion_r: column is missing (available: time, hip, knee)"));
  EXPECT_THAT(plain,
              HasSubstr("w.yaml:35: thigh_kinematics: a plain .mot/.sto name is read with OpenSim's right-leg labels"));
  EXPECT_THAT(plain, HasSubstr("{file: F, hip: LABEL, knee: LABEL"));
  // The map form: a label the file lacks lists those it has; times outside the file; a CSV.
  EXPECT_THAT(thighError("{file: " + kGait10Ik + ", hip: hip_flexion, knee: knee_angle_r}"),
              HasSubstr("w.yaml: thigh_kinematics.hip: expected a column of " + kGait10Ik +
                        ":11 (got 'hip_flexion', which it does not "
                        "have; available: time, pelvis_tilt, pelvis_tx,"));
  EXPECT_THAT(
      thighError("{file: " + kGait10Ik +
                 ", hip: hip_flexion_r, knee: knee_angle_r, toe_off_s: 3, heel_contact_s: 3.5}"),
      HasSubstr("subject01_walk_IK.mot: toe_off_s: expected a time within the file, before its last row; the file's "
                "time runs from 0 to 2.5 s (got 3 s)"));
  EXPECT_THAT(
      thighError("{file: ../studies/data/winter-swing/swing1.csv, hip: a, knee: b}"),
      HasSubstr("w.yaml:35: thigh_kinematics.file: an OpenSim .mot/.sto (the map says how to read its columns"));
  EXPECT_THAT(thighError("{file: " + kGait10Ik + ", knee: knee_angle_r}"),
              HasSubstr("thigh_kinematics.hip: required key is missing"));
}

}  // namespace
}  // namespace swingsim
