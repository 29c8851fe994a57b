#pragma once
// Reports of a knee-axis sweep: the per-participant text tables printed on stdout, the
// JSON result, the CSV of every point, and out/<study>/report.md with SVG figures (the
// paper's Figs. 3 and 4, stick-figure filmstrips, Tables 3 and 4 side by side).
#include <map>
#include <string>

#include "sweep/sweep.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim {

/// Plain-text tables, one per participant, fastest lowering marked.
std::string formatSweepTables(const SweepStudy& study, const SweepResults& results);

/// The `--json` document of the sweep issue; with `uncertainty`, each participant also has
/// fastest_lowering_interval_m, fastest_time_interval_s, sensitivity, uncertainty_samples
/// and seed (README, File formats).
std::string formatSweepJson(const SweepResults& results, const UncertaintyResults* uncertainty = nullptr);

/// Plain-text summary of the uncertainty analysis: the intervals per participant and the
/// three assumptions that move the fastest lowering most.
std::string formatUncertaintyTables(const UncertaintyResults& uncertainty);

/// CSV of every point: participant, lowering_m, added_mass_kg, added_mass_at_m, ok,
/// swing_time_s, peak_knee_flexion_deg, peak_time_s, bounce, min_toe_clearance_m.
std::string formatSweepCsv(const SweepResults& results);

/// All report files, file name (relative to the output folder) -> contents.
/// With `uncertainty`: a "How sure is the optimum" section, a tornado figure per
/// participant and the 5-95 % band on the swing-time figure.
std::map<std::string, std::string> makeSweepReport(const SweepStudy& study, const SweepResults& results,
                                                   const UncertaintyResults* uncertainty = nullptr);

}  // namespace swingsim
