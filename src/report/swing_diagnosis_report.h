#pragma once
// Reports of `swingsim compare` and `swingsim diagnose` for the swing (kind:
// swing-diagnosis): knee RMSE (deg) per file and per swing phase, the ranking of every step,
// the before/after table, and the JSON of issue 5. Shared pieces: report/diagnosis_report.h.
#include <string>

#include "fit/swing_diagnosis.h"

namespace swingsim {

std::string formatSwingComparisonTable(const SwingComparison& comparison);
std::string formatSwingDiagnosisText(const SwingDiagnosis& diagnosis, const SwingComparison& before,
                                     const SwingComparison& after);
std::string formatSwingDiagnosisJson(const SwingDiagnosis& diagnosis, const SwingComparison& before,
                                     const SwingComparison& after);

}  // namespace swingsim
