#pragma once
// Progress of a long run on stderr. On a terminal: one bar redrawn in place with the count,
// the percentage and the elapsed time, ended by a newline. Anywhere else (a CI log, `| tee`,
// a file): whole lines only, one per tenth of the work (every step when there are 20 or
// fewer), each with the step name, the count and the elapsed time, so lines never run
// together.
#include <chrono>
#include <string>

namespace swingsim::cli {

class ProgressReporter {
 public:
  /// `step`: what is running ("sweep", "mauch-4phase: profiling switches"); `unit`: what is
  /// counted ("swings", "switch settings").
  ProgressReporter(std::string step, std::string unit);
  /// Reports `done` of `total`; cheap to call often.
  void update(int done, int total);

 private:
  std::string step_, unit_;
  bool terminal_;
  int lastReported_ = -1;   ///< last count written (line mode) or drawn (terminal)
  int lastTenth_ = -1;
  bool finished_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace swingsim::cli
