// report.md of a knee-axis sweep (report/sweep_markdown.h) on hand-made results: Burkett's
// Table 4 rows beside ours with the differences in ms, the fastest lowering in the summary,
// its table and its mark in the text table, the added-mass table, a participant without a
// swing end and the points that failed.
#include "report/sweep_markdown.h"

#include <gtest/gtest.h>

#include <string>

#include "study/sweep_study.h"
#include "sweep/burkett_published.h"

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

SweepPoint failedAt(double lowering, const std::string& failure) {
  SweepPoint pt;
  pt.lowering = lowering;
  pt.ran = true;
  pt.failure = failure;
  return pt;
}

// P1 (a Burkett participant, Table 4 at 0, 0.05, 0.10 and 0.15 m) fastest at 0.05 m and
// failing at 0.15 m; Q (not in the paper) without a swing end.
SweepResults makeResults() {
  ParticipantSweep p1;
  p1.name = "P1";
  p1.published = findPublished("P1");  // as runSweep looks it up
  p1.points = {endedAt(0, 0.430), endedAt(0.05, 0.420), endedAt(0.10, 0.425),
               failedAt(0.15, "the knee never came back into the zone of stability")};
  p1.best = 1;
  ParticipantSweep q;
  q.name = "Q";
  q.points = {failedAt(0, "the thigh never reached its target flexion")};
  SweepResults results;
  results.study = "hand-made";
  results.participants = {p1, q};
  return results;
}

// The shipped study's assumptions, with a participant named after neither P1 nor Q, so the
// report draws no stick figures of the hand-made swings (they have no trajectory).
SweepStudy studyOfOthers() {
  SweepStudy study = loadSweepStudy("studies/burkett2004.yaml");
  study.participants.resize(1);
  study.participants[0].name = "someone else";
  return study;
}

int countOf(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

TEST(SweepMarkdown, Table4RowsCarryOursAndTheDifferencesInMilliseconds) {
  const SweepStudy study = studyOfOthers();
  const auto files = makeSweepReport(study, makeResults());
  const std::string& md = files.at("report.md");
  EXPECT_EQ(md.rfind("# Knee-axis sweep: " + study.name + "\n", 0), 0u);
  // Burkett's Table 4 for P1: lowering, model, measured; ours; ours - model; ours - measured.
  EXPECT_NE(md.find("| P1 | 0.000 | 0.420 | 0.463 | 0.430 | +10 ms | -33 ms |\n"), std::string::npos) << md;
  EXPECT_NE(md.find("| P1 | 0.050 | 0.405 | 0.423 | 0.420 | +15 ms | -3 ms |\n"), std::string::npos);
  EXPECT_NE(md.find("| P1 | 0.100 | 0.375 | 0.410 | 0.425 | +50 ms | +15 ms |\n"), std::string::npos);
  EXPECT_NE(md.find("| P1 | 0.150 | 0.465 | 0.418 | no end: knee stays flexed |  |  |\n"), std::string::npos);
  EXPECT_EQ(countOf(md, "| Q | 0."), 0) << "Q is not in the paper: no Table 4 rows";
  // Three rows ended a swing; only the one at 0.10 m is more than 20 ms from Burkett's model.
  EXPECT_NE(
      md.find("Agreement with the paper: 2 of 3 Table 4 rows simulated here are within 20 ms of Burkett's model.\n"),
      std::string::npos);
  EXPECT_NE(md.find("(1 rows differ from Burkett's model by more than 20 ms)"), std::string::npos);
}

TEST(SweepMarkdown, FastestLoweringIsNamedInTheSummaryItsTableAndMarkedOnce) {
  const auto files = makeSweepReport(studyOfOthers(), makeResults());
  const std::string& md = files.at("report.md");
  EXPECT_NE(md.find("- P1: fastest at 0.050 m (swing time 0.4200 s); Burkett's model: 0.100 m.\n"), std::string::npos)
      << md;
  EXPECT_NE(md.find("- Q: no lowering ended a swing.\n"), std::string::npos);
  EXPECT_NE(
      md.find("- P1: fastest at 0.050 m, slower beyond it (as in the paper); Burkett's model: fastest at 0.100 m.\n"),
      std::string::npos);
  // Fastest-lowering table: ours, its time, Burkett's, the difference, bounce, toe strike.
  EXPECT_NE(md.find("| P1 | 0.050 | 0.4200 | 0.100 | -0.050 | no | no |\n"), std::string::npos);
  EXPECT_NE(md.find("| Q | none ended |  |  |  |  |  |\n"), std::string::npos);
  // The text table marks the fastest row, and only it.
  EXPECT_EQ(countOf(md, "<- fastest"), 1);
  const std::size_t mark = md.find("<- fastest");
  const std::size_t lineStart = md.rfind('\n', mark) + 1;
  EXPECT_EQ(md.substr(lineStart, 14), "       0.050  ") << md.substr(lineStart, mark - lineStart);
}

TEST(SweepMarkdown, FailuresAreListedWholeAndPointedTo) {
  const auto files = makeSweepReport(studyOfOthers(), makeResults());
  const std::string& md = files.at("report.md");
  EXPECT_NE(md.find("## Points that failed\n\n- the knee never came back into the zone of stability\n"
                    "- the thigh never reached its target flexion\n"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("- the points that failed (\"Points that failed\").\n"), std::string::npos);
  EXPECT_NE(md.find("- how sure the optimum is: rerun with `--uncertainty N`.\n"), std::string::npos);
  EXPECT_EQ(md.find("## How sure is the optimum"), std::string::npos) << "no uncertainty analysis ran";
  EXPECT_EQ(md.find("## Lowering and added shank mass together"), std::string::npos) << "no added mass swept";
  EXPECT_EQ(md.find("## Terminal impact"), std::string::npos) << "the check did not run";
}

TEST(SweepMarkdown, AddedMassTableGivesTheGainOverLoweringAlone) {
  SweepResults results = makeResults();
  SweepPoint withMass = endedAt(0.05, 0.410);
  withMass.added.mass = 0.5;
  withMass.added.distanceBelowKnee = 0.2;
  results.participants[0].massPoints = {withMass};
  results.participants[0].bestWithMass = 0;
  const std::string md = makeSweepReport(studyOfOthers(), results).at("report.md");
  EXPECT_NE(md.find("## Lowering and added shank mass together (beyond the paper)\n"), std::string::npos);
  EXPECT_NE(md.find("| P1 | 0.050 | 0.50 | 0.200 | 0.4100 | -10 ms |\n"), std::string::npos) << md;
}

TEST(SweepMarkdown, WritesTheFiguresItLinksAndTheCsv) {
  const auto files = makeSweepReport(studyOfOthers(), makeResults());
  const std::string& md = files.at("report.md");
  for (const std::string name : {"figures/P1-swing-time.svg", "figures/P1-knee-flexion.svg", "figures/Q-swing-time.svg",
                                 "figures/Q-knee-flexion.svg"}) {
    ASSERT_EQ(files.count(name), 1u) << name;
    EXPECT_NE(md.find("](" + name + ")"), std::string::npos) << name << " is linked";
    EXPECT_EQ(files.at(name).rfind("<svg", 0), 0u) << name;
  }
  EXPECT_EQ(files.count("figures/P1-filmstrip.svg"), 0u) << "no participant of the study: no stick figures";
  EXPECT_EQ(files.count("sweep.csv"), 1u);
  EXPECT_EQ(files.count("report.html"), 1u);
  EXPECT_NE(files.at("sweep.csv").find("P1,0.050,"), std::string::npos);
}

}  // namespace
}  // namespace swingsim
