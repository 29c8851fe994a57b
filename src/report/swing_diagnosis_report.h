#pragma once
// Reports of `swingsim compare` and `swingsim diagnose` for the swing (kind:
// swing-diagnosis): knee RMSE (deg) per file and per swing phase, the ranking of every step,
// the before/after table, the residual plots, and the JSON of issue 5. Shared pieces:
// report/diagnosis_report.h.
#include <string>
#include <vector>

#include "identify/swing_diagnosis.h"

namespace swingsim {

std::string formatSwingComparisonTable(const SwingComparison& comparison);
/// One SVG with five stacked panels for one record (the cylinder's layout,
/// renderResidualPanels): knee residual (deg) vs time over the whole swing with the swing
/// phases shaded; binned mean knee residual with its 99 % band vs the model's knee flexion
/// (deg), knee flexion rate (deg/s) and knee angular acceleration (deg/s^2, central
/// differences of the model rate); knee residual autocorrelation with its 99 % band.
std::string renderSwingResidualSvg(const SwingRecordComparison& record, const std::vector<std::string>& phaseNames,
                                   const std::string& title);

/// Writes `<prefix>-<stem>-residual.svg` for every record into `outDir`; returns the paths.
std::vector<std::string> writeSwingResidualPlots(const std::string& outDir, const std::string& prefix,
                                                 const SwingComparison& comparison);

std::string formatSwingDiagnosisText(const SwingDiagnosis& diagnosis, const SwingComparison& before,
                                     const SwingComparison& after);
std::string formatSwingDiagnosisJson(const SwingDiagnosis& diagnosis, const SwingComparison& before,
                                     const SwingComparison& after);

}  // namespace swingsim
