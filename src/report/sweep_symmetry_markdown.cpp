#include "report/sweep_symmetry_markdown.h"

#include <cmath>
#include <limits>

#include "core/text_format.h"
#include "report/sweep_report_parts.h"

namespace swingsim {

using namespace sweep_report_parts;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string mdRow(const std::vector<std::string>& cells) {
  std::string s = "|";
  for (const auto& c : cells) s += " " + c + " |";
  return s + "\n";
}

// Our swing time at each of Table 4's lowerings (NaN: not simulated or no swing end).
std::vector<double> oursAtTable4(const ParticipantSweep& ps) {
  std::vector<double> times;
  for (const auto& row : ps.published->table4) {
    const SweepPoint* pt = pointAt(ps, row.lowering);
    times.push_back(pt && pt->ok ? pt->result.swingTime : kNaN);
  }
  return times;
}

// A Table 4 row's lowering, "-" for none.
std::string rowLowering(const PublishedParticipant& pub, int row) {
  return row < 0 ? "-" : fmt("%.3f", pub.table4[static_cast<std::size_t>(row)].lowering);
}

}  // namespace

int calcTable4SymmetryRow(const PublishedParticipant& pub, const std::vector<double>& times) {
  int best = -1;
  double bestGap = 0;
  for (std::size_t k = 0; k < pub.table4.size() && k < times.size(); ++k) {
    if (!std::isfinite(times[k])) continue;
    const double gap = std::fabs(times[k] - pub.table4[k].measuredAnatomical);
    if (best < 0 || gap < bestGap) {
      best = static_cast<int>(k);
      bestGap = gap;
    }
  }
  return best;
}

std::string formatSymmetrySection(const SweepResults& results, const UncertaintyResults* uncertainty) {
  std::string rows;
  for (const auto& ps : results.participants) {
    const SymmetryLowering& sym = ps.symmetry;
    if (!sym.given) continue;
    std::vector<std::string> cells = {
        ps.name, fmt("%.3f", sym.soundTime),
        ps.best >= 0 ? fmt("%.3f", ps.points[static_cast<std::size_t>(ps.best)].lowering) : "none ended"};
    if (sym.found)
      cells.insert(cells.end(),
                   {fmt("%.3f", sym.lowering),
                    sym.reached      ? "yes"
                    : sym.acrossJump ? "no: the swing time jumps over it"
                                     : "no",
                    fmt("%.4f", sym.prostheticTime), fmt("%+.0f", sym.gap * 1000), fmt("%.3f", sym.calcRatio())});
    else
      cells.insert(cells.end(), {"no swing end", "", "", "", ""});
    if (uncertainty) {
      const ParticipantUncertainty* pu = uncertaintyOf(uncertainty, ps.name);
      cells.push_back(pu && pu->symmetryLowering.count > 0
                          ? fmt("%.3f", pu->symmetryLowering.p05) + " - " + fmt("%.3f", pu->symmetryLowering.p95)
                          : "-");
      cells.push_back(pu ? std::to_string(pu->symmetryNotReached) + " of " + std::to_string(pu->symmetryLowering.count)
                         : "-");
    }
    rows += mdRow(cells);
  }
  if (rows.empty()) return "";
  std::string md = "## Symmetry with the sound limb\n\n";
  md +=
      "The lowering where the modelled prosthetic swing time equals the sound limb's (the participant file's "
      "`sound_limb_swing_time_s`), beside the fastest. Over the same grid points as the fastest; where the swing "
      "times cross the sound limb's between two grid lowerings the crossing is interpolated linearly (the first "
      "crossing from the standard location), else the closest grid point is given and the symmetry is *not "
      "reached* (gap = prosthetic - sound).\n\n";
  std::vector<std::string> head = {"participant", "sound limb (s)",       "fastest (m)", "best symmetry (m)",
                                   "reached",     "prosthetic there (s)", "gap (ms)",    "prosthetic/sound"};
  if (uncertainty) head.insert(head.end(), {"symmetry 5-95 % (m)", "samples not reaching it"});
  md += mdRow(head) + mdRow(std::vector<std::string>(head.size(), "---")) + rows;
  if (uncertainty)
    md +=
        "\nThe interval is over the Monte Carlo samples with a swing end (\"How sure is the optimum\"), each "
        "sample's symmetry lowering found by the same rule (its closest point where it does not reach the sound "
        "limb's time).\n";
  return md + "\n";
}

std::string formatTable4SymmetrySection(const SweepResults& results) {
  std::string rows;
  for (const auto& ps : results.participants) {
    const PublishedParticipant* pub = ps.published;
    if (!pub || !ps.symmetry.given) continue;
    std::vector<double> measured, model;
    for (const auto& row : pub->table4) {
      measured.push_back(row.measuredProsthetic);
      model.push_back(row.model);
    }
    const int star = calcTable4SymmetryRow(*pub, measured);
    const std::vector<double> oursTimes = oursAtTable4(ps);
    const int ours = calcTable4SymmetryRow(*pub, oursTimes);
    // The control: a swing time that does not change with the lowering (ours at 0 m).
    const int flat =
        oursTimes.empty() ? -1 : calcTable4SymmetryRow(*pub, std::vector<double>(oursTimes.size(), oursTimes.front()));
    const SymmetryLowering& sym = ps.symmetry;
    const std::string grid =
        !sym.found ? "no swing end" : fmt("%.3f", sym.lowering) + (sym.reached ? "" : " (not reached)");
    rows += mdRow(
        {ps.name, rowLowering(*pub, star), grid,
         sym.found && star >= 0 ? fmt("%+.3f", sym.lowering - pub->table4[static_cast<std::size_t>(star)].lowering)
                                : "-",
         rowLowering(*pub, ours), rowLowering(*pub, calcTable4SymmetryRow(*pub, model)), rowLowering(*pub, flat)});
  }
  if (rows.empty()) return "";
  std::string md = "### Best symmetry: Table 4's `*` beside this model\n\n";
  md +=
      "Burkett's `*` is the Table 4 lowering where the measured prosthetic swing time is closest to the measured "
      "anatomical one *at that lowering* (Table 4's anatomical time changes with the lowering). Ours "
      "compares with one sound-limb time, the participant file's (Table 4's anatomical time at 0 m), over the "
      "whole grid; the last three columns use Burkett's per-lowering anatomical times instead, over Table 4's "
      "lowerings only; the last is a control, a swing time that does not change with the lowering (ours at 0 m): "
      "where it picks the same row, the row is set by the anatomical column, not by the knee axis. "
      "docs/burkett2004.md discusses what agrees and why.\n\n";
  md += mdRow({"participant", "Table 4 `*` (m)", "ours, sound limb at 0 m (m)", "ours - `*` (m)",
               "ours, per-lowering anatomical (m)", "Burkett's model, per-lowering anatomical (m)",
               "constant swing time, per-lowering anatomical (m)"});
  md += mdRow({"---", "---", "---", "---", "---", "---", "---"});
  return md + rows + "\n";
}

}  // namespace swingsim
