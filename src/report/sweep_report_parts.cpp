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

std::string formatSymmetryLine(const SymmetryLowering& sym) {
  std::string out = "best symmetry with the sound limb (" + fmt("%.3f", sym.soundTime) + " s): ";
  if (!sym.found) return out + "no swing ended";
  if (sym.reached) return out + fmt("%.3f", sym.lowering) + " m (the swing times cross there; prosthetic/sound 1.00)";
  return out + "not reached; closest " + fmt("%.3f", sym.lowering) + " m, " + fmt("%.4f", sym.prostheticTime) + " s, " +
         fmt("%.0f", std::fabs(sym.gap) * 1000) + " ms " + (sym.gap < 0 ? "faster" : "slower") +
         " than the sound limb (prosthetic/sound " + fmt("%.2f", sym.calcRatio()) + ")";
}

std::string formatLoweringOrNone(double v) { return std::isfinite(v) ? fmt("%.3f", v) : "no end"; }

}  // namespace swingsim::sweep_report_parts
