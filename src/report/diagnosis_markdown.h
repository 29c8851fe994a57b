#pragma once
// The report directory of `swingsim diagnose`: report.md (the command, the base model's
// comparison before, the ranking and result, the comparison after, the held-back knee
// moment when the plant has one, links to the residual plots) with its SVG plots.
#include <optional>
#include <string>
#include <vector>

#include "identify/comparison.h"
#include "identify/diagnosis_engine.h"

namespace swingsim {

/// What report.md of a diagnosis shows; everything is computed before it is written.
struct DiagnosisReportInput {
  std::string studyName;
  std::string command;  ///< the command line, quoted in the report
  std::string drive;    ///< describeStudyDrive of the study; empty: not said
  const Diagnosis* diagnosis = nullptr;
  const Comparison* before = nullptr;  ///< the base model against the data
  const Comparison* after = nullptr;   ///< the diagnosed model against the data
  std::string check;                   ///< the plant's verification of the final model; empty: none
  std::optional<HeldBackComparison> heldBefore, heldAfter;  ///< both or neither
  std::vector<std::string> heldWarnings;                    ///< checkHeldBackComparison's warnings, written under it
};

/// The "## Warnings" section of a report (a bullet per warning), "" when there are none.
std::string formatWarningsSection(const std::vector<std::string>& warnings);

/// Writes report.md, held-back.svg (when both held-back comparisons are given) and the
/// residual plots before-*.svg and after-*.svg into `outDir`, each atomically.
void writeDiagnosisReport(const std::string& outDir, const DiagnosisReportInput& input);

}  // namespace swingsim
