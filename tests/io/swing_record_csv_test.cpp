// The swing kinematics CSV (io/swing_record_csv.h): a record written and read back is the
// same record (degrees in the file, radians inside); time is rebased to toe-off; the
// moment columns are optional; a knee column in radians is refused by name.
#include "io/swing_record_csv.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/input_error.h"
#include "core/units.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

// %.10g in the file: ten significant digits of a value of order 1 (degrees or N m).
constexpr double kWrittenDigits = 1e-8;

std::string writeTemp(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "swingsim_swing_record_csv_test";
  std::filesystem::create_directories(dir);
  const auto path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

// 20 samples at 100 Hz of a knee flexing to 60 deg and a thigh rising, with or without moments.
SwingRecord makeRecord(bool moments) {
  SwingRecord r;
  for (int i = 0; i < 20; ++i) {
    const double t = 0.01 * i;
    r.time.push_back(t);
    r.hipFlexion.push_back(-0.1 + 0.9 * t);
    r.kneeFlexion.push_back(1.05 * std::sin(3.14159 * t / 0.19));
    if (moments) {
      r.hipMoment.push_back(20 * std::cos(10 * t));
      r.kneeMoment.push_back(-3 * t);
    }
  }
  return r;
}

void expectNear(const std::vector<double>& a, const std::vector<double>& b, double tol, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], tol) << what << " row " << i;
}

TEST(SwingRecordCsv, WrittenAndReadBackIsTheSameRecord) {
  const SwingRecord written = makeRecord(true);
  const std::string text = formatSwingRecordCsv(written);
  EXPECT_EQ(text.substr(0, text.find('\n')), "time_s,hip_flexion_deg,knee_flexion_deg,hip_moment_Nm,knee_moment_Nm");
  const SwingRecord read = readSwingRecord(writeTemp("round.csv", text));
  EXPECT_EQ(read.stem, "round");
  expectNear(read.time, written.time, kWrittenDigits, "time");
  expectNear(read.hipFlexion, written.hipFlexion, kWrittenDigits * kDegToRad, "hip");
  expectNear(read.kneeFlexion, written.kneeFlexion, kWrittenDigits * kDegToRad, "knee");
  expectNear(read.hipMoment, written.hipMoment, kWrittenDigits * 20, "hip moment");
  expectNear(read.kneeMoment, written.kneeMoment, kWrittenDigits, "knee moment");
}

TEST(SwingRecordCsv, MomentColumnsAreOptionalAndTimeStartsAtToeOff) {
  SwingRecord written = makeRecord(false);
  for (double& t : written.time) t += 2.5;  // a trial cut from a longer recording
  const std::string text = formatSwingRecordCsv(written);
  EXPECT_EQ(text.substr(0, text.find('\n')), "time_s,hip_flexion_deg,knee_flexion_deg");
  const SwingRecord read = readSwingRecord(writeTemp("plain.csv", text));
  EXPECT_TRUE(read.hipMoment.empty());
  EXPECT_TRUE(read.kneeMoment.empty());
  EXPECT_EQ(read.time.front(), 0.0);
  EXPECT_NEAR(read.time.back(), 0.19, kWrittenDigits);
}

TEST(SwingRecordCsv, KneeInRadiansOrTooFewRowsAreRefused) {
  std::string radians = "time_s,hip_flexion_deg,knee_flexion_deg\n";
  for (int i = 0; i < 12; ++i) radians += std::to_string(0.01 * i) + ",10," + std::to_string(0.1 * i) + "\n";
  try {
    readSwingRecord(writeTemp("radians.csv", radians));
    ADD_FAILURE() << "a knee column in radians was read";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("radians.csv: knee_flexion_deg: the knee moves through only 1.1 deg over the whole "
                                    "record (from 0 to 1.1"));
    EXPECT_THAT(e.what(), HasSubstr("the column looks like radians, expected degrees"));
  }
  try {
    readSwingRecord(writeTemp("short.csv", "time_s,hip_flexion_deg,knee_flexion_deg\n0,1,2\n0.01,1,20\n"));
    ADD_FAILURE() << "two rows were read";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("short.csv: too few data rows (got 2, need at least 10)"));
  }
  // Issue 57: a record timed in ms (a diagnosis then integrated for minutes).
  std::string ms = "time_s,hip_flexion_deg,knee_flexion_deg\n";
  for (int i = 0; i < 12; ++i) ms += std::to_string(40 * i) + ",10," + std::to_string(5 * i) + "\n";
  try {
    readSwingRecord(writeTemp("ms.csv", ms));
    ADD_FAILURE() << "a record in ms was read";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(),
                HasSubstr("ms.csv: time_s: expected one swing in seconds, spanning at most 10 s (got 440 s from "
                          "the first sample to the last: in ms?)"));
  }
}

}  // namespace
}  // namespace swingsim
