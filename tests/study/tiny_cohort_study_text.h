#pragma once
// A small valid cohort-sweep study with every distribution (P1 as template), for the cohort
// study tests; `from` -> `to` swaps one piece of its text for another.
#include <gtest/gtest.h>

#include <string>

namespace swingsim {

inline std::string tinyCohortStudyText(int participants, const std::string& from = "", const std::string& to = "") {
  std::string text = R"(kind: cohort-sweep
name: tiny-cohort
participants: )" + std::to_string(participants) +
                     R"(
seed: 3
template: participants/p1.yaml
lowering: {step_m: 0.05, max_m: 0.10}
distributions:
  stature_m: {distribution: normal, mean: 1.759, sd: 0.067, min: 1.649, max: 1.869, source: Huston 2009}
  body_mass_index_kg_m2: {distribution: uniform, min: 20, max: 26, source: Burkett 2004 Table 1}
  residual_limb_fraction: {distribution: uniform, min: 0.57, max: 1.0, source: Baum 2008}
  socket_mass_kg: {distribution: uniform, min: 0.5, max: 1.2, source: "assumption"}
  knee_mass_kg: {distribution: uniform, min: 0.4, max: 1.4, source: "assumption"}
  knee_com_below_axis_m: {distribution: uniform, min: 0.03, max: 0.08, source: "assumption"}
  knee_radius_of_gyration_m: {distribution: uniform, min: 0.03, max: 0.06, source: "assumption"}
  pylon_mass_kg: {distribution: uniform, min: 0.08, max: 0.30, source: "assumption"}
  foot_mass_kg: {distribution: uniform, min: 0.45, max: 1.05, source: Burkett 2004 Table 2}
  foot_com_from_toe_fraction: {distribution: uniform, min: 0.55, max: 0.78, source: Burkett 2004 Table 2}
  foot_radius_of_gyration_fraction: {distribution: uniform, min: 0.30, max: 0.48, source: Burkett 2004 Table 2}
  knee_friction_Nm: {distribution: uniform, min: 5, max: 15, source: Burkett 2004 Table 2}
  swing_time_s: {distribution: uniform, min: 0.40, max: 0.48, source: Burkett 2004 Table 3}
)";
  if (!from.empty()) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  }
  return text;
}

}  // namespace swingsim
