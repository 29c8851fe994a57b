#include "knee/bench_profile.h"
#include "core/units.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/input_error.h"

namespace swingsim {

namespace {

// Periodic Catmull-Rom through the stride's frames, s in [0, 1).
double interpolate(const std::vector<double>& v, double s) {
  const int n = static_cast<int>(v.size());
  double u = s * n;
  u -= n * std::floor(u / n);
  const int i = static_cast<int>(std::floor(u));
  const double t = u - i;
  auto at = [&](int k) { return v[static_cast<std::size_t>(((k % n) + n) % n)]; };
  const double p0 = at(i - 1), p1 = at(i), p2 = at(i + 1), p3 = at(i + 2);
  return 0.5 * ((2 * p1) + (-p0 + p2) * t + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t * t +
                (-p0 + 3 * p1 - 3 * p2 + p3) * t * t * t);
}

// Landmarks of the (scaled, shifted) stride, found on a fine grid: stance peak (first 30 %),
// stance minimum (between the stance peak and 60 %), swing peak (after the stance minimum).
struct Landmarks {
  double stancePeakS, stancePeak, stanceMinS, stanceMin, swingPeakS, swingPeak;
};

constexpr int kGrid = 4000;

// The first grid index in [first, last) (first < last) where sign * f(s) is largest.
template <class F>
int findExtreme(const F& f, int first, int last, double sign) {
  int best = first;
  for (int i = first + 1; i < last; ++i)
    if (sign * f(static_cast<double>(i) / kGrid) > sign * f(static_cast<double>(best) / kGrid)) best = i;
  return best;
}

Landmarks findLandmarks(const std::vector<double>& v, double scale, double offset) {
  auto f = [&](double s) { return scale * interpolate(v, s) + offset; };
  // Grid ends of the windows: s < 0.3 and s < 0.6; each window below holds grid points.
  constexpr int kStanceEnd = static_cast<int>(0.3 * kGrid), kMinimumEnd = static_cast<int>(0.6 * kGrid);
  const int peak = findExtreme(f, 0, kStanceEnd, 1);
  const int minimum = findExtreme(f, peak + 1, kMinimumEnd, -1);
  const int swing = findExtreme(f, minimum + 1, kGrid, 1);
  auto at = [](int i) { return static_cast<double>(i) / kGrid; };
  return {at(peak), f(at(peak)), at(minimum), f(at(minimum)), at(swing), f(at(swing))};
}

double calcOffset(const std::vector<double>& v, double scale, double target) {
  auto f = [&](double s) { return scale * interpolate(v, s); };
  return target - f(static_cast<double>(findExtreme(f, 0, kGrid, -1)) / kGrid);
}

}  // namespace

namespace {

double modifiedFlexion(const std::vector<double>& v, const BenchProfileParams& p, double offset, const Landmarks& m,
                       double s) {
  s -= std::floor(s);
  double th = p.amplitudeScale * interpolate(v, s) + offset;
  // Stretch stance extension and pre-swing flexion so the stance minimum reaches the
  // hyperextension angle while the stance and swing peak angles stay where they were.
  if (s >= m.stancePeakS && s <= m.stanceMinS) {
    th = m.stancePeak - (m.stancePeak - th) * (m.stancePeak - p.hyperextension) / (m.stancePeak - m.stanceMin);
  } else if (s > m.stanceMinS && s <= m.swingPeakS) {
    th = m.swingPeak - (m.swingPeak - th) * (m.swingPeak - p.hyperextension) / (m.swingPeak - m.stanceMin);
  }
  return th;
}

}  // namespace

double calcModifiedFlexion(const KneeAngleStride& stride, const BenchProfileParams& p, double s) {
  const double offset = calcOffset(stride.flexion, p.amplitudeScale, p.terminalSwingMinimum);
  return modifiedFlexion(stride.flexion, p, offset, findLandmarks(stride.flexion, p.amplitudeScale, offset), s);
}

BenchProfile makeBenchProfile(const KneeAngleStride& stride, const BenchProfileParams& p,
                              const KneeGeometry& geometry) {
  if (!(p.strideTime > 0) || !(p.amplitudeScale > 0) || !(p.sampleRate > 0) || p.cycles < 1 || p.holdSamples < 0)
    throw std::invalid_argument(
        "makeBenchProfile: stride time, amplitude scale, sample rate and cycles must be positive");
  if (stride.flexion.size() < 8) throw std::invalid_argument("makeBenchProfile: stride has too few frames");
  const double offset = calcOffset(stride.flexion, p.amplitudeScale, p.terminalSwingMinimum);
  const Landmarks m = findLandmarks(stride.flexion, p.amplitudeScale, offset);
  if (!(p.hyperextension < m.stanceMin))
    throw std::invalid_argument("makeBenchProfile: the hyperextension angle must lie below the stance minimum");

  BenchProfile out;
  const auto n = static_cast<std::size_t>(std::floor(p.cycles * p.strideTime * p.sampleRate));
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / p.sampleRate;
    out.time.push_back(t);
    out.flexion.push_back(modifiedFlexion(stride.flexion, p, offset, m, t / p.strideTime));
  }
  // Hold: the sample nearest each cycle's minimum and `holdSamples` either side of it.
  for (int c = 0; c < p.cycles; ++c) {
    const double tMin = (c + m.stanceMinS) * p.strideTime;
    const long centre = std::lround(tMin * p.sampleRate);
    for (long j = centre - p.holdSamples; j <= centre + p.holdSamples; ++j) {
      if (j >= 0 && j < static_cast<long>(n)) out.flexion[static_cast<std::size_t>(j)] = p.hyperextension;
    }
  }
  for (double th : out.flexion) out.position.push_back(geometry.calcPistonPosition(th));
  return out;
}

}  // namespace swingsim
