#include "study/run_estimate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <thread>

#include "core/input_error.h"

namespace swingsim {

std::string formatEstimate(double seconds) {
  char estimate[64];
  if (seconds < 120)
    std::snprintf(estimate, sizeof estimate, "%.0f s", std::ceil(seconds));
  else if (seconds < 7200)
    std::snprintf(estimate, sizeof estimate, "%.0f min", std::ceil(seconds / 60));
  else
    std::snprintf(estimate, sizeof estimate, "%.3g hours", seconds / 3600);
  return estimate;
}

void announceRunSize(const RunSize& size, std::uint64_t limit, const std::string& where, const std::string& shrink,
                     const std::string& option) {
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const std::uint64_t asked = size.jobs > 0 ? static_cast<std::uint64_t>(size.jobs) : cores;
  const double threads = static_cast<double>(std::max<std::uint64_t>(1, std::min(asked, size.count)));
  const std::string estimate = formatEstimate(static_cast<double>(size.count) * size.secondsPerUnit /
                                              std::min(threads, static_cast<double>(cores)));
  std::fprintf(stderr, "%s: %llu %s (%s), about %s on %d thread%s\n", size.label.c_str(),
               static_cast<unsigned long long>(size.count), size.unit.c_str(), size.detail.c_str(), estimate.c_str(),
               static_cast<int>(threads), threads == 1 ? "" : "s");
  if (size.count > limit)
    throw InputError(where + ": " + size.noun + " has " + std::to_string(size.count) + " " + size.unit + " (" +
                     size.detail + "; about " + estimate + "), more than the limit of " + std::to_string(limit) + ": " +
                     shrink + ", or raise the limit with " + option + " " + std::to_string(size.count) +
                     " if you mean it");
}

}  // namespace swingsim
