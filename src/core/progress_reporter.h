#pragma once
// Progress of a long run, on stderr. On a terminal: one bar redrawn in place (\r) with the
// count, the percentage and the elapsed time, ended by a newline. Anywhere else (a CI log,
// `| tee`, a file): whole lines only, each starting with the step name, e.g.
// `sweep burkett2004: 42/84 swings (50 %), 1.3 s`, at most one per 5 % of the work (one per
// step when there are 20 steps or fewer), never a carriage return, so lines never run together.
#include <chrono>
#include <cstdio>
#include <string>

namespace swingsim {

class ProgressReporter {
 public:
  enum class Style {
    kAuto,   ///< a bar if the stream is a terminal (isatty), lines otherwise
    kBar,    ///< redrawn in place
    kLines,  ///< one whole line per report
  };
  /// `step`: what runs ("sweep burkett2004", "mauch-4phase: profiling switches"); `unit`:
  /// what is counted ("swings", "switch settings"). Writes nothing until the first report.
  ProgressReporter(std::string step, std::string unit, std::FILE* stream = stderr, Style style = Style::kAuto);
  /// Ends a bar left unfinished (an interrupted run) with a newline.
  ~ProgressReporter();
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

  /// Reports `done` of `total` (0 <= done <= total); cheap to call often. The report with
  /// done == total is always written and ends the progress; later calls write nothing.
  /// Call from one thread.
  void update(int done, int total);
  /// Writes `text` as a whole line after the step name ("sweep burkett2004: 4 participants"),
  /// ending a bar in progress first.
  void note(const std::string& text);
  /// Also show the rate and the time left at that rate ("..., 12.3 s, 480 swings/s, 25 s
  /// left"), for runs long enough that the user wants to know when they end.
  void setShowRate(bool show) { rate_ = show; }
  /// A resumed run: the first `done` of the work were done by an earlier run, so the rate
  /// and the time left count only what this run does (the count still shows the whole).
  void setResumedFrom(int done) { resumedFrom_ = done; }

 private:
  void endBar();

  std::string step_, unit_;
  std::FILE* stream_;
  bool bar_;
  int lastDone_ = -1;     ///< count of the last report written
  int lastBucket_ = -1;   ///< lines: the 5 % bucket of the last line; bar: its percentage
  double lastDrawn_ = 0;  ///< bar: elapsed seconds at the last redraw
  bool barOpen_ = false;  ///< bar drawn and not yet ended by a newline
  bool finished_ = false;
  bool rate_ = false;
  int resumedFrom_ = 0;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace swingsim
