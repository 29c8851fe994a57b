#include "report/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace swingsim {

namespace {

// Layout in pixels, chosen so 12-13 px text stays readable when the SVG is shown 800 px wide.
constexpr double kMarginLeft = 74;
constexpr double kMarginRight = 18;
constexpr double kMarginTop = 34;
constexpr double kMarginBottom = 50;
constexpr double kTickLength = 5;
constexpr double kFontTick = 12;
constexpr double kFontLabel = 13;
constexpr double kFontTitle = 15;
constexpr double kLegendRow = 17;
// Average glyph width of a 12 px sans-serif font, for sizing the legend box.
constexpr double kGlyphWidth = 6.8;
constexpr double kStackGap = 6;
constexpr double kFigureTitleHeight = 30;

std::string px(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

std::string tickLabel(double v, double step) {
  char buf[40];
  if (std::fabs(v) < 1e-12 * std::max(1.0, std::fabs(step))) v = 0;  // no "-0"
  const double mag = std::max(std::fabs(v), std::fabs(step));
  if (mag >= 1e6 || step < 1e-4) {
    std::snprintf(buf, sizeof buf, "%.3g", v);
  } else {
    int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  }
  return buf;
}

std::string opacity(double v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%.2f", std::clamp(v, 0.0, 1.0));
  return buf;
}

std::string dashAttr(bool dashed) { return dashed ? " stroke-dasharray=\"6 4\"" : ""; }

}  // namespace

std::string svgPaletteColor(int i) {
  static const char* kPalette[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                   "#E69F00", "#56B4E9", "#000000", "#F0E442"};
  const int n = static_cast<int>(sizeof kPalette / sizeof kPalette[0]);
  return kPalette[((i % n) + n) % n];
}

std::string svgEscape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::vector<double> calcNiceTicks(double lo, double hi, int target) {
  std::vector<double> ticks;
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo) || target < 1) return ticks;
  const double raw = (hi - lo) / target;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double norm = raw / mag;
  const double step = (norm < 1.5 ? 1 : norm < 3.5 ? 2 : norm < 7.5 ? 5 : 10) * mag;
  // A tick within a millionth of a step of the range end still counts as inside.
  const double slack = 1e-6 * step;
  for (double k = std::ceil((lo - slack) / step); k * step <= hi + slack; k += 1) {
    ticks.push_back(k * step);
  }
  return ticks;
}

SvgPlot::SvgPlot(double width, double height) : width_(width), height_(height), marginLeft_(kMarginLeft) {
  if (!(width > kMarginLeft + kMarginRight + 10) || !(height > kMarginTop + kMarginBottom + 10)) {
    throw std::invalid_argument("SvgPlot: panel of " + px(width) + " x " + px(height) +
                                " px is too small for axes and labels");
  }
}

void SvgPlot::setXRange(double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo))
    throw std::invalid_argument("SvgPlot::setXRange: need finite lo < hi");
  fixedX_ = true;
  xLo_ = lo;
  xHi_ = hi;
}

void SvgPlot::setYRange(double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo))
    throw std::invalid_argument("SvgPlot::setYRange: need finite lo < hi");
  fixedY_ = true;
  yLo_ = lo;
  yHi_ = hi;
}

void SvgPlot::addLine(const std::vector<double>& xs, const std::vector<double>& ys, const std::string& label,
                      const std::string& color, double strokeWidth, bool dashed) {
  if (xs.size() != ys.size()) throw std::invalid_argument("SvgPlot::addLine: xs and ys differ in length");
  series_.push_back({xs, ys, label, color, strokeWidth, dashed, false});
}

void SvgPlot::addPoints(const std::vector<double>& xs, const std::vector<double>& ys, const std::string& label,
                        const std::string& color, double radius) {
  if (xs.size() != ys.size()) throw std::invalid_argument("SvgPlot::addPoints: xs and ys differ in length");
  series_.push_back({xs, ys, label, color, radius, false, true});
}

void SvgPlot::addBand(double x0, double x1, const std::string& label, const std::string& color, double opacity) {
  if (!std::isfinite(x0) || !std::isfinite(x1)) return;
  bands_.push_back({std::min(x0, x1), std::max(x0, x1), label, color, opacity});
}

void SvgPlot::addHBand(double y0, double y1, const std::string& label, const std::string& color, double opacity) {
  if (!std::isfinite(y0) || !std::isfinite(y1)) return;
  bands_.push_back({std::min(y0, y1), std::max(y0, y1), label, color, opacity, true});
}

void SvgPlot::addFill(const std::vector<double>& xs, const std::vector<double>& lows, const std::vector<double>& highs,
                      const std::string& label, const std::string& color, double opacity) {
  if (xs.size() != lows.size() || xs.size() != highs.size())
    throw std::invalid_argument("SvgPlot::addFill: xs, lows and highs differ in length");
  fills_.push_back({xs, lows, highs, label, color, opacity});
}

void SvgPlot::setYTickLabels(const std::vector<std::pair<double, std::string>>& labels, double leftMargin) {
  if (!(leftMargin >= kMarginLeft) || !(width_ > leftMargin + kMarginRight + 10))
    throw std::invalid_argument("SvgPlot::setYTickLabels: a left margin of " + px(leftMargin) +
                                " px does not fit a panel " + px(width_) + " px wide");
  yTickLabels_ = labels;
  marginLeft_ = leftMargin;
}

void SvgPlot::addHLine(double y, const std::string& label, const std::string& color, bool dashed, bool includeInRange) {
  if (!std::isfinite(y)) return;
  refs_.push_back({y, label, color, dashed, true, includeInRange});
}

void SvgPlot::addVLine(double x, const std::string& label, const std::string& color, bool dashed) {
  if (!std::isfinite(x)) return;
  refs_.push_back({x, label, color, dashed, false, false});
}

void SvgPlot::calcRanges(double& x0, double& x1, double& y0, double& y1) const {
  const double inf = std::numeric_limits<double>::infinity();
  double xmin = inf, xmax = -inf, ymin = inf, ymax = -inf;
  for (const auto& s : series_) {
    for (std::size_t i = 0; i < s.xs.size(); ++i) {
      if (!std::isfinite(s.xs[i]) || !std::isfinite(s.ys[i])) continue;
      xmin = std::min(xmin, s.xs[i]);
      xmax = std::max(xmax, s.xs[i]);
      ymin = std::min(ymin, s.ys[i]);
      ymax = std::max(ymax, s.ys[i]);
    }
  }
  for (const auto& f : fills_) {
    for (std::size_t i = 0; i < f.xs.size(); ++i) {
      if (!std::isfinite(f.xs[i]) || !std::isfinite(f.lows[i]) || !std::isfinite(f.highs[i])) continue;
      xmin = std::min(xmin, f.xs[i]);
      xmax = std::max(xmax, f.xs[i]);
      ymin = std::min({ymin, f.lows[i], f.highs[i]});
      ymax = std::max({ymax, f.lows[i], f.highs[i]});
    }
  }
  for (const auto& r : refs_) {
    if (r.horizontal && r.inRange) {
      ymin = std::min(ymin, r.value);
      ymax = std::max(ymax, r.value);
    }
  }
  if (!(xmax >= xmin)) {
    for (const auto& b : bands_) {
      if (b.horizontal) continue;
      xmin = std::min(xmin, b.x0);
      xmax = std::max(xmax, b.x1);
    }
  }
  auto widen = [](double& lo, double& hi, double pad) {
    if (!(hi >= lo)) {
      lo = 0;
      hi = 1;
    } else if (hi == lo) {
      const double d = lo == 0 ? 1 : 0.1 * std::fabs(lo);
      lo -= d;
      hi += d;
    } else {
      const double d = pad * (hi - lo);
      lo -= d;
      hi += d;
    }
  };
  if (fixedX_) {
    x0 = xLo_;
    x1 = xHi_;
  } else {
    x0 = xmin;
    x1 = xmax;
    widen(x0, x1, 0.0);
  }
  if (fixedY_) {
    y0 = yLo_;
    y1 = yHi_;
  } else {
    y0 = ymin;
    y1 = ymax;
    // 6 % head room so lines do not touch the frame.
    widen(y0, y1, 0.06);
  }
}

std::string SvgPlot::renderBands(const Frame& f, const std::string& clipId) const {
  const double left = f.left, top = f.top, plotW = f.plotW, plotH = f.plotH;
  auto mapX = [&](double x) { return f.mapX(x); };
  auto mapY = [&](double y) { return f.mapY(y); };
  std::string s;
  // Bands first, beneath everything.
  s += "<g clip-path=\"url(#" + clipId + ")\">\n";
  for (const auto& b : bands_) {
    if (b.horizontal) {
      const double a = std::max(mapY(b.x1), top - 1), c = std::min(mapY(b.x0), top + plotH + 1);
      if (c <= a) continue;
      s += "<rect x=\"" + px(left) + "\" y=\"" + px(a) + "\" width=\"" + px(plotW) + "\" height=\"" + px(c - a) +
           "\" fill=\"" + svgEscape(b.color) + "\" fill-opacity=\"" + opacity(b.opacity) + "\"/>\n";
      continue;
    }
    const double a = std::max(mapX(b.x0), left - 1), c = std::min(mapX(b.x1), left + plotW + 1);
    if (c <= a) continue;
    s += "<rect x=\"" + px(a) + "\" y=\"" + px(top) + "\" width=\"" + px(c - a) + "\" height=\"" + px(plotH) +
         "\" fill=\"" + svgEscape(b.color) + "\" fill-opacity=\"" + opacity(b.opacity) + "\"/>\n";
  }
  // Filled bands between two curves, one polygon per finite run of points.
  for (const auto& fl : fills_) {
    std::size_t i = 0;
    while (i < fl.xs.size()) {
      auto finite = [&](std::size_t k) {
        return std::isfinite(fl.xs[k]) && std::isfinite(fl.lows[k]) && std::isfinite(fl.highs[k]);
      };
      if (!finite(i)) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < fl.xs.size() && finite(j)) ++j;
      std::string d;
      for (std::size_t k = i; k < j; ++k) d += (k == i ? "M" : "L") + px(mapX(fl.xs[k])) + " " + px(mapY(fl.highs[k]));
      for (std::size_t k = j; k-- > i;) d += "L" + px(mapX(fl.xs[k])) + " " + px(mapY(fl.lows[k]));
      s += "<path d=\"" + d + "Z\" fill=\"" + svgEscape(fl.color) + "\" fill-opacity=\"" + opacity(fl.opacity) +
           "\" stroke=\"none\"/>\n";
      i = j;
    }
  }
  s += "</g>\n";
  return s;
}

std::string SvgPlot::renderGrid(const Frame& f) const {
  const double left = f.left, top = f.top, plotW = f.plotW, plotH = f.plotH;
  auto mapX = [&](double x) { return f.mapX(x); };
  auto mapY = [&](double y) { return f.mapY(y); };
  std::string s;
  // Grid and ticks.
  const auto xt = calcNiceTicks(f.x0, f.x1, std::max(3, static_cast<int>(plotW / 110)));
  const auto yt = calcNiceTicks(f.y0, f.y1, std::max(3, static_cast<int>(plotH / 55)));
  const double xstep = xt.size() > 1 ? xt[1] - xt[0] : (f.x1 - f.x0);
  const double ystep = yt.size() > 1 ? yt[1] - yt[0] : (f.y1 - f.y0);
  for (double v : xt) {
    const double X = mapX(v);
    s += "<line x1=\"" + px(X) + "\" y1=\"" + px(top) + "\" x2=\"" + px(X) + "\" y2=\"" + px(top + plotH) +
         "\" stroke=\"#e3e3e3\" stroke-width=\"1\"/>\n";
    s += "<line x1=\"" + px(X) + "\" y1=\"" + px(top + plotH) + "\" x2=\"" + px(X) + "\" y2=\"" +
         px(top + plotH + kTickLength) + "\" stroke=\"#333\" stroke-width=\"1\"/>\n";
    s += "<text x=\"" + px(X) + "\" y=\"" + px(top + plotH + kTickLength + kFontTick + 2) + "\" font-size=\"" +
         px(kFontTick) + "\" text-anchor=\"middle\" fill=\"#333\">" + tickLabel(v, xstep) + "</text>\n";
  }
  std::vector<std::pair<double, std::string>> yLabels = yTickLabels_;
  if (yLabels.empty())
    for (double v : yt) yLabels.emplace_back(v, tickLabel(v, ystep));
  for (const auto& [v, text] : yLabels) {
    const double Y = mapY(v);
    s += "<line x1=\"" + px(left) + "\" y1=\"" + px(Y) + "\" x2=\"" + px(left + plotW) + "\" y2=\"" + px(Y) +
         "\" stroke=\"#e3e3e3\" stroke-width=\"1\"/>\n";
    s += "<line x1=\"" + px(left - kTickLength) + "\" y1=\"" + px(Y) + "\" x2=\"" + px(left) + "\" y2=\"" + px(Y) +
         "\" stroke=\"#333\" stroke-width=\"1\"/>\n";
    s += "<text x=\"" + px(left - kTickLength - 3) + "\" y=\"" + px(Y + kFontTick * 0.35) + "\" font-size=\"" +
         px(kFontTick) + "\" text-anchor=\"end\" fill=\"#333\">" + svgEscape(text) + "</text>\n";
  }
  return s;
}

std::string SvgPlot::renderData(const Frame& f, const std::string& clipId) const {
  const double left = f.left, top = f.top, plotW = f.plotW, plotH = f.plotH;
  auto mapX = [&](double x) { return f.mapX(x); };
  auto mapY = [&](double y) { return f.mapY(y); };
  std::string s;
  // Data, clipped to the plot area.
  s += "<g clip-path=\"url(#" + clipId + ")\">\n";
  for (const auto& r : refs_) {
    if (r.horizontal) {
      const double Y = mapY(r.value);
      s += "<line x1=\"" + px(left) + "\" y1=\"" + px(Y) + "\" x2=\"" + px(left + plotW) + "\" y2=\"" + px(Y) +
           "\" stroke=\"" + svgEscape(r.color) + "\" stroke-width=\"1.2\"" + dashAttr(r.dashed) + "/>\n";
    } else {
      const double X = mapX(r.value);
      s += "<line x1=\"" + px(X) + "\" y1=\"" + px(top) + "\" x2=\"" + px(X) + "\" y2=\"" + px(top + plotH) +
           "\" stroke=\"" + svgEscape(r.color) + "\" stroke-width=\"1.2\"" + dashAttr(r.dashed) + "/>\n";
    }
  }
  for (const auto& ser : series_) {
    if (ser.points) {
      s += "<g fill=\"" + svgEscape(ser.color) + "\">";
      for (std::size_t i = 0; i < ser.xs.size(); ++i) {
        if (!std::isfinite(ser.xs[i]) || !std::isfinite(ser.ys[i])) continue;
        s += "<circle cx=\"" + px(mapX(ser.xs[i])) + "\" cy=\"" + px(mapY(ser.ys[i])) + "\" r=\"" + px(ser.size) +
             "\"/>";
      }
      s += "</g>\n";
      continue;
    }
    std::string d;
    bool pen = false;
    for (std::size_t i = 0; i < ser.xs.size(); ++i) {
      if (!std::isfinite(ser.xs[i]) || !std::isfinite(ser.ys[i])) {
        pen = false;
        continue;
      }
      d += (pen ? "L" : "M") + px(mapX(ser.xs[i])) + " " + px(mapY(ser.ys[i]));
      pen = true;
    }
    if (d.empty()) continue;
    s += "<path d=\"" + d + "\" fill=\"none\" stroke=\"" + svgEscape(ser.color) + "\" stroke-width=\"" + px(ser.size) +
         "\" stroke-linejoin=\"round\"" + dashAttr(ser.dashed) + "/>\n";
  }
  s += "</g>\n";
  return s;
}

std::string SvgPlot::renderLabels(const Frame& f) const {
  const double left = f.left, top = f.top, plotW = f.plotW, plotH = f.plotH;
  std::string s;
  // Frame, labels, title.
  s += "<rect x=\"" + px(left) + "\" y=\"" + px(top) + "\" width=\"" + px(plotW) + "\" height=\"" + px(plotH) +
       "\" fill=\"none\" stroke=\"#333\" stroke-width=\"1\"/>\n";
  if (!xLabel_.empty()) {
    s += "<text x=\"" + px(left + plotW / 2) + "\" y=\"" + px(height_ - 10) + "\" font-size=\"" + px(kFontLabel) +
         "\" text-anchor=\"middle\" fill=\"#111\">" + svgEscape(xLabel_) + "</text>\n";
  }
  if (!yLabel_.empty()) {
    const double X = 16, Y = top + plotH / 2;
    s += "<text x=\"" + px(X) + "\" y=\"" + px(Y) + "\" font-size=\"" + px(kFontLabel) +
         "\" text-anchor=\"middle\" fill=\"#111\" transform=\"rotate(-90 " + px(X) + " " + px(Y) + ")\">" +
         svgEscape(yLabel_) + "</text>\n";
  }
  if (!title_.empty()) {
    s += "<text x=\"" + px(left + plotW / 2) + "\" y=\"" + px(top - 12) + "\" font-size=\"" + px(kFontTitle) +
         "\" font-weight=\"bold\" text-anchor=\"middle\" fill=\"#111\">" + svgEscape(title_) + "</text>\n";
  }
  return s;
}

// The corner (index into `corners`) where a legend box of boxW x boxH px covers the least
// data: series vertices and points along line segments every few pixels (the first corner
// wins ties).
int SvgPlot::calcLegendCorner(const Frame& f, const double corners[4][2], double boxW, double boxH) const {
  constexpr double kSampleSpacing = 4;  // px
  auto mapX = [&](double x) { return f.mapX(x); };
  auto mapY = [&](double y) { return f.mapY(y); };
  int covered[4] = {0, 0, 0, 0};
  auto mark = [&](double X, double Y) {
    for (int c = 0; c < 4; ++c)
      if (X >= corners[c][0] && X <= corners[c][0] + boxW && Y >= corners[c][1] && Y <= corners[c][1] + boxH)
        ++covered[c];
  };
  for (const auto& ser : series_) {
    for (std::size_t i = 0; i < ser.xs.size(); ++i) {
      if (!std::isfinite(ser.xs[i]) || !std::isfinite(ser.ys[i])) continue;
      const double X = mapX(ser.xs[i]), Y = mapY(ser.ys[i]);
      mark(X, Y);
      if (ser.points || i + 1 >= ser.xs.size() || !std::isfinite(ser.xs[i + 1]) || !std::isfinite(ser.ys[i + 1]))
        continue;
      const double X1 = mapX(ser.xs[i + 1]), Y1 = mapY(ser.ys[i + 1]);
      const int n = static_cast<int>(std::min(1000.0, std::hypot(X1 - X, Y1 - Y) / kSampleSpacing));
      for (int k = 1; k < n; ++k) mark(X + (X1 - X) * k / n, Y + (Y1 - Y) * k / n);
    }
  }
  int best = 0;
  for (int c = 1; c < 4; ++c)
    if (covered[c] < covered[best]) best = c;
  return best;
}

std::string SvgPlot::renderLegend(const Frame& f) const {
  const double left = f.left, top = f.top, plotW = f.plotW, plotH = f.plotH;
  std::string s;
  // Legend: labelled series, then unique band labels, then labelled reference lines.
  struct Entry {
    std::string label, color;
    int kind;  // 0 line, 1 points, 2 band, 3 dashed line
  };
  std::vector<Entry> entries;
  for (const auto& ser : series_) {
    if (!ser.label.empty()) entries.push_back({ser.label, ser.color, ser.points ? 1 : (ser.dashed ? 3 : 0)});
  }
  for (const auto& fl : fills_) {
    if (!fl.label.empty()) entries.push_back({fl.label, fl.color, 2});
  }
  for (const auto& b : bands_) {
    if (b.label.empty()) continue;
    bool seen = false;
    for (const auto& e : entries) seen = seen || (e.kind == 2 && e.label == b.label);
    if (!seen) entries.push_back({b.label, b.color, 2});
  }
  for (const auto& r : refs_) {
    if (!r.label.empty()) entries.push_back({r.label, r.color, r.dashed ? 3 : 0});
  }
  if (legend_ && !entries.empty()) {
    std::size_t longest = 0;
    for (const auto& e : entries) longest = std::max(longest, e.label.size());
    const double boxW = 34 + kGlyphWidth * static_cast<double>(longest);
    const double boxH = 8 + kLegendRow * static_cast<double>(entries.size());
    // The corner where the box covers the least data: series vertices and points along
    // line segments every few pixels (top right wins ties, then top left, bottom right,
    // bottom left).
    constexpr double kInset = 6;  // px
    const double corners[4][2] = {{left + plotW - boxW - kInset, top + kInset},
                                  {left + kInset, top + kInset},
                                  {left + plotW - boxW - kInset, top + plotH - boxH - kInset},
                                  {left + kInset, top + plotH - boxH - kInset}};
    const int best = calcLegendCorner(f, corners, boxW, boxH);
    const double bx = corners[best][0], by = corners[best][1];
    s += "<g font-size=\"" + px(kFontTick) + "\">\n";
    s += "<rect x=\"" + px(bx) + "\" y=\"" + px(by) + "\" width=\"" + px(boxW) + "\" height=\"" + px(boxH) +
         "\" fill=\"#ffffff\" fill-opacity=\"0.85\" stroke=\"#999\" stroke-width=\"0.8\"/>\n";
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const auto& e = entries[i];
      const double ry = by + 4 + kLegendRow * (static_cast<double>(i) + 0.5);
      const std::string c = svgEscape(e.color);
      if (e.kind == 2) {
        s += "<rect x=\"" + px(bx + 6) + "\" y=\"" + px(ry - 6) + "\" width=\"20\" height=\"12\" fill=\"" + c +
             "\" fill-opacity=\"0.35\"/>";
      } else if (e.kind == 1) {
        s += "<circle cx=\"" + px(bx + 16) + "\" cy=\"" + px(ry) + "\" r=\"3\" fill=\"" + c + "\"/>";
      } else {
        s += "<line x1=\"" + px(bx + 6) + "\" y1=\"" + px(ry) + "\" x2=\"" + px(bx + 26) + "\" y2=\"" + px(ry) +
             "\" stroke=\"" + c + "\" stroke-width=\"2\"" + dashAttr(e.kind == 3) + "/>";
      }
      s += "<text x=\"" + px(bx + 30) + "\" y=\"" + px(ry + 4) + "\" fill=\"#111\">" + svgEscape(e.label) + "</text>\n";
    }
    s += "</g>\n";
  }
  return s;
}

std::string SvgPlot::renderGroup(double dx, double dy) const {
  Frame f{};
  calcRanges(f.x0, f.x1, f.y0, f.y1);
  f.left = marginLeft_;
  f.top = kMarginTop;
  f.plotW = width_ - marginLeft_ - kMarginRight;
  f.plotH = height_ - kMarginTop - kMarginBottom;
  const std::string clipId =
      "clip" + std::to_string(static_cast<long>(dx)) + "_" + std::to_string(static_cast<long>(dy));

  std::string s;
  s += "<g transform=\"translate(" + px(dx) + "," + px(dy) + ")\" font-family=\"sans-serif\">\n";
  s += "<defs><clipPath id=\"" + clipId + "\"><rect x=\"" + px(f.left) + "\" y=\"" + px(f.top) + "\" width=\"" +
       px(f.plotW) + "\" height=\"" + px(f.plotH) + "\"/></clipPath></defs>\n";
  s += "<rect x=\"" + px(f.left) + "\" y=\"" + px(f.top) + "\" width=\"" + px(f.plotW) + "\" height=\"" + px(f.plotH) +
       "\" fill=\"#ffffff\" stroke=\"none\"/>\n";
  s += renderBands(f, clipId) + renderGrid(f) + renderData(f, clipId) + renderLabels(f) + renderLegend(f);
  s += "</g>\n";
  return s;
}

namespace {

std::string svgHeader(double w, double h) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + px(w) + "\" height=\"" + px(h) + "\" viewBox=\"0 0 " +
         px(w) + " " + px(h) + "\">\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
}

}  // namespace

std::string SvgPlot::render() const { return svgHeader(width_, height_) + renderGroup(0, 0) + "</svg>\n"; }

std::string renderStackedSvg(const std::vector<SvgPlot>& panels, const std::string& title) {
  double w = 0, h = title.empty() ? 0 : kFigureTitleHeight;
  for (const auto& p : panels) {
    w = std::max(w, p.width());
    h += p.height() + kStackGap;
  }
  if (panels.empty()) w = 400;
  std::string s = svgHeader(w, h);
  double y = 0;
  if (!title.empty()) {
    s += "<text x=\"" + px(w / 2) + "\" y=\"" + px(kFigureTitleHeight - 8) +
         "\" font-family=\"sans-serif\" font-size=\"" + px(kFontTitle + 1) +
         "\" font-weight=\"bold\" text-anchor=\"middle\" fill=\"#111\">" + svgEscape(title) + "</text>\n";
    y = kFigureTitleHeight;
  }
  for (const auto& p : panels) {
    s += p.renderGroup(0, y);
    y += p.height() + kStackGap;
  }
  return s + "</svg>\n";
}

}  // namespace swingsim
