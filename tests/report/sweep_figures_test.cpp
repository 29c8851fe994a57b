// The sweep report's figures (report/sweep_figures.h) on hand-made results: what each
// figure shows (Table 4's points and Burkett's optimum only for a participant of the paper,
// our fastest, the uncertainty band; a knee curve every 50 mm of lowering that ended; a
// stick figure every 40 ms to the swing end; a tornado row per assumption).
#include "report/sweep_figures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "sweep/burkett_published.h"

namespace swingsim {
namespace {

int countOf(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

// A knee trajectory of a few samples and a foot 0.5 m below the hip.
SweepPoint endedAt(double lowering, double swingTime) {
  SweepPoint pt;
  pt.lowering = lowering;
  pt.ran = pt.ok = true;
  pt.result.swingTime = swingTime;
  for (int i = 0; i <= 50; ++i) {
    auto& tr = pt.result.trajectory;
    tr.time.push_back(0.01 * i);
    tr.kneeFlexion.push_back(std::sin(0.06 * i));
    tr.kneeX.push_back(0.1);
    tr.kneeY.push_back(0.5);
    tr.ankleX.push_back(0.2);
    tr.ankleY.push_back(0.1);
    tr.toeX.push_back(0.3);
    tr.toeY.push_back(0.05);
  }
  return pt;
}

ParticipantSweep sweepNamed(const std::string& name) {
  ParticipantSweep ps;
  ps.name = name;
  ps.published = findPublished(name);  // as runSweep looks it up
  SweepPoint failed;
  failed.lowering = 0.1;
  failed.ran = true;
  ps.points = {endedAt(0, 0.43), endedAt(0.025, 0.425), endedAt(0.05, 0.42), failed};
  ps.best = 2;
  return ps;
}

TEST(SweepFigures, SwingTimeFigureShowsThePapersPointsOnlyForItsParticipants) {
  const std::string p1 = makeSwingTimeFigure(sweepNamed("P1"), nullptr).render();
  EXPECT_NE(p1.find("P1: swing time vs knee-axis lowering"), std::string::npos);
  for (const char* label :
       {"this model", "Burkett model (Table 4)", "measured prosthetic (Table 4)", "Burkett's fastest", "our fastest"})
    EXPECT_NE(p1.find(label), std::string::npos) << label;
  EXPECT_EQ(p1.find("5-95 %"), std::string::npos) << "no band without the uncertainty analysis";
  const std::string other = makeSwingTimeFigure(sweepNamed("Q"), nullptr).render();
  EXPECT_EQ(other.find("Table 4"), std::string::npos);
  EXPECT_EQ(other.find("Burkett's fastest"), std::string::npos);
  ParticipantSweep none = sweepNamed("Q");
  none.best = -1;
  EXPECT_EQ(makeSwingTimeFigure(none, nullptr).render().find("our fastest"), std::string::npos);
  ParticipantUncertainty pu;
  pu.name = "P1";
  pu.bandLowerings = {0, 0.05};
  pu.bandP05 = {0.41, 0.40};
  pu.bandP95 = {0.45, 0.44};
  EXPECT_NE(makeSwingTimeFigure(sweepNamed("P1"), &pu).render().find("5-95 % over the assumptions"), std::string::npos);
}

TEST(SweepFigures, KneeFlexionHasACurveEvery50MillimetresThatEnded) {
  const std::string svg = makeKneeFlexionFigure(sweepNamed("P1"), 6.0).render();
  EXPECT_NE(svg.find(">standard<"), std::string::npos);
  EXPECT_NE(svg.find(">std +50 mm<"), std::string::npos);
  EXPECT_EQ(svg.find("std +25 mm"), std::string::npos) << "not on the 50 mm grid";
  EXPECT_EQ(svg.find("std +100 mm"), std::string::npos) << "no swing end";
  EXPECT_NE(svg.find("zone of stability (&lt; 6 deg)"), std::string::npos);
}

TEST(SweepFigures, FilmstripDrawsAFrameEvery40MillisecondsToTheSwingEnd) {
  // 0.30 s: frames at 0, 0.04, ..., 0.28 s.
  const auto frames = [](double swingTime) {
    SweepPoint pt = endedAt(0, swingTime);
    const std::string svg = makeFilmstrip("P1 at the standard knee location", pt.result, 0.9).render();
    return countOf(svg, "stroke-linejoin=\"round\"");
  };
  EXPECT_EQ(frames(0.30), 8);
  EXPECT_EQ(frames(0.0), 1);
  EXPECT_EQ(frames(5.0), 14) << "at most 14 frames";
}

TEST(SweepFigures, TornadoHasARowPerAssumptionAndNamesRunsWithoutASwingEnd) {
  ParticipantUncertainty pu;
  pu.name = "P1";
  pu.nominal.lowerings = {0, 0.05, 0.10};
  pu.nominal.swingTimes = {0.43, 0.42, 0.425};
  pu.nominal.best = 1;
  SensitivityRow moves;
  moves.assumption = "stop_restitution";
  moves.name = "stop restitution";
  moves.lowValue = 0.3;
  moves.highValue = 0.5;
  moves.low = moves.high = pu.nominal;
  moves.high.best = 2;
  SensitivityRow ends = moves;
  ends.name = "never ends";
  ends.low.best = -1;
  pu.sensitivity = {moves, ends};
  const std::string svg = makeTornadoFigure(pu).render();
  EXPECT_NE(svg.find("P1: change in the fastest lowering, one assumption at a time"), std::string::npos);
  EXPECT_NE(svg.find("stop restitution ["), std::string::npos);
  EXPECT_EQ(countOf(svg, "(no swing end)"), 1);
  EXPECT_NE(svg.find("never ends ["), std::string::npos);
}

}  // namespace
}  // namespace swingsim
