#pragma once
// Swing runs for the equivalence tests (settle_dwell_test, early_failure_test): a swing's
// result or the message of the error that stopped it, and the Burkett Monte Carlo's swings
// run with a lever on and off.
#include <gtest/gtest.h>

#include <cstdint>
#include <exception>
#include <string>

#include "study/sweep_study.h"
#include "sweep/sweep_uncertainty.h"
#include "swing/swing_simulation.h"

namespace swingsim::testing {

struct SwingOutcome {
  bool ok = false;
  std::string failure;  ///< what() of the error, if !ok
  SwingResult result;
};

inline SwingOutcome runSwingCatching(const SwingSetup& setup, const SwingOptions& options) {
  SwingOutcome o;
  try {
    o.result = simulateSwing(setup, options);
    o.ok = true;
  } catch (const std::exception& e) {
    o.failure = e.what();
  }
  return o;
}

/// Every swing of `samples` Monte Carlo samples (seed `seed`, no one-at-a-time runs) of
/// studies/burkett2004.yaml, run with its own options ("on") and with `turnOff(options)`
/// applied ("off"); check(planned, on, off) is called for each, under a trace naming the
/// participant, the lowering and the sample.
template <class TurnOff, class Check>
void compareMonteCarloSwings(int samples, std::uint64_t seed, TurnOff turnOff, Check check) {
  const SweepStudy study = loadSweepStudy("studies/burkett2004.yaml");
  UncertaintyOptions options;
  options.samples = samples;
  options.seed = seed;
  options.sensitivity = false;
  const UncertaintyPlan plan = planSweepUncertainty(study, options);
  for (std::size_t swing = 0; swing < plan.swingCount; ++swing) {
    const PlannedSwing planned = plan.makeSwing(swing);
    const SwingSetup setup = planned.makeSetup();
    SwingOptions off = planned.variant.swing;
    turnOff(off);
    SCOPED_TRACE(setup.participant.name + " at " + std::to_string(planned.lowering) + " m, sample " +
                 std::to_string(planned.run->sample));
    check(planned, runSwingCatching(setup, planned.variant.swing), runSwingCatching(setup, off));
  }
}

}  // namespace swingsim::testing
