#include "identify/missing_force.h"

#include "core/text_format.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace swingsim {

namespace {

constexpr double kBinMm = kMissingForceBinMm;
struct Bin {
  double sum = 0, variance = 0;  // sum of residuals, N; sum of their noise variances, N^2
  int n = 0;
  double xLow = 1e9, xHigh = -1e9, vLow = 1e9, vHigh = -1e9;  // mm, mm/s
};

void extend(MissingForceRegion& r, const Bin& b, double mean) {
  r.force = (r.force * r.samples + b.sum) / (r.samples + b.n);
  r.samples += b.n;
  r.low = std::min(r.low, mean);
  r.high = std::max(r.high, mean);
  r.positionLowMm = std::min(r.positionLowMm, b.xLow);
  r.positionHighMm = std::max(r.positionHighMm, b.xHigh);
  r.speedLowMmS = std::min(r.speedLowMmS, b.vLow);
  r.speedHighMmS = std::max(r.speedHighMmS, b.vHigh);
}

}  // namespace

std::string MissingForceRegion::describe() const {
  const bool resists = extending ? force < 0 : force > 0;
  const std::string motion = extending ? "extension" : "compression";
  return "missing force: " + fmt("%+.2g", force) + " N (" + fmt("%.2g", low) + " to " + fmt("%.2g", high) + ") " +
         (resists ? "resisting " : "assisting ") + motion + " at piston " + fmt("%.0f", positionLowMm) + "-" +
         fmt("%.0f", positionHighMm) + " mm while " + (extending ? "extending" : "compressing") + " (" +
         fmt("%.0f", speedLowMmS) + " to " + fmt("%.0f", speedHighMmS) + " mm/s)";
}

MissingForce calcMissingForce(const MauchCylinderParams& params, const std::vector<BenchData>& records,
                              const std::vector<double>& noise) {
  if (noise.size() != records.size()) throw std::invalid_argument("calcMissingForce: one noise per record");
  const MauchCylinder cylinder(params);
  MissingForce out;
  std::map<std::pair<bool, int>, Bin> bins;  // (extending, position bin)
  for (std::size_t r = 0; r < records.size(); ++r) {
    const BenchData& d = records[r];
    const CylinderTrace trace = calcCylinderTrace(cylinder, d.time, d.position, d.velocity, 0.0);
    for (std::size_t i = 0; i < d.force.size(); ++i) {
      const double x = d.position[i] * 1e3, v = d.velocity[i] * 1e3;
      Bin& b = bins[{v < 0, static_cast<int>(std::floor(x / kBinMm))}];
      b.sum += d.force[i] - trace.force[i];
      out.positionMm.push_back(x);
      out.speedMmS.push_back(v);
      out.forceN.push_back(d.force[i] - trace.force[i]);
      out.noiseN.push_back(noise[r]);
      b.variance += noise[r] * noise[r];
      ++b.n;
      b.xLow = std::min(b.xLow, x);
      b.xHigh = std::max(b.xHigh, x);
      b.vLow = std::min(b.vLow, v);
      b.vHigh = std::max(b.vHigh, v);
    }
  }
  // Runs of neighbouring bins (one direction) whose means depart from zero with one sign.
  std::vector<MissingForceRegion>& regions = out.regions;
  bool open = false;
  std::pair<bool, int> last{false, 0};
  int lastSign = 0;
  for (const auto& [key, b] : bins) {
    const double mean = b.n > 0 ? b.sum / b.n : 0.0;
    const double se = std::sqrt(b.variance) / std::max(b.n, 1);
    const int sign = b.n >= kMissingRegionMinSamples && std::abs(mean) > kMissingRegionZ * se ? (mean > 0 ? 1 : -1) : 0;
    if (sign != 0 && open && key.first == last.first && key.second == last.second + 1 && sign == lastSign) {
      extend(regions.back(), b, mean);
    } else if (sign != 0) {
      regions.push_back({key.first, mean, mean, mean, b.xLow, b.xHigh, b.vLow, b.vHigh, b.n});
    }
    open = sign != 0;
    last = key;
    lastSign = sign;
  }
  std::sort(regions.begin(), regions.end(), [](const MissingForceRegion& a, const MissingForceRegion& b) {
    return std::abs(a.force) * a.samples > std::abs(b.force) * b.samples;
  });
  return out;
}

std::string describeMissingForce(const std::vector<MissingForceRegion>& regions) {
  if (regions.empty()) return "missing force: none departs from zero beyond its noise";
  constexpr std::size_t kShown = 3;  // the largest; a line a user reads
  std::string out;
  for (std::size_t i = 0; i < regions.size() && i < kShown; ++i)
    out += (out.empty() ? "" : "; ") + regions[i].describe();
  if (regions.size() > kShown) out += " (and " + std::to_string(regions.size() - kShown) + " smaller regions)";
  return out;
}

}  // namespace swingsim
