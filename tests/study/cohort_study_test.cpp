// The cohort-sweep study format: the shipped example loads (at least 100 participants, every
// distribution with a source, every drawn value inside its range) and draws the same cohort
// twice; bad distributions are refused with file:line, the key, what was expected and what
// was found.
#include "study/cohort_study.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "core/input_error.h"
#include "tiny_cohort_study_text.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

const std::string kRoot = SWINGSIM_SOURCE_DIR;

std::string studyText(const std::string& from = "", const std::string& to = "") {
  return tinyCohortStudyText(5, from, to);
}

std::string errorOf(const std::string& text) {
  try {
    parseCohortStudy(text, kRoot + "/study.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(CohortStudy, ShippedExampleDrawsAtLeast100ParticipantsInsideTheirRanges) {
  const std::string path = kRoot + "/studies/cohort-example.yaml";
  EXPECT_TRUE(isCohortStudyFile(path));
  EXPECT_FALSE(isCohortStudyFile(kRoot + "/studies/burkett2004.yaml"));
  const Cohort c = loadCohortStudy(path);
  EXPECT_GE(c.count, 100);
  ASSERT_EQ(c.study.participants.size(), static_cast<std::size_t>(c.count));
  ASSERT_EQ(c.distributions.size(), cohortProperties().size());
  for (const auto& d : c.distributions) EXPECT_GE(d.source.size(), 10u);
  for (const auto& row : c.values)
    for (std::size_t k = 0; k < row.size(); ++k) {
      EXPECT_GE(row[k], c.distributions[k].min);
      EXPECT_LE(row[k], c.distributions[k].max);
    }
  EXPECT_EQ(loadCohortStudy(path).values, c.values);  // the seed makes it reproducible
  for (const auto& p : c.study.participants) EXPECT_NO_THROW(calcLegGeometry(p, 0.1)) << p.name;
}

TEST(CohortStudy, RefusesBadDistributionsWithFileLineKeyExpectedAndFound) {
  EXPECT_EQ(errorOf(studyText()), "no error");
  // A range outside what is physically possible.
  EXPECT_THAT(errorOf(studyText("min: 0.57, max: 1.0", "min: 0.57, max: 1.3")),
              HasSubstr("study.yaml:10: distributions.residual_limb_fraction.max: expected a value inside 0.2 .. 1"));
  EXPECT_THAT(errorOf(studyText("min: 0.57, max: 1.0", "min: 0.57, max: 1.3")), HasSubstr("(got 1.3)"));
  // min above max.
  EXPECT_THAT(errorOf(studyText("min: 5, max: 15", "min: 15, max: 5")),
              HasSubstr("distributions.knee_friction_Nm.max: expected a value above min 15 (got 5)"));
  // A normal whose sd is not positive, or whose mean is outside its range.
  EXPECT_THAT(errorOf(studyText("sd: 0.067", "sd: -0.1")),
              HasSubstr("distributions.stature_m.sd: expected a positive standard deviation (got -0.1)"));
  EXPECT_THAT(errorOf(studyText("mean: 1.759", "mean: 1.9")),
              HasSubstr("distributions.stature_m.mean: expected a mean inside [1.649, 1.869] (got 1.9)"));
  // No source (blank; an empty text is refused by the reader already).
  EXPECT_THAT(errorOf(studyText("source: Baum 2008", "source: \"   \"")),
              HasSubstr("distributions.residual_limb_fraction.source: expected the published source"));
  // An unknown distribution, a missing property, an unknown property.
  EXPECT_THAT(errorOf(studyText("{distribution: uniform, min: 20", "{distribution: lognormal, min: 20")),
              HasSubstr("distributions.body_mass_index_kg_m2.distribution"));
  EXPECT_THAT(errorOf(studyText(
                  "  pylon_mass_kg: {distribution: uniform, min: 0.08, max: 0.30, source: \"assumption\"}\n", "")),
              HasSubstr("distributions.pylon_mass_kg: required key is missing"));
  EXPECT_THAT(errorOf(studyText("distributions:\n",
                                "distributions:\n  shoe_size: {distribution: uniform, min: 1, max: 2, source: x}\n")),
              HasSubstr("shoe_size"));
  // A uniform with a normal's keys, and a participant count out of range.
  EXPECT_THAT(errorOf(studyText("min: 20, max: 26", "min: 20, max: 26, sd: 1")), HasSubstr("sd"));
  EXPECT_THAT(
      errorOf(studyText("participants: 5", "participants: 0")),
      HasSubstr("study.yaml:3: participants: expected a whole number of participants from 1 to 100000 (got 0)"));
}

}  // namespace
}  // namespace swingsim
