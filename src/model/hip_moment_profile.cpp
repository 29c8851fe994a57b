#include "model/hip_moment_profile.h"
#include "core/units.h"

#include "numerics/monotone_cubic.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace swingsim {

namespace {}  // namespace

double HipMomentProfile::calcMoment(double time) const {
  const double t = time / timeScale;
  const double gain = 1.0 / (timeScale * timeScale);
  if (kind == Kind::kTable) return gain * interpolateMonotoneCubic(times, moments, t, MonotoneCubicEnds::kSecant);
  if (t < 0) return 0;
  if (t < flexionDuration) return gain * flexionAmplitude * std::sin(kPi * t / flexionDuration);
  const double te = t - flexionDuration;
  if (te < extensionDuration) return -gain * extensionAmplitude * std::sin(kPi * te / extensionDuration);
  return 0;
}

std::vector<double> HipMomentProfile::calcBreakpoints() const {
  std::vector<double> t;
  if (kind == Kind::kTable) {
    if (!times.empty()) t = {times.front(), times.back()};
  } else {
    t = {flexionDuration, flexionDuration + extensionDuration};
  }
  std::vector<double> scaled;
  for (double v : t)
    if (v * timeScale > 0) scaled.push_back(v * timeScale);
  return scaled;
}

std::pair<double, double> HipMomentProfile::calcRangeFrom(double time) const {
  const double now = calcMoment(time);
  double low = now, high = now;
  const auto include = [&](double m) {
    low = std::min(low, m);
    high = std::max(high, m);
  };
  const double t = time / timeScale;
  const double gain = 1.0 / (timeScale * timeScale);
  if (kind == Kind::kTable) {
    for (std::size_t i = 0; i < times.size(); ++i)
      if (times[i] > t) include(gain * moments[i]);
    if (!moments.empty()) include(gain * moments.back());
    return {low, high};
  }
  include(0.0);  // the end, and the switch between the half-sines
  if (t < 0.5 * flexionDuration) include(gain * flexionAmplitude);
  if (t < flexionDuration + 0.5 * extensionDuration) include(-gain * extensionAmplitude);
  return {low, high};
}

void HipMomentProfile::validate() const {
  if (!(timeScale > 0) || !std::isfinite(timeScale)) throw std::invalid_argument("time_scale must be positive");
  if (kind == Kind::kTable) {
    if (times.size() < 2 || times.size() != moments.size())
      throw std::invalid_argument("table needs at least 2 times and one moment per time");
    for (std::size_t i = 1; i < times.size(); ++i)
      if (!(times[i] > times[i - 1])) throw std::invalid_argument("times must strictly increase");
    return;
  }
  if (!(flexionDuration > 0) || !(extensionDuration > 0)) throw std::invalid_argument("durations must be positive");
  if (!(flexionAmplitude >= 0) || !(extensionAmplitude >= 0))
    throw std::invalid_argument("amplitudes must not be negative");
}

std::string HipMomentProfile::describe() const {
  char buf[256];
  if (kind == Kind::kTable) {
    std::snprintf(buf, sizeof buf, "table of %zu samples (monotone cubic), time scale %.4f", times.size(), timeScale);
  } else {
    std::snprintf(buf, sizeof buf,
                  "biphasic sine: flexion %.1f N m for %.3f s, then extension %.1f N m for %.3f s, time scale %.4f",
                  flexionAmplitude, flexionDuration, extensionAmplitude, extensionDuration, timeScale);
  }
  return buf;
}

}  // namespace swingsim
