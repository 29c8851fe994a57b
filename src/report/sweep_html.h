#pragma once
// report.html of a knee-axis sweep: report.md's content as one self-contained page (every
// figure inline as <svg>, no scripts, no links to files), with each participant's fastest
// swing as an animated stick figure (report/stick_figure_animation.h).
#include <map>
#include <string>

#include "sweep/sweep.h"

namespace swingsim {

/// The page from `files` (makeSweepReport's: "report.md" and the figures it links, by their
/// path there), with the animation after each participant's "## NAME" heading when its
/// fastest swing has a trajectory. Throws std::logic_error if report.md links a figure that
/// `files` lacks.
std::string makeSweepReportHtml(const SweepStudy& study, const SweepResults& results,
                                const std::map<std::string, std::string>& files);

}  // namespace swingsim
