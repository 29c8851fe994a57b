#pragma once
// CPU time for the tests' "refused quickly" and "linear time" checks. A wall-clock bound fails
// when a loaded machine (ctest -j2 beside a sanitizer build) keeps the test off a core; CPU
// time counts only the time the work ran, so the bound speaks of the work, not of the load.
// Each bound stays far below what the failure it guards against would cost (a quadratic
// check, a whole file read, an unbounded swing).

#include <sys/resource.h>
#include <time.h>

#include <functional>

namespace swingsim::testing {

/// CPU seconds (user + system) this process spent in `f`.
inline double cpuSecondsOf(const std::function<void()>& f) {
  const auto now = [] {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  };
  const double start = now();
  f();
  return now() - start;
}

/// CPU seconds (user + system) of the child processes that `f` started and waited for (a
/// `runSwingsim` call: the shell and the program it ran).
inline double childCpuSecondsOf(const std::function<void()>& f) {
  const auto now = [] {
    rusage u{};
    getrusage(RUSAGE_CHILDREN, &u);
    const auto seconds = [](const timeval& t) {
      return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
    };
    return seconds(u.ru_utime) + seconds(u.ru_stime);
  };
  const double start = now();
  f();
  return now() - start;
}

}  // namespace swingsim::testing
