#pragma once
// A swing run for the equivalence tests (settle_dwell_test, early_failure_test): its result,
// or the message of the error that stopped it.
#include <exception>
#include <string>

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

}  // namespace swingsim::testing
