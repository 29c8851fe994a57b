// The cohort study file says what it draws: its seed takes every seed of the generator
// (std::mt19937_64: 0 to 2^64 - 1, read exactly) and a seed out of that range is refused
// naming the range; a normal whose sd flattens or collapses its truncation is refused at
// file:line with the reason; a drawn participant that a participant file could not hold is
// refused at `distributions`, naming the participant and the key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/input_error.h"
#include "study/cohort_study.h"
#include "tiny_cohort_study_text.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

const std::string kRoot = SWINGSIM_SOURCE_DIR;

std::string studyText(const std::string& from = "", const std::string& to = "") {
  return tinyCohortStudyText(3, from, to);
}

std::string errorOf(const std::string& text, const std::string& path = kRoot + "/study.yaml") {
  try {
    parseCohortStudy(text, path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(CohortStudyChecks, TheSeedTakesTheGeneratorsWholeRangeAndNamesIt) {
  const std::string path = kRoot + "/study.yaml";
  EXPECT_EQ(parseCohortStudy(studyText("seed: 3", "seed: 4000000000"), path).seed, 4000000000ULL);
  EXPECT_EQ(parseCohortStudy(studyText("seed: 3", "seed: 18446744073709551615"), path).seed, 18446744073709551615ULL);
  // Read exactly, not through a double (which would make both of these 2^53).
  EXPECT_NE(parseCohortStudy(studyText("seed: 3", "seed: 9007199254740993"), path).values,
            parseCohortStudy(studyText("seed: 3", "seed: 9007199254740992"), path).values);
  const std::string range =
      "seed: expected an integer in [0, 2^64 - 1 = 18446744073709551615, the seeds of the "
      "std::mt19937_64 that draws the cohort]";
  EXPECT_EQ(errorOf(studyText("seed: 3", "seed: 18446744073709551616")),
            path + ":4: " + range + " (got 18446744073709551616)");
  EXPECT_EQ(errorOf(studyText("seed: 3", "seed: -1")), path + ":4: " + range + " (got -1)");
  EXPECT_EQ(errorOf(studyText("seed: 3", "seed: 2.5")), path + ":4: " + range + " (got 2.5)");
  EXPECT_EQ(parseCohortStudy(studyText("seed: 3", "seed: 1e10"), path).seed, 10000000000ULL);
}

TEST(CohortStudyChecks, ASpreadThatFlattensOrCollapsesItsTruncationIsRefusedAtFileLine) {
  const std::string path = kRoot + "/study.yaml";
  const std::string wide = errorOf(studyText("sd: 0.067", "sd: 1e20"));
  EXPECT_THAT(wide, HasSubstr(path + ":8: distributions.stature_m.sd: expected a standard deviation of at most 10 x "
                                     "(max - min) = 2.2 (a wider normal is flat across [1.649, 1.869]"));
  EXPECT_THAT(wide, HasSubstr("(got 1e+20)"));
  EXPECT_THAT(
      errorOf(studyText("sd: 0.067", "sd: 1e-9")),
      HasSubstr(path + ":8: distributions.stature_m.sd: expected a standard deviation of at least 0.001 x (max - "
                       "min) = 0.00022 (a narrower normal draws every participant at the mean 1.759)"));
}

TEST(CohortStudyChecks, ADrawnLegNoParticipantFileCouldHoldIsRefusedNamingParticipantAndKey) {
  // A template whose shank must keep 0.45 m: a drawn stature of 1.649-1.869 m gives a shank
  // of 0.41-0.46 m, so some drawn participant has less shank than its own minimum.
  const auto dir =
      std::filesystem::temp_directory_path() / ("swingsim-cohort-study-checks-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ifstream in(kRoot + "/participants/p1.yaml");
  std::string templ((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  templ.replace(templ.find("knee_model: ../models/"), 22, "knee_model: " + kRoot + "/models/");
  templ += "min_shank_length_m: 0.45\n";
  std::ofstream((dir / "deep.yaml").string()) << templ;
  const std::string path = (dir / "study.yaml").string();
  const std::string message = errorOf(studyText("template: participants/p1.yaml", "template: deep.yaml"), path);
  EXPECT_THAT(message, HasSubstr(path + ":7: distributions: expected distributions whose every draw is a leg a "
                                        "participant file may hold (narrow the one named) (got C00"));
  EXPECT_THAT(message, HasSubstr(": min_shank_length_m: must be shorter than the shank ("));
  EXPECT_THAT(message, HasSubstr("(got 0.45, the template's)"));
}

}  // namespace
}  // namespace swingsim
