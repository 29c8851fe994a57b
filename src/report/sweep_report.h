#pragma once
// Reports of a knee-axis sweep: the per-participant text tables printed on stdout, the
// JSON result, the CSV of every point, and out/<study>/report.md with SVG figures (the
// paper's Figs. 3 and 4, stick-figure filmstrips, Tables 3 and 4 side by side).
#include <map>
#include <string>

#include "swing/sweep.h"

namespace swingsim {

/// Plain-text tables, one per participant, fastest lowering marked.
std::string formatSweepTables(const SweepStudy& study, const SweepResults& results);

/// The `--json` document of the sweep issue.
std::string formatSweepJson(const SweepResults& results);

/// CSV of every point: participant, lowering_m, added_mass_kg, added_mass_at_m, ok,
/// swing_time_s, peak_knee_flexion_deg, peak_time_s, bounce, min_toe_clearance_m.
std::string formatSweepCsv(const SweepResults& results);

/// All report files, file name (relative to the output folder) -> contents.
std::map<std::string, std::string> makeSweepReport(const SweepStudy& study, const SweepResults& results);

}  // namespace swingsim
