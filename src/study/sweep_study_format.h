#pragma once
// The parts of the knee-axis sweep study format that other study kinds share (the cohort
// study, cohort_study.h): the `lowering:` map and the `integrator:` map, described once for
// the YAML archives (io/yaml_archive.h).
#include <string>
#include <utility>
#include <vector>

#include "io/yaml_reader.h"
#include "sweep/sweep.h"

namespace swingsim {

/// Tag: serialize a study's `lowering:` map.
struct LoweringOf {};

inline std::vector<std::pair<std::string, SwingIntegrator>> integratorChoices() {
  std::vector<std::pair<std::string, SwingIntegrator>> choices;
  for (const auto& key : integratorKeys()) choices.emplace_back(key, *findIntegrator(key));
  return choices;
}

template <class A>
void serialize(A& a, SweepStudy& s, LoweringOf) {
  // The grid is rounded to 1 um (sweepLowerings): a smaller step would never advance. With
  // lowerings capped by the shank (calcMaxLowering), this also bounds a sweep to a few
  // thousand swings per participant.
  a.optionalNumber("step_m", s.loweringStep,
                   [](double v) { return v >= 1e-4 ? "" : "expected a step of at least 0.0001 m"; });
  a.optionalNumber("max_m", s.loweringMax, mustBeNonNegative);
  a.optionalFlag("include_published", s.includePublishedLowerings);
}

template <class A>
void serialize(A& a, SwingOptions& o) {
  a.choice("method", o.integrator, integratorChoices(), true);
  a.optionalNumber("accuracy", o.accuracy, [](double v) { return checkAccuracy(v); });
  a.optionalNumber("sample_interval_s", o.sampleInterval, [](double v) {
    return v >= 1e-5 && v <= 0.1 ? "" : "expected a sample interval from 0.00001 to 0.1 s";
  });
}

}  // namespace swingsim
