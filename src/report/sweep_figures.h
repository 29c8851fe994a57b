#pragma once
// The SVG figures of the sweep report (report/sweep_markdown.h links them from report.md).
#include <string>

#include "report/svg_plot.h"
#include "sweep/sweep.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim {

/// Swing time against the knee-axis lowering (cf. Burkett 2004 Fig. 4) with Table 4's model
/// and measured points, Burkett's fastest, ours, and with `pu` the 5-95 % band.
SvgPlot makeSwingTimeFigure(const ParticipantSweep& ps, const ParticipantUncertainty* pu);
/// The change in the fastest lowering with each assumption at the low and high end of its
/// range, largest effect on top.
SvgPlot makeTornadoFigure(const ParticipantUncertainty& pu);
/// Knee flexion against time every 50 mm of lowering (cf. Burkett 2004 Fig. 3), with the
/// zone of stability below `zoneDeg` shaded.
SvgPlot makeKneeFlexionFigure(const ParticipantSweep& ps, double zoneDeg);
/// Hip-thigh-shank-foot stick figures every 40 ms from toe-off to the swing end, on equal axes.
SvgPlot makeFilmstrip(const std::string& title, const SwingResult& r, double hipHeight);

}  // namespace swingsim
