#include "report/missing_moment_plot.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "core/text_format.h"
#include "report/svg_plot.h"

namespace swingsim {

namespace {

constexpr double kBinDeg = 5.0;  // as the regions' bins (identify/missing_moment.cpp)

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

SvgPlot panelOf(const MissingMoment& m, bool extending) {
  SvgPlot p(800, 300);
  p.setTitle(extending ? "while the knee extends" : "while the knee flexes");
  p.setXLabel("measured knee flexion (deg)");
  p.setYLabel("missing knee moment (N m, + flexes)");
  std::vector<double> x, y;
  std::map<int, std::vector<double>> bands;
  for (std::size_t i = 0; i < m.kneeDeg.size(); ++i) {
    if ((m.kneeRateDegS[i] < 0) != extending) continue;
    x.push_back(m.kneeDeg[i]);
    y.push_back(m.momentNm[i]);
    bands[static_cast<int>(std::floor(m.kneeDeg[i] / kBinDeg))].push_back(m.bandNm[i]);
  }
  std::vector<double> bx, lo, hi;
  for (const auto& [bin, b] : bands) {
    const double half = median(b);
    for (double edge : {bin * kBinDeg, (bin + 1) * kBinDeg}) {
      bx.push_back(edge);
      lo.push_back(-half);
      hi.push_back(half);
    }
  }
  if (!bx.empty()) p.addFill(bx, lo, hi, "95 % noise band of one sample", "#999999");
  int shaded = 0;
  for (const auto& r : m.regions) {
    if (r.extending != extending) continue;
    p.addBand(r.kneeLowDeg, r.kneeHighDeg, "missing moment beyond its band", svgPaletteColor(5));
    p.addHLine(r.moment, fmt("%+.1f N m at %.0f-%.0f deg", r.moment, r.kneeLowDeg, r.kneeHighDeg), svgPaletteColor(5 + ++shaded));
  }
  p.addHLine(0, "", "#000000", false, true);
  p.addPoints(x, y, "each sample", svgPaletteColor(1), 1.6);
  return p;
}

}  // namespace

std::string renderMissingMomentSvg(const MissingMoment& missing, const std::string& title) {
  std::vector<SvgPlot> panels{panelOf(missing, false), panelOf(missing, true)};
  return renderStackedSvg(panels, title);
}

}  // namespace swingsim
