#pragma once
// Small pieces shared by the sweep report's units: sweep_report.cpp (the text tables, the
// JSON and the CSV) and sweep_markdown.cpp (report.md and its figures).
#include <string>

#include "sweep/sweep.h"
#include "sweep/sweep_assumptions.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim::sweep_report_parts {

constexpr double kSameLowering = 1e-6;  // m: lowerings closer than this are the same row

/// The plain sweep's point at `lowering`; nullptr if none was simulated there.
const SweepPoint* pointAt(const ParticipantSweep& ps, double lowering);
/// The study's participant called `name`; nullptr if none.
const Participant* participantNamed(const SweepStudy& study, const std::string& name);
/// A failed point's cause in a few words, for a table cell.
std::string shortFailure(const SweepPoint& pt);
/// The uncertainty analysis of participant `name`; nullptr without one.
const ParticipantUncertainty* uncertaintyOf(const UncertaintyResults* u, const std::string& name);
/// The assumption with `key` (sweep/sweep_assumptions.h); nullptr if none.
const SweepAssumption* assumptionKeyed(const std::string& key);
/// An assumption's value as a reader wants it: the reading's name for a two-way choice.
std::string formatAssumptionValue(const std::string& key, double v);
/// " N m" after a value; nothing for a choice or a dimensionless value (unit "1").
std::string unitSuffix(const std::string& unit);
/// One line on the symmetry lowering (sym.given): where the prosthetic swing time meets the
/// sound limb's, or the closest point with its gap when it never does; where the swing time
/// jumps over the sound limb's, the jump of `jumps` with its cause.
std::string formatSymmetryLine(const SymmetryLowering& sym, const std::vector<SwingTimeJump>& jumps = {});
/// The jump next to grid point `best` of ps.points (between it and a neighbouring grid
/// lowering), or nullptr: a fastest swing beside a jump lies at the edge of its piece.
const SwingTimeJump* jumpBesideBest(const ParticipantSweep& ps);
/// " (a jump beside it: the swing jumps from ... at ... m (...))" or "" (jumpBesideBest).
std::string formatJumpBesideBest(const ParticipantSweep& ps);
/// A lowering in m with 3 decimals, "no end" if not finite.
std::string formatLoweringOrNone(double v);

}  // namespace swingsim::sweep_report_parts
