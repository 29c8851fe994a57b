// The symmetry lowering in the sweep report (report/sweep_symmetry_markdown.h, the JSON, the
// swing-time figure) on hand-made results: shown for a participant with a sound-limb swing
// time, absent for one without; and Table 4's `*` found from Burkett's published columns.
#include "report/sweep_symmetry_markdown.h"

#include <gtest/gtest.h>

#include <string>

#include "io/json_file.h"
#include "report/sweep_figures.h"
#include "report/sweep_markdown.h"
#include "report/sweep_report.h"
#include "study/sweep_study.h"

namespace swingsim {
namespace {

SweepPoint endedAt(double lowering, double swingTime) {
  SweepPoint pt;
  pt.lowering = lowering;
  pt.ran = pt.ok = true;
  pt.result.swingTime = swingTime;
  pt.result.minToeClearance = 0.01;
  return pt;
}

// P1 with Table 4's 0 m anatomical time (0.499 s), never reached (every lowering faster):
// closest at 0 m, 0.430 s, gap -69 ms. Q (not in the paper) without a sound-limb time.
SweepResults makeResults() {
  ParticipantSweep p1;
  p1.name = "P1";
  p1.published = findPublished("P1");
  p1.points = {endedAt(0, 0.430), endedAt(0.05, 0.420), endedAt(0.10, 0.425), endedAt(0.15, 0.428)};
  p1.best = 1;
  p1.symmetry = calcSymmetryLowering({0, 0.05, 0.10, 0.15}, {0.430, 0.420, 0.425, 0.428}, 0.499);
  ParticipantSweep q;
  q.name = "Q";
  q.points = {endedAt(0, 0.40), endedAt(0.05, 0.39)};
  q.best = 1;
  SweepResults results;
  results.study = "hand-made";
  results.participants = {p1, q};
  return results;
}

// P1's analysis with a symmetry interval; Q's without (no sound-limb time).
UncertaintyResults makeUncertainty(const SweepResults& r) {
  UncertaintyResults u;
  u.samples = 20;
  u.seed = 3;
  for (const auto& ps : r.participants) {
    ParticipantUncertainty pu;
    pu.name = ps.name;
    pu.symmetry = ps.symmetry;
    if (ps.symmetry.given) {
      pu.symmetryLowering = {0.02, 0.0, 0.07, 20};
      pu.symmetryNotReached = 17;
    }
    u.participants.push_back(pu);
  }
  return u;
}

SweepStudy studyOfOthers() {
  SweepStudy study = loadSweepStudy("studies/burkett2004.yaml");
  study.participants.resize(1);
  study.participants[0].name = "someone else";
  return study;
}

std::string section(const std::string& md, const std::string& heading) {
  const auto at = md.find(heading);
  if (at == std::string::npos) return "";
  return md.substr(at, md.find("\n## ", at + 1) - at);
}

TEST(SweepSymmetryReport, Table4StarsComeFromThePublishedColumns) {
  // Burkett 2004 Table 4's `*`: P1 0.100, P2 0.125, P3 0.200, P4 0.130 m.
  const std::vector<std::pair<std::string, double>> stars = {
      {"P1", 0.100}, {"P2", 0.125}, {"P3", 0.200}, {"P4", 0.130}};
  for (const auto& [name, lowering] : stars) {
    const PublishedParticipant* pub = findPublished(name);
    std::vector<double> measured;
    for (const auto& row : pub->table4) measured.push_back(row.measuredProsthetic);
    const int star = calcTable4SymmetryRow(*pub, measured);
    ASSERT_GE(star, 0) << name;
    EXPECT_DOUBLE_EQ(pub->table4[static_cast<std::size_t>(star)].lowering, lowering) << name;
  }
}

TEST(SweepSymmetryReport, SectionShowsTheParticipantWithASoundLimbTimeOnly) {
  const SweepResults r = makeResults();
  const UncertaintyResults u = makeUncertainty(r);
  const std::string md = makeSweepReport(studyOfOthers(), r, &u).at("report.md");
  const std::string symmetry = section(md, "## Symmetry with the sound limb");
  ASSERT_FALSE(symmetry.empty()) << md;
  EXPECT_NE(symmetry.find("| P1 | 0.499 | 0.050 | 0.000 | no | 0.4300 | -69 | 0.862 | 0.000 - 0.070 | 17 of 20 |"),
            std::string::npos)
      << symmetry;
  EXPECT_EQ(symmetry.find("| Q |"), std::string::npos) << symmetry;
  // Table 4's `*` (0.100 m) beside ours (0 m, not reached).
  const std::string star = section(md, "### Best symmetry: Table 4's `*` beside this model");
  EXPECT_NE(star.find("| P1 | 0.100 | 0.000 (not reached) | -0.100 |"), std::string::npos) << star;
  // The text table under P1's section says it; Q's does not.
  EXPECT_NE(section(md, "## P1").find("best symmetry with the sound limb (0.499 s): not reached; closest 0.000 m"),
            std::string::npos);
  EXPECT_EQ(section(md, "## Q").find("best symmetry"), std::string::npos);
}

TEST(SweepSymmetryReport, NoSectionsWithoutASoundLimbTime) {
  SweepResults r = makeResults();
  r.participants[0].symmetry = SymmetryLowering{};
  const std::string md = makeSweepReport(studyOfOthers(), r).at("report.md");
  EXPECT_EQ(md.find("Symmetry with the sound limb"), std::string::npos);
  EXPECT_EQ(md.find("Best symmetry"), std::string::npos);
  EXPECT_EQ(md.find("best symmetry"), std::string::npos);
}

TEST(SweepSymmetryReport, JsonKeysWithUnitsForTheParticipantWithASoundLimbTime) {
  const SweepResults r = makeResults();
  const UncertaintyResults u = makeUncertainty(r);
  const Json j = Json::parse(formatSweepJson(r, &u));
  const Json& p1 = j["participants"][0];
  ASSERT_TRUE(p1.contains("symmetry"));
  const Json& s = p1["symmetry"];
  EXPECT_DOUBLE_EQ(s["sound_limb_swing_time_s"].get<double>(), 0.499);
  EXPECT_DOUBLE_EQ(s["lowering_m"].get<double>(), 0.0);
  EXPECT_FALSE(s["reached"].get<bool>());
  EXPECT_DOUBLE_EQ(s["prosthetic_swing_time_s"].get<double>(), 0.430);
  EXPECT_NEAR(s["gap_s"].get<double>(), -0.069, 1e-12);
  EXPECT_NEAR(s["ratio"].get<double>(), 0.430 / 0.499, 1e-12);
  EXPECT_DOUBLE_EQ(p1["symmetry_lowering_interval_m"]["p95"].get<double>(), 0.07);
  EXPECT_EQ(p1["symmetry_samples_not_reached"].get<int>(), 17);
  const Json& q = j["participants"][1];
  EXPECT_FALSE(q.contains("symmetry"));
  EXPECT_FALSE(q.contains("symmetry_lowering_interval_m"));
  EXPECT_FALSE(q.contains("symmetry_samples_not_reached"));
}

TEST(SweepSymmetryReport, FigureMarksTheSoundLimbAndTheSymmetryLowering) {
  const SweepResults r = makeResults();
  const std::string p1 = makeSwingTimeFigure(r.participants[0], nullptr).render();
  EXPECT_NE(p1.find("sound limb (participant file)"), std::string::npos);
  EXPECT_NE(p1.find("our best symmetry (not reached)"), std::string::npos);
  const std::string q = makeSwingTimeFigure(r.participants[1], nullptr).render();
  EXPECT_EQ(q.find("sound limb"), std::string::npos);
  EXPECT_EQ(q.find("symmetry"), std::string::npos);
}

}  // namespace
}  // namespace swingsim
