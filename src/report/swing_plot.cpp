#include "report/swing_plot.h"

#include "report/svg_plot.h"

namespace swingsim {

std::string formatSwingMomentsSvg(const SwingTrajectory& trajectory, const std::string& title) {
  SvgPlot plot(800, 360);
  plot.setTitle(title);
  plot.setXLabel("time since toe-off (s)");
  plot.setYLabel("moment (N m, + = flexion)");
  plot.addLine(trajectory.time, trajectory.hipMoment, "hip moment", svgPaletteColor(0));
  plot.addLine(trajectory.time, trajectory.kneeMoment, "knee moment", svgPaletteColor(1));
  plot.addHLine(0, "", "#999999");
  return plot.render();
}

}  // namespace swingsim
