// The missing moment's and force's figures (report/missing_plot.h): two panels by the
// direction of motion, each sample drawn in its own panel, the region shaded and labelled.
#include "report/missing_plot.h"

#include <gtest/gtest.h>

#include <string>

namespace swingsim {
namespace {

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

TEST(MissingMomentPlot, PanelsByDirectionWithTheRegionShadedAndLabelled) {
  MissingMoment m;
  // Three flexing samples, four extending; the extending ones near extension miss +1.7 N m.
  for (double k : {20.0, 40.0, 60.0}) {
    m.kneeDeg.push_back(k);
    m.kneeRateDegS.push_back(200.0);
    m.momentNm.push_back(0.1);
    m.bandNm.push_back(0.5);
  }
  for (double k : {12.0, 15.0, 18.0, 50.0}) {
    m.kneeDeg.push_back(k);
    m.kneeRateDegS.push_back(-300.0);
    m.momentNm.push_back(k < 20 ? 1.7 : 0.0);
    m.bandNm.push_back(0.4);
  }
  MissingMomentRegion r;
  r.extending = true;
  r.moment = 1.7;
  r.kneeLowDeg = 12;
  r.kneeHighDeg = 18;
  m.regions.push_back(r);
  const std::string svg = renderMissingMomentSvg(m, "missing");
  EXPECT_NE(svg.find("while the knee flexes"), std::string::npos);
  EXPECT_NE(svg.find("while the knee extends"), std::string::npos);
  EXPECT_NE(svg.find("+1.7 N m at 12-18 deg"), std::string::npos) << "the region's label";
  EXPECT_EQ(count(svg, "+1.7 N m at"), 1u) << "in the extending panel only";
  EXPECT_NE(svg.find("95 % noise band of one sample"), std::string::npos);
  EXPECT_EQ(count(svg, "<circle"), 7u + 2u) << "every sample once (and a legend marker per panel)";
}

TEST(MissingForcePlot, PanelsByDirectionWithTheRegionShadedAndLabelled) {
  MissingForce m;
  // Two compressing samples, three extending; the extending ones at 20-24 mm miss -40 N.
  for (double x : {5.0, 15.0}) {
    m.positionMm.push_back(x);
    m.speedMmS.push_back(50.0);
    m.forceN.push_back(1.0);
    m.noiseN.push_back(2.0);
  }
  for (double x : {20.0, 22.0, 24.0}) {
    m.positionMm.push_back(x);
    m.speedMmS.push_back(-80.0);
    m.forceN.push_back(-40.0);
    m.noiseN.push_back(2.0);
  }
  MissingForceRegion r;
  r.extending = true;
  r.force = -40;
  r.positionLowMm = 20;
  r.positionHighMm = 24;
  m.regions.push_back(r);
  const std::string svg = renderMissingForceSvg(m, "missing");
  EXPECT_NE(svg.find("while the piston compresses"), std::string::npos);
  EXPECT_NE(svg.find("while the piston extends"), std::string::npos);
  EXPECT_NE(svg.find("measured piston position (mm)"), std::string::npos);
  EXPECT_EQ(count(svg, "-40 N at 20-24 mm"), 1u) << "the region's label, in the extending panel only";
  EXPECT_EQ(count(svg, "<circle"), 5u + 2u) << "every sample once (and a legend marker per panel)";
}

// A bench record's thousands of samples are thinned evenly, and the legend says so.
TEST(MissingForcePlot, ThousandsOfSamplesAreThinnedEvenly) {
  MissingForce m;
  for (int i = 0; i < 5000; ++i) {
    m.positionMm.push_back(i * 0.005);
    m.speedMmS.push_back(10.0);
    m.forceN.push_back(0.0);
    m.noiseN.push_back(1.0);
  }
  const std::string svg = renderMissingForceSvg(m, "missing");
  EXPECT_EQ(count(svg, "<circle"), 1667u + 2u) << "one sample in 3 (and a legend marker per panel)";
  EXPECT_NE(svg.find("one sample in 3"), std::string::npos);
}

}  // namespace
}  // namespace swingsim
