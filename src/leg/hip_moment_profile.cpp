#include "leg/hip_moment_profile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace swingsim {

namespace {
constexpr double kPiLocal = 3.14159265358979323846;

// Fritsch-Carlson monotone cubic: no overshoot between dynamometer samples.
double interpolateMonotone(const std::vector<double>& x, const std::vector<double>& y, double t) {
  const std::size_t n = x.size();
  if (t <= x.front()) return y.front();
  if (t >= x.back()) return y.back();
  std::size_t i = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), t) - x.begin()) - 1;
  auto secant = [&](std::size_t k) { return (y[k + 1] - y[k]) / (x[k + 1] - x[k]); };
  auto tangent = [&](std::size_t k) {
    if (k == 0) return secant(0);
    if (k == n - 1) return secant(n - 2);
    double a = secant(k - 1), b = secant(k);
    if (a * b <= 0) return 0.0;
    return 3 * (a + b) / ((2 * b + a) / a + (b + 2 * a) / b);  // weighted harmonic mean
  };
  const double h = x[i + 1] - x[i];
  const double s = (t - x[i]) / h;
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
  const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
  return h00 * y[i] + h10 * h * tangent(i) + h01 * y[i + 1] + h11 * h * tangent(i + 1);
}
}  // namespace

double HipMomentProfile::calcMoment(double time) const {
  const double t = time / timeScale;
  const double gain = 1.0 / (timeScale * timeScale);
  if (kind == Kind::kTable) return gain * interpolateMonotone(times, moments, t);
  if (t < 0) return 0;
  if (t < flexionDuration) return gain * flexionAmplitude * std::sin(kPiLocal * t / flexionDuration);
  const double te = t - flexionDuration;
  if (te < extensionDuration) return -gain * extensionAmplitude * std::sin(kPiLocal * te / extensionDuration);
  return 0;
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
  if (!(flexionAmplitude >= 0) || !(extensionAmplitude >= 0)) throw std::invalid_argument("amplitudes must not be negative");
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
