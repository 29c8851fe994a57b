// report.html of a sweep: well-formed, self-contained, every figure inline, one animated
// stick figure per participant whose segments keep the leg's lengths in every frame.
#include "report/sweep_html.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <vector>

#include "core/text_format.h"
#include "html_checks.h"
#include "model/leg_parameters.h"
#include "report/markdown_html.h"
#include "report/stick_figure_animation.h"
#include "report/sweep_markdown.h"
#include "report/sweep_report_parts.h"
#include "study/sweep_study.h"

namespace swingsim {
namespace {

using testing::checkTagsBalanced;
using ::testing::HasSubstr;
using ::testing::Not;

// Endpoints are written with 2 decimals (0.005 px of rounding each), so a segment's length
// can be off by up to 0.01 px: in metres at the figure's scale, with a margin.
constexpr double kLengthTol = 0.02 / kStickFigurePxPerMetre;  // m

// Two participants, lowerings 0, 0.05 and 0.10 m: small enough for a unit test, and the
// fastest is not at the standard location for either.
SweepStudy smallStudy() {
  SweepStudy s = loadSweepStudy("studies/burkett2004.yaml");
  s.participants.resize(2);
  s.loweringStep = 0.05;
  s.loweringMax = 0.10;
  s.addedMasses = {0.0};
  s.addedMassDistances.clear();
  s.includePublishedLowerings = false;
  return s;
}

const SweepResults& sweepOnce() {
  static const SweepResults results = runSweep(smallStudy(), 0);
  return results;
}

const std::map<std::string, std::string>& reportOnce() {
  static const auto files = makeSweepReport(smallStudy(), sweepOnce());
  return files;
}

int countOf(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

// The numbers of `values="a;b;c"` of the <animate> of `attribute` inside `element`.
std::vector<double> animatedValues(const std::string& element, const std::string& attribute) {
  const std::size_t at = element.find("attributeName=\"" + attribute + "\"");
  EXPECT_NE(at, std::string::npos) << attribute;
  if (at == std::string::npos) return {};
  const std::size_t start = element.find("values=\"", at) + 8;
  std::stringstream in(element.substr(start, element.find('"', start) - start));
  std::vector<double> values;
  for (std::string item; std::getline(in, item, ';');) values.push_back(std::stod(item));
  return values;
}

// The lengths (m, at the figure's scale) of the line of class `name` in every frame.
std::vector<double> segmentLengths(const std::string& svg, const std::string& name) {
  const std::size_t at = svg.find("<line class=\"" + name + "\"");
  EXPECT_NE(at, std::string::npos) << name;
  if (at == std::string::npos) return {};
  const std::string element = svg.substr(at, svg.find("</line>", at) - at);
  const auto x1 = animatedValues(element, "x1"), y1 = animatedValues(element, "y1");
  const auto x2 = animatedValues(element, "x2"), y2 = animatedValues(element, "y2");
  EXPECT_TRUE(x1.size() == y1.size() && x1.size() == x2.size() && x1.size() == y2.size()) << name;
  std::vector<double> lengths;
  for (std::size_t k = 0; k < x1.size(); ++k)
    lengths.push_back(std::hypot(x2[k] - x1[k], y2[k] - y1[k]) / kStickFigurePxPerMetre);
  return lengths;
}

TEST(SweepHtml, IsWrittenBesideTheMarkdownAndWellFormed) {
  const auto& files = reportOnce();
  ASSERT_EQ(files.count("report.html"), 1u);
  const std::string& html = files.at("report.html");
  EXPECT_EQ(checkTagsBalanced(html), "");
  EXPECT_THAT(html, HasSubstr("<h1 id=\"knee-axis-sweep-burkett2004\">Knee-axis sweep: burkett2004</h1>"));
}

TEST(SweepHtml, CarriesTheMarkdownsHeadingsAndTables) {
  const auto& files = reportOnce();
  const std::string& md = files.at("report.md");
  const std::string& html = files.at("report.html");
  std::istringstream in(md);
  int headings = 0, tables = 0;
  bool inTable = false, inCode = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("```", 0) == 0) inCode = !inCode;
    if (inCode) continue;
    if (line.rfind("## ", 0) == 0) {
      ++headings;
      EXPECT_THAT(html, HasSubstr("\">" + escapeHtml(line.substr(3)) + "</h2>"));
    }
    if (!inTable && line.rfind("|", 0) == 0) ++tables;
    inTable = line.rfind("|", 0) == 0;
  }
  EXPECT_GT(headings, 3);
  EXPECT_EQ(countOf(html, "<h2 id="), headings);
  EXPECT_EQ(countOf(html, "<table>"), tables);
}

TEST(SweepHtml, HasEveryFigureInlineAndNoExternalReference) {
  const auto& files = reportOnce();
  const std::string& html = files.at("report.html");
  int figureSvgs = 0;
  for (const auto& [name, contents] : files)
    if (name.size() > 4 && name.compare(name.size() - 4, 4, ".svg") == 0) figureSvgs += countOf(contents, "<svg");
  EXPECT_GT(figureSvgs, 0);
  const int animated = countOf(html, "class=\"stick-figure\"");
  EXPECT_EQ(countOf(html, "<svg"), figureSvgs + animated);
  for (const char* external : {"src=", "href=", "<script", "<img", "<link", "@import"})
    EXPECT_THAT(html, Not(HasSubstr(external))) << external;
  EXPECT_EQ(countOf(html, "url("), countOf(html, "url(#")) << "only references inside the page";
  // The figures' clip paths are renamed per figure, so no id is defined twice.
  EXPECT_EQ(countOf(html, "id=\"f1-"), countOf(files.at("figures/P1-swing-time.svg"), "id=\""));
}

TEST(SweepHtml, AnimatesEachParticipantsFastestSwingWithItsSegmentLengths) {
  const SweepStudy study = smallStudy();
  const std::string& html = reportOnce().at("report.html");
  ASSERT_EQ(countOf(html, "class=\"stick-figure\""), static_cast<int>(sweepOnce().participants.size()));
  EXPECT_EQ(countOf(html, "repeatCount=\"indefinite\""), 12 * countOf(html, "class=\"stick-figure\""));
  for (const auto& ps : sweepOnce().participants) {
    ASSERT_GE(ps.best, 0) << ps.name;
    const SweepPoint& b = ps.points[static_cast<std::size_t>(ps.best)];
    const std::size_t at = html.find("\">" + ps.name + "</h2>");
    ASSERT_NE(at, std::string::npos) << ps.name;
    const std::size_t svgAt = html.find("class=\"stick-figure\"", at);
    const std::string svg = html.substr(svgAt, html.find("</svg>", svgAt) - svgAt);
    EXPECT_THAT(html.substr(svgAt, html.find("</figcaption>", svgAt) - svgAt),
                HasSubstr(ps.name + ", fastest swing: knee axis lowered " + fmt("%.3f", b.lowering) +
                          " m, swing time " + fmt("%.4f", b.result.swingTime) + " s"));
    const LegGeometry g = calcLegGeometry(*sweep_report_parts::participantNamed(study, ps.name), b.lowering);
    const auto thigh = segmentLengths(svg, "thigh"), shank = segmentLengths(svg, "shank");
    ASSERT_GT(thigh.size(), 10u) << ps.name << ": frames";
    for (std::size_t k = 0; k < thigh.size(); ++k) {
      EXPECT_NEAR(thigh[k], g.thighLength, kLengthTol) << ps.name << " frame " << k;
      EXPECT_NEAR(shank[k], g.shankLength, kLengthTol) << ps.name << " frame " << k;
    }
  }
}

TEST(StickFigureAnimation, RunsInRealTimeAndRefusesASwingWithoutATrajectory) {
  const SweepPoint& b = sweepOnce().participants[0].points[static_cast<std::size_t>(sweepOnce().participants[0].best)];
  const std::string svg = renderStickFigureAnimation(b.result, 0.9);
  // The duration is the last frame's time (within one sample of the swing end) plus the hold.
  const std::size_t at = svg.find("dur=\"") + 5;
  const double duration = std::stod(svg.substr(at, svg.find('s', at) - at));
  EXPECT_NEAR(duration, b.result.swingTime + kStickFigureHold, kStickFigureFrameStep);
  EXPECT_LE(duration, b.result.swingTime + kStickFigureHold + 1e-4);
  SwingResult empty;
  empty.swingTime = 0.5;
  EXPECT_THROW(renderStickFigureAnimation(empty, 0.9), std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
