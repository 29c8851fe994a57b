#include "report/svg_plot.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace swingsim {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

int countOf(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

TEST(NiceTicks, UseOneTwoFiveStepsInsideTheRange) {
  const auto t = calcNiceTicks(0.0, 0.96, 6);
  ASSERT_GE(t.size(), 4u);
  EXPECT_NEAR(t[1] - t[0], 0.2, 1e-12);
  EXPECT_GE(t.front(), 0.0);
  EXPECT_LE(t.back(), 0.96);
  const auto u = calcNiceTicks(-730.0, 410.0, 6);
  EXPECT_NEAR(u[1] - u[0], 200.0, 1e-9);
  EXPECT_TRUE(calcNiceTicks(1.0, 1.0).empty());
  EXPECT_TRUE(calcNiceTicks(0.0, std::nan("")).empty());
}

TEST(SvgPlot, RendersAxesLabelsLegendAndEscapesText) {
  SvgPlot plot(800, 360);
  plot.setTitle("force <measured & predicted>");
  plot.setXLabel("time (s)");
  plot.setYLabel("force (N)");
  plot.addBand(0.1, 0.2, "phase 1", "#E69F00");
  plot.addBand(0.5, 0.6, "phase 1", "#E69F00");
  plot.addLine({0, 0.5, 1}, {0, 100, -50}, "measured", "#000000");
  plot.addPoints({0.25}, {10}, "peaks", "#D55E00");
  plot.addHLine(0, "zero", "#999999");
  const std::string svg = plot.render();
  EXPECT_THAT(svg, HasSubstr("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800.0\""));
  EXPECT_THAT(svg, HasSubstr("force &lt;measured &amp; predicted&gt;"));
  EXPECT_THAT(svg, HasSubstr(">time (s)</text>"));
  EXPECT_THAT(svg, HasSubstr(">force (N)</text>"));
  // Two bands drawn, one legend entry for their shared label.
  EXPECT_EQ(countOf(svg, "fill-opacity=\"0.18\""), 2);
  EXPECT_EQ(countOf(svg, ">phase 1</text>"), 1);
  EXPECT_EQ(countOf(svg, ">measured</text>"), 1);
  EXPECT_EQ(countOf(svg, ">zero</text>"), 1);
  EXPECT_THAT(svg, HasSubstr("<circle"));
  EXPECT_EQ(countOf(svg, "<svg"), 1);
  EXPECT_EQ(countOf(svg, "</svg>"), 1);
}

TEST(SvgPlot, NonFiniteValuesBreakTheLine) {
  SvgPlot plot;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  plot.addLine({0, 1, 2, 3, 4}, {0, 1, nan, 3, 4}, "", "#000");
  const std::string svg = plot.render();
  const auto start = svg.find("<path d=\"");
  ASSERT_NE(start, std::string::npos);
  const std::string d = svg.substr(start, svg.find('"', start + 9) - start);
  EXPECT_EQ(countOf(d, "M"), 2);
  EXPECT_EQ(countOf(d, "L"), 2);
  EXPECT_THAT(svg, Not(HasSubstr("nan")));
}

TEST(SvgPlot, FixedRangeMapsDataToPixelsLinearly) {
  // Plot area is 800 - 74 - 18 = 708 px wide starting at x = 74 (layout constants).
  SvgPlot plot(800, 300);
  plot.setXRange(0, 10);
  plot.setYRange(0, 1);
  plot.addLine({0, 5, 10}, {0.5, 0.5, 0.5}, "", "#000");
  const std::string svg = plot.render();
  EXPECT_THAT(svg, HasSubstr("M74.0 "));
  EXPECT_THAT(svg, HasSubstr("L428.0 "));
  EXPECT_THAT(svg, HasSubstr("L782.0 "));
}

// A band between two curves is one closed polygon per finite run: along the highs, back
// along the lows; a NaN splits it in two.
TEST(SvgPlot, FillIsAClosedPolygonPerFiniteRun) {
  SvgPlot plot(800, 300);
  plot.setXRange(0, 10);
  plot.setYRange(0, 1);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  plot.addFill({0, 5, 10}, {0.25, 0.25, 0.25}, {0.75, 0.75, 0.75}, "5-95 %", "#0072B2");
  const std::string one = plot.render();
  // Plot area 708 x 216 px from (74, 34): y = 0.75 at 88, y = 0.25 at 196.
  EXPECT_THAT(one, HasSubstr("M74.0 88.0L428.0 88.0L782.0 88.0L782.0 196.0L428.0 196.0L74.0 196.0Z"));
  EXPECT_THAT(one, HasSubstr("5-95 %"));  // in the legend
  SvgPlot gap(800, 300);
  gap.addFill({0, 1, 2, 3, 4}, {0, 0, nan, 0, 0}, {1, 1, 1, 1, 1}, "", "#000");
  EXPECT_EQ(countOf(gap.render(), "Z\" fill=\"#000\""), 2);
  EXPECT_THROW(gap.addFill({0, 1}, {0}, {1, 1}, "", "#000"), std::invalid_argument);
}

// Text labels replace the numeric y ticks (a tornado's rows); the left margin grows for them.
TEST(SvgPlot, YTickLabelsReplaceNumbersAndWidenTheMargin) {
  SvgPlot plot(800, 300);
  plot.setXRange(0, 10);
  plot.setYRange(0, 3);
  plot.addLine({0, 10}, {1, 1}, "", "#000");
  plot.setYTickLabels({{1, "knee friction <Tc>"}, {2, "COM rule"}}, 300);
  const std::string svg = plot.render();
  EXPECT_THAT(svg, HasSubstr(">knee friction &lt;Tc&gt;</text>"));
  EXPECT_THAT(svg, HasSubstr(">COM rule</text>"));
  EXPECT_THAT(svg, Not(HasSubstr(">2.5</text>")));  // no numeric tick
  EXPECT_THAT(svg, HasSubstr("M300.0 "));           // the plot starts at the new margin
  EXPECT_THROW(plot.setYTickLabels({}, 790), std::invalid_argument);
}

// The legend box (white, grey frame) in the corner where it hides the least data.
TEST(SvgPlot, LegendGoesToTheCornerWithTheLeastData) {
  auto legendX = [](const std::string& svg) {
    const auto p = svg.find("fill-opacity=\"0.85\" stroke=\"#999\"");
    const auto rect = svg.rfind("<rect x=\"", p);
    return std::stod(svg.substr(rect + 9));
  };
  auto legendY = [](const std::string& svg) {
    const auto p = svg.find("fill-opacity=\"0.85\" stroke=\"#999\"");
    const auto y = svg.rfind(" y=\"", p);
    return std::stod(svg.substr(y + 4));
  };
  SvgPlot rising(800, 300);  // data from bottom left to top right: the top left is free
  rising.setXRange(0, 1);
  rising.setYRange(0, 1);
  rising.addLine({0, 1}, {0, 1}, "rising", "#000");
  rising.addLine({0.6, 1}, {1, 0.6}, "", "#000");
  const std::string a = rising.render();
  EXPECT_LT(legendX(a), 200) << "left";
  EXPECT_LT(legendY(a), 100) << "top";

  SvgPlot falling(800, 300);  // a line across the top: the legend goes below it
  falling.setXRange(0, 1);
  falling.setYRange(0, 1);
  falling.addLine({0, 1}, {0.95, 0.95}, "flat top", "#000");
  const std::string b = falling.render();
  EXPECT_GT(legendY(b), 150) << "bottom";

  SvgPlot empty(800, 300);  // nothing in the way: top right, as before
  empty.setXRange(0, 1);
  empty.setYRange(0, 1);
  empty.addLine({0.0, 0.1}, {0.0, 0.1}, "corner", "#000");
  const std::string c = empty.render();
  EXPECT_GT(legendX(c), 500) << "right";
  EXPECT_LT(legendY(c), 100) << "top";
}

TEST(SvgPlot, StacksPanelsVerticallyWithDistinctClipIds) {
  SvgPlot a(800, 300), b(800, 200);
  a.addLine({0, 1}, {0, 1}, "a", "#000");
  b.addLine({0, 1}, {1, 0}, "b", "#000");
  const std::string svg = renderStackedSvg({a, b}, "two panels");
  EXPECT_EQ(countOf(svg, "<svg"), 1);
  EXPECT_EQ(countOf(svg, "<clipPath id=\"clip0_30\""), 1);
  EXPECT_EQ(countOf(svg, "<clipPath id=\"clip0_336\""), 1);
  EXPECT_THAT(svg, HasSubstr(">two panels</text>"));
}

TEST(SvgPlot, RejectsBadSizesAndRangesAndMismatchedSeries) {
  EXPECT_THROW(SvgPlot(50, 50), std::invalid_argument);
  SvgPlot plot;
  EXPECT_THROW(plot.setXRange(1, 1), std::invalid_argument);
  EXPECT_THROW(plot.addLine({0, 1}, {0}, "x", "#000"), std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
