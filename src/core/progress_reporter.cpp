#include "core/progress_reporter.h"

#include <unistd.h>

namespace swingsim {

namespace {

constexpr int kBarWidth = 40;
constexpr int kEveryStepUpTo = 20;      // with this few steps, line mode reports every one
constexpr int kLineBuckets = 20;        // otherwise one line per 1/20 (5 %) of the work
constexpr double kRedrawSeconds = 0.2;  // a bar is redrawn at most this often unless its percentage moved

}  // namespace

ProgressReporter::ProgressReporter(std::string step, std::string unit, std::FILE* stream, Style style)
    : step_(std::move(step)),
      unit_(std::move(unit)),
      stream_(stream),
      bar_(style == Style::kBar || (style == Style::kAuto && isatty(fileno(stream)) != 0)),
      start_(std::chrono::steady_clock::now()) {}

ProgressReporter::~ProgressReporter() { endBar(); }

void ProgressReporter::endBar() {
  if (!barOpen_) return;
  std::fputc('\n', stream_);
  std::fflush(stream_);
  barOpen_ = false;
}

void ProgressReporter::note(const std::string& text) {
  endBar();
  std::fprintf(stream_, "%s: %s\n", step_.c_str(), text.c_str());
  std::fflush(stream_);
}

void ProgressReporter::update(int done, int total) {
  if (finished_ || done == lastDone_) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const bool last = done >= total;
  const int percent = total > 0 ? static_cast<int>(100LL * done / total) : 100;
  // ", 480 swings/s, 25 s left" once there is a rate to extrapolate.
  std::string rate;
  if (rate_ && done > resumedFrom_ && elapsed > 0) {
    char buf[96];
    const double perSecond = (done - resumedFrom_) / elapsed;
    std::snprintf(buf, sizeof buf, ", %.0f %s/s, %.0f s left", perSecond, unit_.c_str(), (total - done) / perSecond);
    rate = buf;
  }
  if (bar_) {
    if (!last && percent == lastBucket_ && elapsed - lastDrawn_ < kRedrawSeconds) return;
    const int filled = total > 0 ? static_cast<int>(static_cast<long long>(kBarWidth) * done / total) : kBarWidth;
    std::fprintf(stream_, "\r%s [%s%s] %d/%d %s (%d %%), %.1f s%s", step_.c_str(), std::string(filled, '#').c_str(),
                 std::string(kBarWidth - filled, ' ').c_str(), done, total, unit_.c_str(), percent, elapsed,
                 (rate + (rate_ ? "    " : "")).c_str());  // blanks over a longer previous rate
    barOpen_ = true;
    lastBucket_ = percent;
    lastDrawn_ = elapsed;
    if (last) endBar();
  } else {
    const int bucket = total > 0 ? static_cast<int>(static_cast<long long>(kLineBuckets) * done / total) : kLineBuckets;
    if (total > kEveryStepUpTo && bucket == lastBucket_ && !last) return;
    std::fprintf(stream_, "%s: %d/%d %s (%d %%), %.1f s%s\n", step_.c_str(), done, total, unit_.c_str(), percent,
                 elapsed, rate.c_str());
    lastBucket_ = bucket;
  }
  std::fflush(stream_);
  lastDone_ = done;
  finished_ = last;
}

}  // namespace swingsim
