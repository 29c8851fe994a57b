// The SVG figures of the sweep report, one per participant each: swing time against the
// lowering (Burkett 2004 Fig. 4), the tornado of one-at-a-time sensitivities, knee flexion
// against time (Fig. 3) and the stick-figure filmstrip.
#include "report/sweep_figures.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/text_format.h"
#include "report/sweep_report_parts.h"
#include "sweep/burkett_published.h"

namespace swingsim {

using namespace sweep_report_parts;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

// With a sound-limb swing time: that time as a horizontal line, our symmetry lowering, and
// Table 4's measured anatomical times (Burkett's `*` compares with those); nothing without one.
void addSymmetryMarks(const ParticipantSweep& ps, SvgPlot& plot) {
  const SymmetryLowering& sym = ps.symmetry;
  if (!sym.given) return;
  plot.addHLine(sym.soundTime, "sound limb (participant file)", svgPaletteColor(3), true, true);
  if (const PublishedParticipant* pub = ps.published) {
    std::vector<double> px, pa;
    for (const auto& row : pub->table4) {
      px.push_back(row.lowering);
      pa.push_back(row.measuredAnatomical);
    }
    plot.addPoints(px, pa, "measured anatomical (Table 4)", svgPaletteColor(3), 4);
  }
  if (sym.found)
    plot.addPoints({sym.lowering}, {sym.prostheticTime},
                   sym.reached ? "our best symmetry" : "our best symmetry (not reached)", svgPaletteColor(4), 6);
}

}  // namespace

SvgPlot makeSwingTimeFigure(const ParticipantSweep& ps, const ParticipantUncertainty* pu) {
  SvgPlot plot(800, 380);
  plot.setTitle(ps.name + ": swing time vs knee-axis lowering (cf. Burkett 2004 Fig. 4)");
  plot.setXLabel("knee-axis lowering below standard (m)");
  plot.setYLabel("swing time (s)");
  // The grid and both sides of each jump, the line broken at every jump (never drawn across one).
  std::vector<std::pair<double, double>> samples;
  for (const auto& pt : ps.points) samples.emplace_back(pt.lowering, pt.ok ? pt.result.swingTime : kNaN);
  for (const SwingTimeJump& j : ps.jumps) {
    samples.emplace_back(j.below.lowering, j.below.swingTime);
    samples.emplace_back(j.calcLowering(), kNaN);
    samples.emplace_back(j.above.lowering, j.above.swingTime);
  }
  std::stable_sort(samples.begin(), samples.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<double> x, y;
  for (const auto& [lowering, time] : samples) {
    x.push_back(lowering);
    y.push_back(time);
  }
  if (pu)
    plot.addFill(pu->bandLowerings, pu->bandP05, pu->bandP95, "5-95 % over the assumptions (docs/uncertainty.md)",
                 svgPaletteColor(0));
  plot.addLine(x, y, "this model", svgPaletteColor(0), 2.0);
  for (std::size_t k = 0; k < ps.jumps.size(); ++k)
    plot.addVLine(ps.jumps[k].calcLowering(), k == 0 ? "swing-time jump (a rebound past the zone)" : "", "#888888");
  double xMax = x.empty() ? 0.2 : x.back();
  if (const PublishedParticipant* pub = ps.published)
    for (const auto& row : pub->table4) xMax = std::max(xMax, row.lowering);
  plot.setXRange(-0.005, xMax + 0.01);
  if (const PublishedParticipant* pub = ps.published) {
    std::vector<double> px, pm, pp;
    for (const auto& row : pub->table4) {
      px.push_back(row.lowering);
      pm.push_back(row.model);
      pp.push_back(row.measuredProsthetic);
    }
    plot.addPoints(px, pm, "Burkett model (Table 4)", svgPaletteColor(1), 4);
    plot.addPoints(px, pp, "measured prosthetic (Table 4)", svgPaletteColor(2), 4);
    plot.addVLine(pub->predictedBestLowering, "Burkett's fastest", svgPaletteColor(1));
  }
  if (ps.best >= 0) {
    const auto& b = ps.points[static_cast<std::size_t>(ps.best)];
    plot.addPoints({b.lowering}, {b.result.swingTime}, "our fastest", "#000000", 6);
  }
  addSymmetryMarks(ps, plot);
  return plot;
}

// Horizontal bars of the change in the fastest lowering when one assumption goes to the low
// or the high end of its range, largest effect on top; a dot at the end of each bar (so a
// zero change still shows) and "no swing end" in the label where a run found none.
SvgPlot makeTornadoFigure(const ParticipantUncertainty& pu) {
  const std::size_t n = pu.sensitivity.size();
  SvgPlot plot(800, 120 + 34 * static_cast<double>(n));
  plot.setTitle(pu.name + ": change in the fastest lowering, one assumption at a time");
  plot.setXLabel("fastest lowering minus nominal (m); each assumption at the low / high end of its range");
  const double nominal = pu.nominal.calcFastestLowering();
  std::vector<std::pair<double, std::string>> labels;
  double reach = 0.01;              // m: at least +-10 mm, one grid step either side
  constexpr double kOffset = 0.17;  // rows: low bar above, high bar below the row's centre
  constexpr double kBarPx = 10;
  bool labelled = false;
  for (std::size_t i = 0; i < n; ++i) {
    const SensitivityRow& r = pu.sensitivity[i];
    const double y = static_cast<double>(n - i);
    std::string label = r.name + " [" + formatAssumptionValue(r.assumption, r.lowValue) + " .. " +
                        formatAssumptionValue(r.assumption, r.highValue) + unitSuffix(r.unit) + "]";
    const double dLow = r.low.calcFastestLowering() - nominal, dHigh = r.high.calcFastestLowering() - nominal;
    if (!std::isfinite(dLow) || !std::isfinite(dHigh)) label += " (no swing end)";
    labels.emplace_back(y, label);
    const struct {
      double d, dy;
      int colour;
      const char* name;
    } ends[] = {{dLow, kOffset, 0, "low end"}, {dHigh, -kOffset, 1, "high end"}};
    for (const auto& e : ends) {
      if (!std::isfinite(e.d)) continue;
      reach = std::max(reach, std::fabs(e.d));
      plot.addLine({0.0, e.d}, {y + e.dy, y + e.dy}, labelled ? "" : e.name, svgPaletteColor(e.colour), kBarPx);
      plot.addPoints({e.d}, {y + e.dy}, "", svgPaletteColor(e.colour), 4);
    }
    labelled = labelled || (std::isfinite(dLow) && std::isfinite(dHigh));
  }
  plot.addVLine(0.0, "", "#333333", false);
  plot.setXRange(-1.15 * reach, 1.15 * reach);
  plot.setYRange(0.4, static_cast<double>(n) + 0.6);
  plot.setYTickLabels(labels, 330);
  return plot;
}

SvgPlot makeKneeFlexionFigure(const ParticipantSweep& ps, double zoneDeg) {
  SvgPlot plot(800, 380);
  plot.setTitle(ps.name + ": knee flexion during swing (cf. Burkett 2004 Fig. 3)");
  plot.setXLabel("time since toe-off (s)");
  plot.setYLabel("knee flexion (deg)");
  int colour = 0;
  for (const auto& pt : ps.points) {
    const int mm = static_cast<int>(std::lround(pt.lowering * 1000));
    if (mm % 50 != 0 || !pt.ok) continue;
    std::vector<double> deg;
    for (double q : pt.result.trajectory.kneeFlexion) deg.push_back(q * kRadToDeg);
    plot.addLine(pt.result.trajectory.time, deg, mm == 0 ? "standard" : "std +" + std::to_string(mm) + " mm",
                 svgPaletteColor(colour++), 1.8);
  }
  plot.addHBand(-100, zoneDeg, "zone of stability (< " + fmt("%.0f", zoneDeg) + " deg)", "#009E73");
  return plot;
}

SvgPlot makeFilmstrip(const std::string& title, const SwingResult& r, double hipHeight) {
  // Frames every 40 ms up to the swing end, shifted right so they do not overlap.
  const auto& tr = r.trajectory;
  const double frameStep = 0.04, shift = 0.45;
  std::vector<std::vector<double>> frameX, frameY;
  for (double t = 0; t <= r.swingTime + 1e-9 && frameX.size() < 14; t += frameStep) {
    std::size_t k = 0;
    while (k + 1 < tr.size() && tr.time[k] < t - 1e-9) ++k;
    const double dx = static_cast<double>(frameX.size()) * shift;
    frameX.push_back({dx, tr.kneeX[k] + dx, tr.ankleX[k] + dx, tr.toeX[k] + dx});
    frameY.push_back({hipHeight, tr.kneeY[k], tr.ankleY[k], tr.toeY[k]});
  }
  const double xLo = -0.6, xHi = static_cast<double>(frameX.size()) * shift + 0.3;
  const double yLo = -0.1, yHi = hipHeight + 0.1;
  // Equal scale on both axes so the leg is not distorted: about 700 px of plot width and
  // about 90 px of title and axis margins.
  SvgPlot plot(800, 90 + 700 * (yHi - yLo) / (xHi - xLo));
  plot.setTitle(title);
  plot.setXLabel("hip-thigh-shank-foot every 0.04 s from toe-off, frames shifted 0.45 m apart (m)");
  plot.setYLabel("height (m)");
  for (std::size_t f = 0; f < frameX.size(); ++f) {
    plot.addLine(frameX[f], frameY[f], "", svgPaletteColor(f % 2 ? 4 : 0), 2.2);
  }
  plot.addHLine(0.0, "", "#555555", false, true);
  plot.setXRange(xLo, xHi);
  plot.setYRange(yLo, yHi);
  plot.setLegend(false);
  return plot;
}

}  // namespace swingsim
