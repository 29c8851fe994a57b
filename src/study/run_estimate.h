#pragma once
// The size of a large run (a sweep, a cohort, a measured sweep table, a long record) and a
// rough time for it, printed on stderr before any work, and its limit: a run above the limit
// is refused, naming the option that raises it (docs/robustness.md, "Large runs").
#include <cstdint>
#include <string>

namespace swingsim {

/// What a run is about to do.
struct RunSize {
  std::string label;          ///< "sweep NAME", "cohort NAME": what the printed line starts with
  std::string noun;           ///< "the sweep", "the cohort": the subject of the refusal
  std::uint64_t count = 0;    ///< units of work
  std::string unit;           ///< "swings", "rows"
  std::string detail;         ///< "3 participants, no added mass"
  double secondsPerUnit = 0;  ///< s on one core, measured (a rough estimate)
  int jobs = 1;               ///< worker threads, 0 = all cores
};

/// Seconds a swing takes on one core, for estimates (docs/robustness.md, "Large runs"):
/// measured on the Burkett sweep (435
/// swings of `swingsim sweep studies/burkett2004.yaml --jobs 1` in 2.7 s); a swing with a
/// stiff knee or a tight accuracy can take several times longer: a rough estimate.
constexpr double kSecondsPerSwingEstimate = 0.006;

/// "N s", "N min" or "N hours": a rough run time for the terminal.
std::string formatEstimate(double seconds);

/// Prints "LABEL: COUNT UNIT (DETAIL), about T on K threads" on stderr; InputError starting
/// with `where` if the count is above `limit`: "...: NOUN has COUNT UNIT (DETAIL; about T),
/// more than the limit of LIMIT: SHRINK, or raise the limit with OPTION COUNT if you mean it".
void announceRunSize(const RunSize& size, std::uint64_t limit, const std::string& where, const std::string& shrink,
                     const std::string& option);

}  // namespace swingsim
