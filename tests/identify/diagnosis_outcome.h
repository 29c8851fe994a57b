#pragma once
// Test support: one summary of a diagnosis the independent-data tests assert on and print.
#include <algorithm>
#include <cstdio>
#include <string>

#include "identify/diagnosis_engine.h"

namespace swingsim::testing {

/// The largest held-out RMSE of the final model (unit of the data).
inline double worstHeldOut(const Diagnosis& dg) {
  double w = 0;
  for (double r : dg.final.validationRmse) w = std::max(w, r);
  return w;
}

/// One line: what was accepted, the held-out errors against the noise, the verdict; then
/// confounds and warnings, indented.
inline void printOutcome(const std::string& tag, const Diagnosis& dg, const char* unit, double noise) {
  std::printf("  %s: accepted", tag.c_str());
  for (const auto& a : dg.accepted) std::printf(" %s", a.c_str());
  std::printf("; held-out");
  for (double r : dg.final.validationRmse) std::printf(" %.3g", r);
  std::printf(" %s (noise %.3g); %s\n", unit, noise, dg.explained ? "explained" : dg.verdict.c_str());
  for (const auto& c : dg.confounds) std::printf("    confound: %s\n", c.c_str());
  for (const auto& w : dg.warnings) std::printf("    warning: %s\n", w.c_str());
}

}  // namespace swingsim::testing
