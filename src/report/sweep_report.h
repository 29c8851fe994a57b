#pragma once
// Reports of a knee-axis sweep: the per-participant text tables printed on stdout, the
// JSON result and the CSV of every point; report.md and its figures: report/sweep_markdown.h.
#include <map>
#include <string>

#include "report/sweep_markdown.h"  // makeSweepReport: report.md and its figures
#include "sweep/sweep.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim {

/// Plain-text tables, one per participant, fastest lowering marked.
std::string formatSweepTables(const SweepStudy& study, const SweepResults& results);

/// The `--json` document of the sweep issue; with `uncertainty`, each participant also has
/// fastest_lowering_interval_m, fastest_time_interval_s, sensitivity, uncertainty_samples
/// and seed (docs/formats.md, "Outputs"; docs/uncertainty.md, "JSON").
std::string formatSweepJson(const SweepResults& results, const UncertaintyResults* uncertainty = nullptr);

/// Plain-text summary of the uncertainty analysis: the intervals per participant and the
/// three assumptions that move the fastest lowering most.
std::string formatUncertaintyTables(const UncertaintyResults& uncertainty);

/// CSV of every point: participant, lowering_m, added_mass_kg, added_mass_at_m, ok,
/// swing_time_s, peak_knee_flexion_deg, peak_time_s, bounce, min_toe_clearance_m.
std::string formatSweepCsv(const SweepResults& results);

}  // namespace swingsim
