#pragma once
// The terminal's side of a sweep run (study/sweep_run.h) for `swingsim sweep` and `swingsim
// merge`: Ctrl-C handling, the test hook that stops a run at a known point, and the
// --max-swings option.
#include <CLI/CLI.hpp>

#include "study/sweep_run.h"

namespace swingsim::cli {

/// Set by SIGINT or SIGTERM while an InterruptScope is alive: no further swing starts; in the
/// write phase the staged files are discarded rather than left half-written.
extern volatile bool gInterrupted;

/// Ctrl-C (and SIGTERM) sets gInterrupted while this lives; the defaults come back after.
class InterruptScope {
 public:
  InterruptScope();
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;
};

/// Test hook: SWINGSIM_TEST_STOP_AFTER_SWINGS=N stops a resumable run after N swings (a
/// cohort run: N participants), as Ctrl-C would (the CLI tests of interrupted and resumed
/// runs; not an option, since no user needs it); -1 if unset. Throws InputError if not a
/// whole number.
long stopAfterSwingsForTests();

/// A run that reports on the terminal and stops on Ctrl-C (gInterrupted) or the test hook.
SweepRunControl makeTerminalControl();

/// `--max-swings N`: the largest plain sweep to run (default kDefaultMaxSweepSwings).
void addMaxSwingsOption(CLI::App* sub, long long& maxSwings);

}  // namespace swingsim::cli
