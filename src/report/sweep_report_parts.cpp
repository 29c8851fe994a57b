#include "report/sweep_report_parts.h"

#include <cmath>

#include "core/text_format.h"
#include "sweep/sweep_assumptions.h"

namespace swingsim::sweep_report_parts {

const SweepPoint* pointAt(const ParticipantSweep& ps, double lowering) {
  for (const auto& pt : ps.points)
    if (std::fabs(pt.lowering - lowering) < kSameLowering) return &pt;
  return nullptr;
}

const Participant* participantNamed(const SweepStudy& study, const std::string& name) {
  for (const auto& p : study.participants)
    if (p.name == name) return &p;
  return nullptr;
}

std::string shortFailure(const SweepPoint& pt) {
  if (pt.failure.find("thigh never reached") != std::string::npos) return "no end: thigh short of target";
  if (pt.failure.find("never came back") != std::string::npos) return "no end: knee stays flexed";
  if (pt.failure.find("knee flexion passed") != std::string::npos)
    return "failed: knee past " + fmt("%.0f", kKneeFlexionLimit * kRadToDeg) + " deg";
  if (!pt.ran) return "not run (interrupted)";
  return "failed";
}

const ParticipantUncertainty* uncertaintyOf(const UncertaintyResults* u, const std::string& name) {
  if (!u) return nullptr;
  for (const auto& pu : u->participants)
    if (pu.name == name) return &pu;
  return nullptr;
}

const SweepAssumption* assumptionKeyed(const std::string& key) {
  for (const auto& a : sweepAssumptions())
    if (a.key == key) return &a;
  return nullptr;
}

std::string formatAssumptionValue(const std::string& key, double v) {
  const SweepAssumption* a = assumptionKeyed(key);
  if (a && a->discrete) return a->choices[v >= 0.5 ? 1 : 0];
  return fmt("%.4g", v);
}

std::string unitSuffix(const std::string& unit) { return unit == "choice" || unit == "1" ? "" : " " + unit; }

const SwingTimeJump* jumpBesideBest(const ParticipantSweep& ps) {
  if (ps.best < 0) return nullptr;
  const auto best = static_cast<std::size_t>(ps.best);
  const double at = ps.points[best].lowering;
  for (std::size_t k = 0; k < ps.points.size(); ++k) {
    if (k == best || !ps.points[k].onGrid) continue;
    const SwingTimeJump* j = findJumpBetween(ps.jumps, at, ps.points[k].lowering);
    // Only a neighbour: no grid point between the two.
    bool between = false;
    for (const SweepPoint& pt : ps.points)
      between = between || (pt.onGrid && pt.lowering > std::min(at, ps.points[k].lowering) + 1e-12 &&
                            pt.lowering < std::max(at, ps.points[k].lowering) - 1e-12);
    if (j && !between) return j;
  }
  return nullptr;
}

std::string formatJumpBesideBest(const ParticipantSweep& ps) {
  const SwingTimeJump* j = jumpBesideBest(ps);
  return j ? " (at the edge of its piece: " + j->describe() + ")" : "";
}

std::string formatSymmetryLine(const SymmetryLowering& sym, const std::vector<SwingTimeJump>& jumps) {
  std::string out = "best symmetry with the sound limb (" + fmt("%.3f", sym.soundTime) + " s): ";
  if (!sym.found) return out + "no swing ended";
  const SwingTimeJump* jump = sym.acrossJump ? findJumpBetween(jumps, sym.jumpFrom, sym.jumpTo) : nullptr;
  const std::string jumpText =
      jump ? jump->describe()
           : "the swing jumps between " + fmt("%.4f", sym.jumpFrom) + " and " + fmt("%.4f", sym.jumpTo) + " m";
  if (sym.reached) {
    out += fmt("%.3f", sym.lowering) + " m (the swing times cross there; prosthetic/sound 1.00)";
    if (sym.acrossJump)
      out += "; not at " + fmt("%.4f", sym.jumpFrom) + "-" + fmt("%.4f", sym.jumpTo) + " m, where " + jumpText;
    return out;
  }
  if (sym.acrossJump)
    out += "not reached: " + jumpText + ";";
  else
    out += "not reached;";
  return out + " closest " + fmt("%.3f", sym.lowering) + " m, " + fmt("%.4f", sym.prostheticTime) + " s, " +
         fmt("%.0f", std::fabs(sym.gap) * 1000) + " ms " + (sym.gap < 0 ? "faster" : "slower") +
         " than the sound limb (prosthetic/sound " + fmt("%.2f", sym.calcRatio()) + ")";
}

std::string formatLoweringOrNone(double v) { return std::isfinite(v) ? fmt("%.3f", v) : "no end"; }

}  // namespace swingsim::sweep_report_parts
