#include "report/missing_plot.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "core/text_format.h"
#include "report/svg_plot.h"

namespace swingsim {

namespace {

constexpr double kMomentBinDeg = 5.0;             // as the moment's regions' bins (identify/missing_moment.cpp)
constexpr std::size_t kMaxPointsPerPanel = 2000;  // a bench record has thousands of samples: thinned evenly

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// One direction's samples and regions, in the figure's units.
struct Panel {
  std::string title, xLabel, yLabel;
  double binWidth = 1;
  std::vector<double> x, y, band;  // band: half-width of one sample's 95 % noise band
  struct Region {
    double low, high, value;
    std::string label;
  };
  std::vector<Region> regions;
};

SvgPlot draw(const Panel& in) {
  SvgPlot p(800, 300);
  p.setTitle(in.title);
  p.setXLabel(in.xLabel);
  p.setYLabel(in.yLabel);
  std::map<int, std::vector<double>> bands;
  for (std::size_t i = 0; i < in.x.size(); ++i)
    bands[static_cast<int>(std::floor(in.x[i] / in.binWidth))].push_back(in.band[i]);
  std::vector<double> bx, lo, hi;
  for (const auto& [bin, b] : bands) {
    const double half = median(b);
    for (double edge : {bin * in.binWidth, (bin + 1) * in.binWidth}) {
      bx.push_back(edge);
      lo.push_back(-half);
      hi.push_back(half);
    }
  }
  if (!bx.empty()) p.addFill(bx, lo, hi, "95 % noise band of one sample", "#999999");
  int shaded = 0;
  for (const auto& r : in.regions) {
    p.addBand(r.low, r.high, "missing beyond its band", svgPaletteColor(5));
    p.addHLine(r.value, r.label, svgPaletteColor(5 + ++shaded));
  }
  p.addHLine(0, "", "#000000", false, true);
  const std::size_t stride = in.x.size() / kMaxPointsPerPanel + 1;
  std::vector<double> x, y;
  for (std::size_t i = 0; i < in.x.size(); i += stride) {
    x.push_back(in.x[i]);
    y.push_back(in.y[i]);
  }
  p.addPoints(x, y, stride > 1 ? fmt("one sample in %zu", stride) : std::string("each sample"), svgPaletteColor(1),
              1.6);
  return p;
}

Panel momentPanel(const MissingMoment& m, bool extending) {
  Panel p{extending ? "while the knee extends" : "while the knee flexes",
          "measured knee flexion (deg)",
          "missing knee moment (N m, + flexes)",
          kMomentBinDeg,
          {},
          {},
          {},
          {}};
  for (std::size_t i = 0; i < m.kneeDeg.size(); ++i) {
    if ((m.kneeRateDegS[i] < 0) != extending) continue;
    p.x.push_back(m.kneeDeg[i]);
    p.y.push_back(m.momentNm[i]);
    p.band.push_back(m.bandNm[i]);
  }
  for (const auto& r : m.regions)
    if (r.extending == extending)
      p.regions.push_back({r.kneeLowDeg, r.kneeHighDeg, r.moment,
                           fmt("%+.1f N m at %.0f-%.0f deg", r.moment, r.kneeLowDeg, r.kneeHighDeg)});
  return p;
}

Panel forcePanel(const MissingForce& m, bool extending) {
  Panel p{extending ? "while the piston extends" : "while the piston compresses",
          "measured piston position (mm)",
          "missing force (N, + resists compression)",
          kMissingForceBinMm,
          {},
          {},
          {},
          {}};
  for (std::size_t i = 0; i < m.positionMm.size(); ++i) {
    if ((m.speedMmS[i] < 0) != extending) continue;
    p.x.push_back(m.positionMm[i]);
    p.y.push_back(m.forceN[i]);
    p.band.push_back(1.96 * m.noiseN[i]);
  }
  for (const auto& r : m.regions)
    if (r.extending == extending)
      p.regions.push_back({r.positionLowMm, r.positionHighMm, r.force,
                           fmt("%+.3g N at %.0f-%.0f mm", r.force, r.positionLowMm, r.positionHighMm)});
  return p;
}

}  // namespace

std::string renderMissingMomentSvg(const MissingMoment& missing, const std::string& title) {
  std::vector<SvgPlot> panels{draw(momentPanel(missing, false)), draw(momentPanel(missing, true))};
  return renderStackedSvg(panels, title);
}

std::string renderMissingForceSvg(const MissingForce& missing, const std::string& title) {
  std::vector<SvgPlot> panels{draw(forcePanel(missing, false)), draw(forcePanel(missing, true))};
  return renderStackedSvg(panels, title);
}

}  // namespace swingsim
