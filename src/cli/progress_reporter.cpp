#include "cli/progress_reporter.h"

#include <unistd.h>

#include <cstdio>

namespace swingsim::cli {

namespace {

constexpr int kBarWidth = 40;
constexpr int kEveryStepUpTo = 20;  // with this few steps, line mode reports every one

}  // namespace

ProgressReporter::ProgressReporter(std::string step, std::string unit)
    : step_(std::move(step)), unit_(std::move(unit)), terminal_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()) {}

void ProgressReporter::update(int done, int total) {
  if (finished_ || done == lastReported_) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const int percent = total > 0 ? 100 * done / total : 100;
  const bool last = done >= total;
  if (terminal_) {
    const int filled = total > 0 ? kBarWidth * done / total : kBarWidth;
    std::fprintf(stderr, "\r%s [%.*s%*s] %d/%d %s (%d %%), %.1f s", step_.c_str(), filled,
                 "########################################", kBarWidth - filled, "", done, total, unit_.c_str(), percent,
                 elapsed);
    if (last) std::fprintf(stderr, "\n");
  } else {
    const int tenth = total > 0 ? 10 * done / total : 10;
    if (total > kEveryStepUpTo && tenth == lastTenth_ && !last) return;
    lastTenth_ = tenth;
    std::fprintf(stderr, "%s: %d/%d %s (%d %%), %.1f s\n", step_.c_str(), done, total, unit_.c_str(), percent, elapsed);
  }
  std::fflush(stderr);
  lastReported_ = done;
  finished_ = last;
}

}  // namespace swingsim::cli
