#pragma once
// Small, dependency-free SVG line plots for reports: axes with "nice" ticks, axis labels
// with units, lines (with gaps at non-finite values), points, shaded vertical bands,
// horizontal and vertical reference lines, and a legend. Several panels can be stacked
// vertically in one SVG (force over time above the switch traces, Chien 2014 Figs. 5-6).
// Sized to stay legible at 800 px wide.
#include <string>
#include <utility>
#include <vector>

namespace swingsim {

/// A colour from a fixed, colour-blind-friendly palette (Okabe-Ito), cycling with i.
std::string svgPaletteColor(int i);

/// One plot panel. Coordinates are in data units; the panel maps them to pixels.
/// Usage:
///   SvgPlot plot(800, 360);
///   plot.setTitle("Normal speed"); plot.setXLabel("time (s)"); plot.setYLabel("force (N)");
///   plot.addBand(0.1, 0.3, "phase 1", "#E69F00");
///   plot.addLine(t, f, "measured", "#000000");
///   std::string svg = plot.render();
class SvgPlot {
 public:
  /// Panel size in pixels (both must be positive; throws std::invalid_argument).
  SvgPlot(double width = 800, double height = 360);

  void setTitle(const std::string& title) { title_ = title; }
  /// Axis labels; put the unit in the label: "time (s)", "force (N)".
  void setXLabel(const std::string& label) { xLabel_ = label; }
  void setYLabel(const std::string& label) { yLabel_ = label; }
  /// Fix an axis range instead of fitting it to the data (lo < hi, finite).
  void setXRange(double lo, double hi);
  void setYRange(double lo, double hi);
  /// Show the legend (default true when anything has a label). It goes in the corner of
  /// the plot area where it covers the least data.
  void setLegend(bool show) { legend_ = show; }

  /// A polyline; a non-finite x or y breaks the line. Empty label = not in the legend.
  void addLine(const std::vector<double>& xs, const std::vector<double>& ys, const std::string& label,
               const std::string& color, double strokeWidth = 1.5, bool dashed = false);
  /// Markers (circles of `radius` px); non-finite points are skipped.
  void addPoints(const std::vector<double>& xs, const std::vector<double>& ys, const std::string& label,
                 const std::string& color, double radius = 2.5);
  /// A shaded vertical band x0..x1 over the full height. Bands with the same label
  /// appear once in the legend. Drawn beneath lines and points.
  void addBand(double x0, double x1, const std::string& label, const std::string& color, double opacity = 0.18);
  /// A shaded horizontal band y0..y1 across the full width (e.g. a zone of stability).
  /// Not used for auto-ranging; drawn beneath lines and points.
  void addHBand(double y0, double y1, const std::string& label, const std::string& color, double opacity = 0.15);
  /// A shaded area between two curves over the same xs (an uncertainty band); a
  /// non-finite value breaks it. Used for auto-ranging; drawn beneath lines and points.
  void addFill(const std::vector<double>& xs, const std::vector<double>& lows, const std::vector<double>& highs,
               const std::string& label, const std::string& color, double opacity = 0.22);
  /// Text labels at given y values instead of numeric y ticks (the rows of a tornado
  /// figure); `leftMargin` px leaves room for them (at least the default 74).
  void setYTickLabels(const std::vector<std::pair<double, std::string>>& labels, double leftMargin);

  /// A horizontal reference line across the panel (not used for auto-ranging y unless
  /// `includeInRange`).
  void addHLine(double y, const std::string& label, const std::string& color, bool dashed = true,
                bool includeInRange = false);
  /// A vertical reference line.
  void addVLine(double x, const std::string& label, const std::string& color, bool dashed = true);

  double width() const { return width_; }
  double height() const { return height_; }

  /// A complete standalone SVG document.
  std::string render() const;
  /// The panel as an SVG group translated by (dx, dy), for composing figures.
  std::string renderGroup(double dx, double dy) const;

 private:
  struct Series {
    std::vector<double> xs, ys;
    std::string label, color;
    double size = 1.5;
    bool dashed = false;
    bool points = false;
  };
  struct Band {
    double x0, x1;
    std::string label, color;
    double opacity;
    bool horizontal = false;
  };
  struct Fill {
    std::vector<double> xs, lows, highs;
    std::string label, color;
    double opacity;
  };
  struct RefLine {
    double value;
    std::string label, color;
    bool dashed;
    bool horizontal;
    bool inRange;
  };
  void calcRanges(double& x0, double& x1, double& y0, double& y1) const;
  /// The plot area in the panel (px) and the data ranges it shows.
  struct Frame {
    double left, top, plotW, plotH;
    double x0, x1, y0, y1;
    double mapX(double x) const { return left + (x - x0) / (x1 - x0) * plotW; }
    double mapY(double y) const { return top + (y1 - y) / (y1 - y0) * plotH; }
  };
  // The steps of renderGroup, in drawing order.
  std::string renderBands(const Frame& f, const std::string& clipId) const;
  std::string renderGrid(const Frame& f) const;
  std::string renderData(const Frame& f, const std::string& clipId) const;
  std::string renderLabels(const Frame& f) const;
  std::string renderLegend(const Frame& f) const;
  int calcLegendCorner(const Frame& f, const double corners[4][2], double boxW, double boxH) const;

  double width_, height_;
  std::string title_, xLabel_, yLabel_;
  bool fixedX_ = false, fixedY_ = false;
  double xLo_ = 0, xHi_ = 1, yLo_ = 0, yHi_ = 1;
  bool legend_ = true;
  std::vector<Series> series_;
  std::vector<Band> bands_;
  std::vector<RefLine> refs_;
  std::vector<Fill> fills_;
  std::vector<std::pair<double, std::string>> yTickLabels_;
  double marginLeft_;
};

/// Panels stacked vertically (top to bottom) in one SVG document, with an optional
/// overall title. The figure is as wide as the widest panel.
std::string renderStackedSvg(const std::vector<SvgPlot>& panels, const std::string& title = "");

/// "Nice" tick positions (1, 2, 5 x 10^n steps) covering [lo, hi], about `target` of them.
std::vector<double> calcNiceTicks(double lo, double hi, int target = 6);

/// Escapes &, <, >, " for SVG text and attributes.
std::string svgEscape(const std::string& text);

}  // namespace swingsim
