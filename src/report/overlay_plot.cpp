#include "report/overlay_plot.h"

#include "core/output_files.h"
#include "core/text_format.h"
#include "report/svg_plot.h"

namespace swingsim {

namespace {

SvgPlot overlayPanel(const std::vector<double>& time, const std::vector<double>& measured,
                     const std::vector<double>& model, const std::string& quantity, const std::string& unit,
                     const std::string& measuredLabel, const std::string& title) {
  SvgPlot plot(800, 300);
  plot.setTitle(title);
  plot.setXLabel("time (s)");
  plot.setYLabel(quantity + " (" + unit + ")");
  plot.addLine(time, measured, measuredLabel, "#000000", 2.0);
  plot.addLine(time, model, "model", svgPaletteColor(1), 1.5);
  return plot;
}

}  // namespace

std::string renderOverlaySvg(const RecordComparison& r, const Comparison& c, const HeldBackComparison::Record* moment,
                             const std::string& momentUnit, const std::string& title) {
  std::vector<SvgPlot> panels;
  panels.push_back(overlayPanel(
      r.time, r.measured, r.predicted, c.quantity, c.unit, "measured",
      c.quantity + ": measured and model, RMSE " + fmt("%.*f", c.decimals + 1, r.overall.rmse) + " " + c.unit));
  if (!r.secondaryMeasured.empty() && r.secondaryMeasured.size() == r.secondaryPredicted.size())
    panels.push_back(overlayPanel(r.time, r.secondaryMeasured, r.secondaryPredicted, c.secondaryQuantity, c.unit,
                                  "measured",
                                  c.secondaryQuantity + ": measured and model, RMSE " +
                                      fmt("%.*f", c.decimals + 1, r.secondary.rmse) + " " + c.unit));
  if (moment) {
    SvgPlot plot =
        overlayPanel(moment->time, moment->measured, moment->model, "knee moment", momentUnit + ", + = flexion",
                     "measured (inverse dynamics)",
                     fmt("knee moment: model against inverse dynamics (never fitted), RMSE %.1f ", moment->rmse) +
                         momentUnit + fmt(", r %+.2f", moment->correlation));
    plot.addHLine(0, "", "#999999");
    panels.push_back(plot);
  }
  return renderStackedSvg(panels, title);
}

std::vector<std::string> writeOverlayPlots(const std::string& outDir, const std::string& prefix, const Comparison& c,
                                           const HeldBackComparison* heldBack) {
  std::vector<std::string> paths;
  if (c.secondaryQuantity.empty()) return paths;
  for (const auto& r : c.records) {
    const HeldBackComparison::Record* moment = nullptr;
    if (heldBack)
      for (const auto& m : heldBack->records)
        if (m.stem == r.stem) moment = &m;
    const std::string path = outDir + "/" + prefix + "-" + makeSafeFileStem(r.stem) + "-overlay.svg";
    writeFileAtomic(path, renderOverlaySvg(r, c, moment, heldBack ? heldBack->unit : "",
                                           prefix + ": " + r.stem + (r.training ? " (train)" : " (validate)") +
                                               ", measured and model"));
    paths.push_back(path);
  }
  return paths;
}

}  // namespace swingsim
