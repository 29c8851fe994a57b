// OpenSim motion files (.mot/.sto) read into swing records: good files in degrees and in
// radians give the same record, our own `simulate` .sto reads back, every bad input is an
// InputError naming file, line and column, and sign, offset, cut and resampling do what
// they say.
#include "io/motion_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>
#include "../cli/run_swingsim.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/units.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "io/swing_record_csv.h"
#include "io/trajectory_writer.h"
#include "swing/knee_setup.h"
#include "swing/swing_simulation.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;
namespace fs = std::filesystem;

const std::string kRoot = SWINGSIM_SOURCE_DIR;

// A swing-like motion: hip from -15 to 20 deg, knee up to 65 deg and back, over 0.5 s.
constexpr double kSwingDuration = 0.5;  // s
constexpr double kFrameStep = 0.01;     // s (100 Hz capture)
constexpr int kRows = 51;
double hipDeg(double t) { return -15 + 35 * (1 - std::cos(kPi * t / kSwingDuration)) / 2; }
double kneeDeg(double t) { return 5 + 60 * std::sin(kPi * t / kSwingDuration); }
double momentNm(double t) { return 25 * std::cos(2 * kPi * t / kSwingDuration); }
double frameTime(int k) { return k * kFrameStep; }

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

/// A motion file as lines, to corrupt one piece at a time. Line numbers: header lines 1-5,
/// endheader 6, labels 7, row k on line 8 + k.
struct MotionText {
  std::vector<std::string> header;
  std::string labels = "time\thip_flexion_r\tknee_angle_r\thip_moment";
  std::vector<std::string> rows;
  bool endheader = true;
  std::string str() const {
    std::string out;
    for (const auto& h : header) out += h + "\n";
    out += (endheader ? "endheader\n" : "") + labels + "\n";
    for (const auto& r : rows) out += r + "\n";
    return out;
  }
};
constexpr int kFirstRowLine = 8;

/// The swing above, angles in degrees or radians, the header saying which.
MotionText swingMotion(bool degrees) {
  MotionText m;
  m.header = {"swing", "version=1", "nRows=" + std::to_string(kRows), "nColumns=4",
              degrees ? "inDegrees=yes" : "inDegrees=no"};
  const double unit = degrees ? 1.0 : kDegToRad;
  for (int k = 0; k < kRows; ++k) {
    const double t = frameTime(k);
    m.rows.push_back(number(t) + "\t" + number(hipDeg(t) * unit) + "\t" + number(kneeDeg(t) * unit) + "\t" +
                     number(momentNm(t)));
  }
  return m;
}

MotionColumns swingColumns() {
  MotionColumns c;
  c.hip = "hip_flexion_r";
  c.knee = "knee_angle_r";
  c.hipMoment = "hip_moment";
  return c;
}

fs::path tempDir() { return testing::suiteTempDir("swingsim_motion_file_test"); }

std::string writeTemp(const std::string& name, const std::string& text) {
  return testing::writeSuiteTempFile("swingsim_motion_file_test", name, text);
}

/// The message of the InputError that reading `text` as a swing record throws ("" if none).
std::string errorOf(const std::string& text, const MotionColumns& columns = swingColumns()) {
  try {
    makeSwingRecord(parseMotionTable(text, "trial.sto"), columns);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// ---- Good files ---------------------------------------------------------------------------

TEST(MotionFile, StoInDegreesAndMotInRadiansGiveTheSameRecord) {
  const std::string sto = writeTemp("trial.sto", swingMotion(true).str());
  const std::string mot = writeTemp("trial.mot", swingMotion(false).str());
  const MotionTable table = readMotionTable(sto);
  EXPECT_TRUE(table.inDegrees);
  EXPECT_EQ(table.labels, (std::vector<std::string>{"time", "hip_flexion_r", "knee_angle_r", "hip_moment"}));
  EXPECT_EQ(table.rows(), static_cast<std::size_t>(kRows));
  EXPECT_EQ(table.rowLines.front(), kFirstRowLine);

  const SwingRecord fromSto = readSwingRecordFile(sto, swingColumns());
  const SwingRecord fromMot = readSwingRecordFile(mot, swingColumns());
  EXPECT_EQ(fromSto.stem, "trial");
  EXPECT_EQ(fromSto.path, sto);
  ASSERT_EQ(fromSto.time.size(), static_cast<std::size_t>(kRows));
  ASSERT_EQ(fromMot.time.size(), static_cast<std::size_t>(kRows));
  for (int k = 0; k < kRows; ++k) {
    const double t = frameTime(k);
    const auto i = static_cast<std::size_t>(k);
    // Both reach radians by one multiplication of the same degrees: the same double (4 ulp).
    EXPECT_DOUBLE_EQ(fromSto.time[i], t);
    EXPECT_DOUBLE_EQ(fromSto.hipFlexion[i], hipDeg(t) * kDegToRad) << "row " << k;
    EXPECT_DOUBLE_EQ(fromSto.kneeFlexion[i], kneeDeg(t) * kDegToRad) << "row " << k;
    EXPECT_DOUBLE_EQ(fromSto.hipMoment[i], momentNm(t)) << "row " << k;
    EXPECT_DOUBLE_EQ(fromMot.time[i], fromSto.time[i]);
    EXPECT_DOUBLE_EQ(fromMot.hipFlexion[i], fromSto.hipFlexion[i]) << "row " << k;
    EXPECT_DOUBLE_EQ(fromMot.kneeFlexion[i], fromSto.kneeFlexion[i]) << "row " << k;
    EXPECT_DOUBLE_EQ(fromMot.hipMoment[i], fromSto.hipMoment[i]) << "row " << k;
  }
}

// OpenSim reads a file without inDegrees as radians; so do we.
TEST(MotionFile, MissingInDegreesIsReadAsRadians) {
  MotionText m = swingMotion(false);
  m.header.pop_back();
  const MotionTable table = parseMotionTable(m.str(), "trial.mot");
  EXPECT_FALSE(table.inDegrees);
  EXPECT_EQ(table.inDegreesLine, 0);
  const SwingRecord r = makeSwingRecord(table, swingColumns());
  EXPECT_DOUBLE_EQ(r.kneeFlexion[10], kneeDeg(frameTime(10)) * kDegToRad);
}

// What lab exports look like: CRLF, a byte-order mark, spaces between values, blank lines,
// header keys we do not use, no final newline; the CSV columns are not needed.
TEST(MotionFile, AcceptsCrlfBomSpacesAndUnknownHeaderKeys) {
  MotionText m = swingMotion(true);
  m.header.insert(m.header.begin() + 1, "DataRate=100.000000");
  m.header.insert(m.header.begin() + 1, "OpenSimVersion=4.4");
  m.labels = "time    hip_flexion_r knee_angle_r   hip_moment";
  for (auto& r : m.rows)
    for (char& c : r)
      if (c == '\t') c = ' ';
  std::string text = "\xEF\xBB\xBF" + m.str();
  std::string crlf;
  for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  crlf.insert(crlf.find("endheader") + 11, "\r\n");
  crlf.erase(crlf.size() - 2);
  const SwingRecord r = makeSwingRecord(parseMotionTable(crlf, "lab.sto"), swingColumns());
  ASSERT_EQ(r.time.size(), static_cast<std::size_t>(kRows));
  EXPECT_DOUBLE_EQ(r.kneeFlexion.back(), kneeDeg(frameTime(kRows - 1)) * kDegToRad);
}

// Our own `swingsim simulate` output (formatTrajectorySto of a simulated swing) reads back to
// the angles and moment it was written from.
TEST(MotionFile, SimulateStoReadsBackToTheSameAngles) {
  const Participant p1 = loadParticipant(kRoot + "/participants/p1.yaml");
  const SwingSetup setup = makeSwingSetup(p1, loadKneeModel(p1.kneeModelPath));
  const SwingTrajectory trajectory = simulateSwing(setup).trajectory;
  ASSERT_GE(trajectory.size(), kMinSwingSamples);

  const MotionTable table = parseMotionTable(formatTrajectorySto(trajectory, "P1"), "P1.sto");
  MotionColumns columns = openSimRightLegColumns(table);  // hip_flexion_r, knee_angle_r (knee_sign -1)
  columns.hipMoment = "hip_flexion_r_moment";
  const SwingRecord r = makeSwingRecord(table, columns);
  ASSERT_EQ(r.time.size(), trajectory.size());
  // The .sto holds %.10g: a relative error of at most 5e-10 in each printed number.
  constexpr double kTenDigits = 1e-9;
  const auto near = [&](double a, double b) { return std::abs(a - b) <= kTenDigits * std::max(std::abs(b), 1e-3); };
  for (std::size_t i = 0; i < r.time.size(); ++i) {
    EXPECT_PRED2(near, r.time[i], trajectory.time[i] - trajectory.time.front()) << i;
    EXPECT_PRED2(near, r.hipFlexion[i] * kRadToDeg, trajectory.hipFlexion[i] * kRadToDeg) << i;
    EXPECT_PRED2(near, r.kneeFlexion[i] * kRadToDeg, trajectory.kneeFlexion[i] * kRadToDeg) << i;
    EXPECT_PRED2(near, r.hipMoment[i], trajectory.hipMoment[i]) << i;
  }
}

// ---- Sign, offset, cut, resample ----------------------------------------------------------

TEST(MotionFile, SignAndOffsetGiveClinicalFlexion) {
  const MotionTable table = parseMotionTable(swingMotion(true).str(), "trial.sto");
  MotionColumns c = swingColumns();
  c.hipSign = -1;
  c.hipOffset = 10 * kDegToRad;
  c.kneeSign = -1;
  c.kneeOffset = 80 * kDegToRad;  // keeps the flipped knee flexed: a knee hyperextended throughout is refused
  const SwingRecord r = makeSwingRecord(table, c);
  constexpr double kDegRoundTrip = 1e-12;  // deg: degrees -> radians -> degrees of values under 100 deg
  for (int k = 0; k < kRows; k += 7) {
    const auto i = static_cast<std::size_t>(k);
    EXPECT_NEAR(r.hipFlexion[i] * kRadToDeg, -hipDeg(frameTime(k)) + 10, kDegRoundTrip) << k;
    EXPECT_NEAR(r.kneeFlexion[i] * kRadToDeg, -kneeDeg(frameTime(k)) + 80, kDegRoundTrip) << k;
  }
  c.kneeOffset = -5 * kDegToRad;  // every sample hyperextended: a flipped sign
  try {
    makeSwingRecord(table, c);
    ADD_FAILURE() << "a knee hyperextended on every sample was accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(),
                ::testing::HasSubstr("trial.sto: knee_angle_r: expected knee flexion, positive when bent (got 51 of 51 "
                                     "samples over the swing below -5 deg"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("set knee_sign: 1"));
  }
}

TEST(MotionFile, CutKeepsTheRowsBetweenToeOffAndHeelContactFromZero) {
  const MotionTable table = parseMotionTable(swingMotion(true).str(), "trial.sto");
  MotionColumns c = swingColumns();
  c.toeOffTime = frameTime(10);
  c.heelContactTime = frameTime(40);
  const SwingRecord r = makeSwingRecord(table, c);
  ASSERT_EQ(r.time.size(), 31u);
  EXPECT_EQ(r.time.front(), 0.0);
  EXPECT_NEAR(r.time.back(), frameTime(40) - frameTime(10), 1e-15);
  for (std::size_t i = 0; i < r.time.size(); ++i)
    EXPECT_DOUBLE_EQ(r.kneeFlexion[i], kneeDeg(frameTime(10 + static_cast<int>(i))) * kDegToRad) << i;
}

// A cut between rows adds the end points by linear interpolation: exact on a straight line.
TEST(MotionFile, CutBetweenRowsInterpolatesTheEnds) {
  MotionText m = swingMotion(true);
  m.labels = "time\thip_flexion_r\tknee_angle_r\thip_moment";
  const auto line = [](double t) { return 2 + 100 * t; };  // deg
  m.rows.clear();
  for (int k = 0; k < kRows; ++k)
    m.rows.push_back(number(frameTime(k)) + "\t" + number(line(frameTime(k))) + "\t" + number(line(frameTime(k))) +
                     "\t0");
  MotionColumns c = swingColumns();
  c.toeOffTime = 0.105;
  c.heelContactTime = 0.3925;
  const SwingRecord r = makeSwingRecord(parseMotionTable(m.str(), "line.sto"), c);
  // 0.11 ... 0.39 inside (29 rows) plus the two ends.
  ASSERT_EQ(r.time.size(), 31u);
  EXPECT_EQ(r.time.front(), 0.0);
  EXPECT_NEAR(r.time[1], 0.11 - 0.105, 1e-15);
  EXPECT_NEAR(r.time.back(), 0.3925 - 0.105, 1e-15);
  constexpr double kLineTol = 1e-12;  // deg: rounding in interpolating a line
  EXPECT_NEAR(r.kneeFlexion.front() * kRadToDeg, line(0.105), kLineTol);
  EXPECT_NEAR(r.kneeFlexion.back() * kRadToDeg, line(0.3925), kLineTol);
  EXPECT_NEAR(r.hipFlexion[1] * kRadToDeg, line(0.11), kLineTol);
}

TEST(MotionFile, ResampleInterpolatesAtTheStatedInterval) {
  MotionText m = swingMotion(true);
  const auto line = [](double t) { return -3 + 80 * t; };  // deg
  m.rows.clear();
  for (int k = 0; k < kRows; ++k)
    m.rows.push_back(number(frameTime(k)) + "\t" + number(line(frameTime(k))) + "\t" + number(line(frameTime(k))) +
                     "\t" + number(10 * frameTime(k)));
  MotionColumns c = swingColumns();
  c.toeOffTime = 0.1;
  c.heelContactTime = 0.4;
  c.resampleInterval = 0.004;
  const SwingRecord r = makeSwingRecord(parseMotionTable(m.str(), "line.sto"), c);
  ASSERT_EQ(r.time.size(), 76u);      // 0, 0.004, ..., 0.3 s
  constexpr double kLineTol = 1e-12;  // deg or N m: rounding in interpolating a line
  for (std::size_t i = 0; i < r.time.size(); ++i) {
    const double t = 0.1 + 0.004 * static_cast<double>(i);
    EXPECT_NEAR(r.time[i], 0.004 * static_cast<double>(i), 1e-15);
    EXPECT_NEAR(r.kneeFlexion[i] * kRadToDeg, line(t), kLineTol) << i;
    EXPECT_NEAR(r.hipMoment[i], 10 * t, kLineTol) << i;
  }
}

TEST(MotionFile, ExtensionChoosesTheReader) {
  EXPECT_TRUE(isMotionFile("a/b.mot"));
  EXPECT_TRUE(isMotionFile("b.STO"));
  EXPECT_FALSE(isMotionFile("b.csv"));
  EXPECT_FALSE(isMotionFile("sto"));
  const std::string csv = writeTemp("trial.csv",
                                    "time_s,hip_flexion_deg,knee_flexion_deg,hip_moment_Nm\n"
                                    "0,1,2,3\n0.1,1,5,3\n0.2,1,9,3\n0.3,1,9,3\n0.4,1,9,3\n"
                                    "0.5,1,9,3\n0.6,1,9,3\n0.7,1,9,3\n0.8,1,9,3\n0.9,1,9,3\n");
  EXPECT_EQ(readSwingRecordFile(csv, std::nullopt).kneeFlexion, readSwingRecord(csv).kneeFlexion);
  const std::string sto = writeTemp("nocolumns.sto", swingMotion(true).str());
  try {
    readSwingRecordFile(sto, std::nullopt);
    FAIL() << "a motion file without motion_columns was read";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), StartsWith(sto + ": "));
    EXPECT_THAT(e.what(), HasSubstr("motion_columns"));
  }
}

// ---- Bad input: each names the file, the line and the column --------------------------------

struct BadMotion {
  std::string name;
  std::function<void(MotionText&)> corrupt;
  std::vector<std::string> expected;  ///< substrings of the message
};

std::vector<BadMotion> badMotions() {
  return {
      {"no endheader",
       [](MotionText& m) { m.endheader = false; },
       {"trial.sto:1: ", "expected an OpenSim Storage header ending in a line 'endheader' (got none in"}},
      {"time not first",
       [](MotionText& m) { m.labels = "hip_flexion_r\ttime\tknee_angle_r\thip_moment"; },
       {"trial.sto:7: time: expected the first column label to be 'time' (got 'hip_flexion_r')"}},
      {"repeated label",
       [](MotionText& m) { m.labels = "time\thip_flexion_r\tknee_angle_r\tknee_angle_r"; },
       {"trial.sto:7: knee_angle_r: column label appears twice"}},
      {"requested column missing",
       [](MotionText& m) { m.labels = "time\thip_flexion_r\tknee_angle_l\thip_moment"; },
       {"trial.sto:7: knee_angle_r: column is missing (available: time, hip_flexion_r, knee_angle_l, hip_moment)"}},
      {"row too short",
       [](MotionText& m) { m.rows[3] = "0.03\t1\t2"; },
       {"trial.sto:11: expected 4 values, one per label on line 7 (got 3)"}},
      {"comma decimals",
       [](MotionText& m) { m.rows[3] = "0,03\t1,5\t2\t3"; },
       {"trial.sto:11: time: expected a number (got '0,03')"}},
      {"not a number",
       [](MotionText& m) { m.rows[4] = "0.04\t1\tabc\t3"; },
       {"trial.sto:12: knee_angle_r: expected a number (got 'abc')"}},
      {"NaN",
       [](MotionText& m) { m.rows[5] = "0.05\tnan\t2\t3"; },
       {"trial.sto:13: hip_flexion_r: expected a finite number (got 'nan')"}},
      {"infinity",
       [](MotionText& m) { m.rows[6] = "0.06\t1\t2\t-inf"; },
       {"trial.sto:14: hip_moment: expected a finite number (got '-inf')"}},
      {"overflow",
       [](MotionText& m) { m.rows[6] = "0.06\t1e999\t2\t3"; },
       {"trial.sto:14: hip_flexion_r: expected a finite number (got '1e999')"}},
      {"time repeats",
       [](MotionText& m) { m.rows[20] = "0.19\t1\t2\t3"; },
       {"trial.sto:28: time: must strictly increase (got 0.19 after 0.19"}},
      {"time goes back",
       [](MotionText& m) { m.rows[20] = "0.1\t1\t2\t3"; },
       {"trial.sto:28: time: must strictly increase (got 0.1 after 0.19"}},
      {"gap",
       [](MotionText& m) {
         m.rows.erase(m.rows.begin() + 20, m.rows.begin() + 26);
         m.header[2] = "nRows=45";
       },
       {"trial.sto:28: time: a gap of 0.07", "s after 0.19", "more than 5 times the median step of 0.01",
        "missing frames?"}},
      {"nRows disagrees",
       [](MotionText& m) { m.rows.pop_back(); },
       {"trial.sto:3: nRows: the header says 51 rows (got 50 rows of numbers)"}},
      {"nRows not a number",
       [](MotionText& m) { m.header[2] = "nRows=many"; },
       {"trial.sto:3: nRows: expected a whole number (got 'many')"}},
      {"nColumns disagrees",
       [](MotionText& m) { m.header[3] = "nColumns=3"; },
       {"trial.sto:4: nColumns: the header says 3 columns, time included (got 4 labels on line 7)"}},
      {"inDegrees not yes or no",
       [](MotionText& m) { m.header[4] = "inDegrees=true"; },
       {"trial.sto:5: inDegrees: expected yes or no (got 'true')"}},
      {"inDegrees twice",
       [](MotionText& m) { m.header.push_back("inDegrees=no"); },
       {"trial.sto:6: inDegrees: appears twice in the header (first on line 5)"}},
      {"version 2",
       [](MotionText& m) { m.header[1] = "version=2"; },
       {"trial.sto:2: version: expected 1 (Storage version 1) (got '2')"}},
      {"no rows",
       [](MotionText& m) {
         m.rows.clear();
         m.header[2] = "nRows=0";
       },
       {"trial.sto:7: expected rows of numbers after the column labels (got none)"}},
      {"no labels",
       [](MotionText& m) {
         m.labels = "";
         m.rows.clear();
       },
       {"trial.sto:6: expected a line of column labels after endheader, starting with 'time' (got the end of the "
        "file)"}},
      {"radians said to be degrees",
       [](MotionText& m) {
         m = swingMotion(false);
         m.header[4] = "inDegrees=yes";
       },
       {"trial.sto:5: knee_angle_r: the knee moves through only", "deg over the swing",
        "the column looks like radians, but the header says inDegrees=yes"}},
      {"degrees said to be radians",
       [](MotionText& m) { m.header[4] = "inDegrees=no"; },
       {"trial.sto:5: knee_angle_r: the knee moves through ", "rad over the swing",
        "the column looks like degrees, but the header says inDegrees=no"}},
      {"degrees without inDegrees",
       [](MotionText& m) { m.header.pop_back(); },
       {"trial.sto: knee_angle_r: the knee moves through ", "rad over the swing",
        "the header has no inDegrees line, read as no (radians)"}},
  };
}

TEST(MotionFileBadInput, EachCaseNamesFileLineAndColumn) {
  for (const BadMotion& c : badMotions()) {
    MotionText m = swingMotion(true);
    c.corrupt(m);
    const std::string message = errorOf(m.str());
    EXPECT_THAT(message, StartsWith("trial.sto")) << c.name;
    for (const auto& part : c.expected) EXPECT_THAT(message, HasSubstr(part)) << c.name;
  }
}

TEST(MotionFileBadInput, CutOutsideTheFileOrTooShort) {
  const std::string text = swingMotion(true).str();
  MotionColumns c = swingColumns();
  c.toeOffTime = -0.1;
  EXPECT_THAT(errorOf(text, c), HasSubstr("trial.sto: toe_off_s: expected a time within the file, before its last row; "
                                          "the file's time runs from 0 to 0.5 s (got -0.1 s)"));
  c.toeOffTime = 0.2;
  c.heelContactTime = 0.6;
  EXPECT_THAT(errorOf(text, c),
              HasSubstr("trial.sto: heel_contact_s: expected a time after toe-off (0.2 s) and within the file"));
  c.heelContactTime = 0.25;
  EXPECT_THAT(errorOf(text, c),
              HasSubstr("trial.sto: expected at least 10 samples between toe-off (0.2 s) and heel contact "
                        "(0.25 s) (got 6)"));
  c = swingColumns();
  c.resampleInterval = 1e-9;
  EXPECT_THAT(errorOf(text, c), HasSubstr("s gives more than 2000000 samples over the swing (the limit)"));
}

TEST(MotionFileBadInput, SizeAndRowLimits) {
  // More rows than the limit: refused at the first row past it, naming its line.
  std::string text = "big\nendheader\ntime\n";
  for (std::size_t k = 0; k <= kMaxMotionRows; ++k) text += std::to_string(k) + "\n";
  try {
    parseMotionTable(text, "big.sto");
    FAIL() << "too many rows accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(),
                HasSubstr("big.sto:" + std::to_string(kMaxMotionRows + 4) + ": too many rows (more than 2000000"));
  }
  // Binary data and directories are named as such.
  std::string binary = "swing\nendheader\ntime\n";
  binary += '\0';
  EXPECT_THAT(errorOf(binary), HasSubstr("trial.sto: not a text motion file (contains NUL bytes)"));
  try {
    readMotionTable(tempDir().string());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("directory"));
  }
}

// ---- Pelvis and inverse dynamics: the shipped OpenSim pipeline output ----------------------

const std::string kGait2354Ik = kRoot + "/studies/data/opensim-subject01/gait2354_subject01_walk1_ik.mot";
const std::string kGait2354Id = kRoot + "/studies/data/opensim-subject01/gait2354_subject01_walk1_inverse_dynamics.sto";
const std::string kGait2392Ik = kRoot + "/studies/data/opensim-subject01/gait2392_subject01_walk1_ik.mot";
const std::string kGait10Ik = kRoot + "/tests/data/opensim-gait10dof/subject01_walk_IK.mot";
const std::string kGait10Id = kRoot + "/tests/data/opensim-gait10dof/subject01_walk_ID.sto";

/// The value of `label` in `table` on the row at file time `t` (the rows the cut keeps).
double valueAt(const MotionTable& table, const std::string& label, double t) {
  const auto& time = table.column("time");
  for (std::size_t r = 0; r < time.size(); ++r)
    if (std::abs(time[r] - t) < 1e-9) return table.column(label)[r];
  ADD_FAILURE() << "no row at " << t;
  return 0;
}

// Rows are kept as read: only the degree-to-radian product rounds (a few ulps).
constexpr double kRowTol = 1e-12;

TEST(MotionFilePelvis, ThighInSpaceIsHipPlusPelvisTiltAndTranslationsStayMetres) {
  for (const std::string& path : {kGait2354Ik, kGait10Ik}) {
    const MotionTable table = readMotionTable(path);
    MotionColumns c = openSimRightLegColumns(table);
    EXPECT_EQ(c.pelvisTilt, "pelvis_tilt") << path;
    EXPECT_EQ(c.kneeSign, -1);
    c.toeOffTime = 0.5;
    c.heelContactTime = 1.2;
    const SwingRecord r = makeSwingRecord(table, c);
    ASSERT_EQ(r.pelvisTilt.size(), r.time.size());
    ASSERT_EQ(r.pelvisX.size(), r.time.size());
    ASSERT_EQ(r.pelvisY.size(), r.time.size());
    for (std::size_t k = 1; k + 1 < r.time.size(); ++k) {  // the rows themselves (the ends are interpolated)
      const double t = 0.5 + r.time[k];
      const double tilt = valueAt(table, "pelvis_tilt", t) * kDegToRad;
      EXPECT_NEAR(r.pelvisTilt[k], tilt, kRowTol);
      EXPECT_NEAR(r.hipFlexion[k], valueAt(table, "hip_flexion_r", t) * kDegToRad + tilt, kRowTol) << path << " " << t;
      EXPECT_NEAR(r.kneeFlexion[k], -valueAt(table, "knee_angle_r", t) * kDegToRad, kRowTol);
      // inDegrees=yes, but pelvis_tx/ty are metres: not converted.
      EXPECT_EQ(r.pelvisX[k], valueAt(table, "pelvis_tx", t));
      EXPECT_EQ(r.pelvisY[k], valueAt(table, "pelvis_ty", t));
    }
    // Without the pelvis columns the hip is the joint angle alone, and a warning says so.
    MotionColumns bare = c;
    bare.pelvisTilt = bare.pelvisTx = bare.pelvisTy = "";
    const SwingRecord joint = makeSwingRecord(table, bare);
    EXPECT_TRUE(joint.pelvisTilt.empty());
    EXPECT_NEAR(joint.hipFlexion[3], r.hipFlexion[3] - r.pelvisTilt[3], kRowTol);
    const auto warnings = checkMotionRecord(joint, table, bare);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_THAT(warnings[0], HasSubstr("motion_columns: pelvis_tilt: pelvis_tilt"));
    EXPECT_TRUE(checkMotionRecord(r, table, c).empty());
  }
}

TEST(MotionFilePelvis, FlippedKneeSignIsWarnedNamingKneeSign) {
  const MotionTable table = readMotionTable(kGait10Ik);
  MotionColumns c = openSimRightLegColumns(table);
  c.kneeSign = 1;  // forgotten: OpenSim's knee angle is negative in flexion
  const auto warnings = checkMotionRecord(makeSwingRecord(table, c), table, c);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_THAT(warnings[0], HasSubstr("knee samples of " + kGait10Ik + " are below -5 deg"));
  EXPECT_THAT(warnings[0], HasSubstr("knee_sign: -1"));
}

// The ID's times lag the IK's by up to 1.5 us (single precision, accumulated: 2.4999985 s for 2.5 s).
constexpr double kIdTimeSkew = 2e-6;  // s

/// The largest |slope| of `label` over the rows of `table`, per s.
double maxSlope(const MotionTable& table, const std::string& label) {
  const auto& t = table.column("time");
  const auto& v = table.column(label);
  double m = 0;
  for (std::size_t r = 1; r < t.size(); ++r) m = std::max(m, std::abs((v[r] - v[r - 1]) / (t[r] - t[r - 1])));
  return m;
}

/// The value of `label` on the row of `table` within kIdTimeSkew of `t`.
double valueNear(const MotionTable& table, const std::string& label, double t) {
  const auto& time = table.column("time");
  for (std::size_t r = 0; r < time.size(); ++r)
    if (std::abs(time[r] - t) < kIdTimeSkew) return table.column(label)[r];
  ADD_FAILURE() << "no row near " << t;
  return 0;
}

TEST(MotionFileKneeMoment, InverseDynamicsKneeMomentOnTheRecordsTimesWithTheKneesSign) {
  const MotionTable ik = readMotionTable(kGait10Ik);
  const MotionTable id = readMotionTable(kGait10Id);
  MotionColumns c = openSimRightLegColumns(ik);
  c.toeOffTime = 1.3;
  c.heelContactTime = 1.75;
  const SwingRecord r = makeSwingRecord(ik, c, &id);
  ASSERT_EQ(r.kneeMoment.size(), r.time.size());
  // Each kept IK row has an ID row within the skew: the moment is that row's, sign flipped,
  // to within the moment's change over the skew.
  const double tol = maxSlope(id, "knee_angle_r_moment") * kIdTimeSkew;
  for (std::size_t k = 1; k + 1 < r.time.size(); ++k)
    EXPECT_NEAR(r.kneeMoment[k], -valueNear(id, "knee_angle_r_moment", 1.3 + r.time[k]), tol) << k;
  // Another label, named through motion_columns: knee_moment.
  c.kneeMoment = "knee_angle_l_moment";
  const SwingRecord left = makeSwingRecord(ik, c, &id);
  EXPECT_NEAR(left.kneeMoment[4], -valueNear(id, "knee_angle_l_moment", 1.3 + left.time[4]),
              maxSlope(id, "knee_angle_l_moment") * kIdTimeSkew);
}

TEST(MotionFileKneeMoment, PartOfTheSwingOutsideTheStoIsNaN) {
  // The Gait2392 IK runs 0.5-4 s, the Gait2354 ID 0.4-1.6 s (its last row at 1.59999928 s).
  const MotionTable ik = readMotionTable(kGait2392Ik);
  const MotionTable id = readMotionTable(kGait2354Id);
  MotionColumns c = openSimRightLegColumns(ik);
  c.toeOffTime = 1.4;
  c.heelContactTime = 1.8;
  const SwingRecord r = makeSwingRecord(ik, c, &id);
  std::size_t covered = 0;
  for (std::size_t k = 0; k < r.time.size(); ++k) {
    const bool inside = 1.4 + r.time[k] <= id.column("time").back();
    EXPECT_EQ(std::isnan(r.kneeMoment[k]), !inside) << r.time[k];
    covered += inside;
  }
  EXPECT_GT(covered, 10u);
  EXPECT_LT(covered, r.time.size());
}

TEST(MotionFileKneeMomentBadInput, NoOverlapOrNoLabelNamesFileKeyAndWhatWasFound) {
  const MotionTable ik = readMotionTable(kGait2392Ik);
  const MotionTable id = readMotionTable(kGait2354Id);
  MotionColumns c = openSimRightLegColumns(ik);
  c.toeOffTime = 2.0;
  c.heelContactTime = 2.5;
  try {
    makeSwingRecord(ik, c, &id);
    FAIL() << "an ID outside the swing was accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(),
                HasSubstr(kGait2354Id + ": inverse_dynamics: expected times that overlap the swing, 2 to 2.5 s "
                                        "(got 0.39999976 to 1.59999928 s)"));
  }
  c.toeOffTime = 0.6;
  c.heelContactTime = 1.2;
  c.kneeMoment = "knee_moment";
  try {
    makeSwingRecord(ik, c, &id);
    FAIL() << "a missing knee moment label was accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(),
                HasSubstr(kGait2354Id + ":7: knee_moment: column is missing (available: time, pelvis_tilt_moment"));
    EXPECT_THAT(e.what(), HasSubstr("motion_columns: knee_moment"));
  }
  // A pelvis label the file lacks lists those it has.
  c.kneeMoment = "";
  c.pelvisTilt = "pelvis_tlt";
  EXPECT_THAT(errorOf(readFile(kGait2392Ik), c),
              HasSubstr("pelvis_tlt: column is missing (available: time, pelvis_tilt,"));
}

}  // namespace
}  // namespace swingsim
