#pragma once
// out/<study>/report.md of a knee-axis sweep with its SVG figures: a summary, Burkett's
// Tables 3 and 4 beside this model, the fastest lowering, terminal impact, added mass, the
// uncertainty analysis, one section per participant, failures and assumptions.
#include <map>
#include <string>

#include "sweep/sweep.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim {

/// All report files, file name (relative to the output folder) -> contents: report.md, its
/// figures, sweep.csv, and report.html (report/sweep_html.h: the same content in one page).
/// With `uncertainty`: a "How sure is the optimum" section, a tornado figure per
/// participant and the 5-95 % band on the swing-time figure.
std::map<std::string, std::string> makeSweepReport(const SweepStudy& study, const SweepResults& results,
                                                   const UncertaintyResults* uncertainty = nullptr);

}  // namespace swingsim
