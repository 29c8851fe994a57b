#include "cli/sweep_steps.h"

#include <csignal>
#include <cstdlib>
#include <string>

#include "cli/option_checks.h"
#include "core/input_error.h"

namespace swingsim::cli {

volatile bool gInterrupted = false;

namespace {

extern "C" void onInterrupt(int) { gInterrupted = true; }

}  // namespace

InterruptScope::InterruptScope() {
  std::signal(SIGINT, onInterrupt);
  std::signal(SIGTERM, onInterrupt);
}

InterruptScope::~InterruptScope() {
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}

long stopAfterSwingsForTests() {
  const char* v = std::getenv("SWINGSIM_TEST_STOP_AFTER_SWINGS");
  if (!v || !*v) return -1;
  char* end = nullptr;
  const long n = std::strtol(v, &end, 10);
  if (*end != '\0' || n < 0)
    throw InputError(std::string("SWINGSIM_TEST_STOP_AFTER_SWINGS: expected a whole number of swings, found \"") + v +
                     "\"");
  return n;
}

SweepRunControl makeTerminalControl() {
  SweepRunControl control;
  control.stop = &gInterrupted;
  control.stopAfterSwings = stopAfterSwingsForTests();
  control.terminal = true;
  return control;
}

void addMaxSwingsOption(CLI::App* sub, long long& maxSwings) {
  sub->add_option("--max-swings", maxSwings,
                  "refuse a plain sweep, or a cohort run or shard, of more swings than this (default " +
                      std::to_string(kDefaultMaxSweepSwings) +
                      "; the count and a time estimate are printed before it starts)")
      ->type_name("N")
      ->check(wholeNumberIn(maxSwingsRange()));
}

}  // namespace swingsim::cli
