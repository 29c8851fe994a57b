#include "identify/missing_moment.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/text_format.h"
#include "core/units.h"
#include "identify/missing_force.h"
#include "numerics/local_polynomial.h"
#include "numerics/noise_estimate.h"
#include "swing/reference_swing.h"

namespace swingsim {

namespace {

// The smoother's half window, s: a cubic over 160 ms of the measured minus the model's own
// swing (whose curvature is small). Chosen on the independent generator's swings (0.5 deg
// noise, 500 Hz; tests/identify/missing_moment_test.cpp): at 65 ms a 20 N m/rad stiffening
// beyond 55 deg stays inside its band; at 100 ms a cushion acting below 20 deg spreads to
// 50 deg; at 80 ms both are placed within 5 deg and three nulls show no region.
constexpr double kHalfWindowS = 0.08;
constexpr double kStopMarginRad = 2.0 * kDegToRad;  // samples whose window comes this near extension are left out
constexpr double kBinDeg = 5.0;

// A bin's samples and, for its mean's noise, the weight each raw sample (record, row) has in
// the sum of its missing moments through the two accelerations: the windows overlap, so the
// mean's noise is found from the filter itself, not from a count of samples.
struct Bin {
  double sum = 0;
  int n = 0;
  double kneeLow = 1e9, kneeHigh = -1e9, rateLow = 1e9, rateHigh = -1e9;
  std::map<std::pair<std::size_t, std::size_t>, double> kneeWeight, hipWeight;
  double variance(const std::vector<double>& kneeNoise, const std::vector<double>& hipNoise) const {
    double v = 0;
    for (const auto& [at, w] : kneeWeight) v += w * w * kneeNoise[at.first] * kneeNoise[at.first];
    for (const auto& [at, w] : hipWeight) v += w * w * hipNoise[at.first] * hipNoise[at.first];
    return v / (static_cast<double>(n) * n);
  }
};

// Regions: runs of neighbouring bins (same direction of motion) whose means depart from zero
// with one sign; the largest (moment x samples) first.
std::vector<MissingMomentRegion> findRegions(const std::map<std::pair<bool, int>, Bin>& bins,
                                             const std::vector<double>& kneeNoises,
                                             const std::vector<double>& hipNoises) {
  std::vector<MissingMomentRegion> regions;
  MissingMomentRegion* open = nullptr;
  int lastIndex = 0, lastSign = 0;
  bool lastExtending = false;
  for (const auto& [key, b] : bins) {
    if (b.n < kMissingRegionMinSamples) continue;
    const double mean = b.sum / b.n;
    const double se = std::sqrt(b.variance(kneeNoises, hipNoises));
    const int sign = std::abs(mean) > kMissingRegionZ * se ? (mean > 0 ? 1 : -1) : 0;
    if (sign == 0) {
      open = nullptr;
      continue;
    }
    if (open && key.first == lastExtending && key.second == lastIndex + 1 && sign == lastSign) {
      open->moment = (open->moment * open->samples + b.sum) / (open->samples + b.n);
      open->samples += b.n;
      open->low = std::min(open->low, mean);
      open->high = std::max(open->high, mean);
      open->kneeLowDeg = std::min(open->kneeLowDeg, b.kneeLow);
      open->kneeHighDeg = std::max(open->kneeHighDeg, b.kneeHigh);
      open->rateLowDegS = std::min(open->rateLowDegS, b.rateLow);
      open->rateHighDegS = std::max(open->rateHighDegS, b.rateHigh);
    } else {
      regions.push_back({key.first, mean, mean, mean, b.kneeLow, b.kneeHigh, b.rateLow, b.rateHigh, b.n});
      open = &regions.back();
    }
    lastIndex = key.second;
    lastSign = sign;
    lastExtending = key.first;
  }
  std::sort(regions.begin(), regions.end(), [](const MissingMomentRegion& a, const MissingMomentRegion& b) {
    return std::abs(a.moment) * a.samples > std::abs(b.moment) * b.samples;
  });
  return regions;
}

// The measured signal smoothed as reference + smooth(measured - reference); the filter
// weights (the noise's path) are those of the smoother alone.
LocalPolynomialFit smoothAround(const std::vector<double>& time, const std::vector<double>& measured,
                                const std::vector<double>* reference, double halfWindow, int degree) {
  if (!reference || reference->size() != measured.size()) return fitLocalPolynomial(time, measured, halfWindow, degree);
  std::vector<double> residual(measured.size());
  for (std::size_t i = 0; i < measured.size(); ++i) residual[i] = measured[i] - (*reference)[i];
  LocalPolynomialFit f = fitLocalPolynomial(time, residual, halfWindow, degree);
  const std::vector<double>& q = *reference;
  for (std::size_t i = 1; i + 1 < q.size(); ++i) {
    if (!std::isfinite(f.value[i])) continue;
    const double h0 = time[i] - time[i - 1], h1 = time[i + 1] - time[i];
    const double rate = (q[i + 1] - q[i - 1]) / (h0 + h1);
    const double acc = 2.0 * ((q[i + 1] - q[i]) / h1 - (q[i] - q[i - 1]) / h0) / (h0 + h1);
    f.value[i] += q[i];
    f.rate[i] += rate;
    f.acceleration[i] += acc;
  }
  return f;
}

}  // namespace

std::string MissingMomentRegion::describe() const {
  const bool resists = extending ? moment > 0 : moment < 0;
  const std::string motion = extending ? "extension" : "flexion";
  return "missing moment: " + fmt("%+.2g", moment) + " N m (" + fmt("%.2g", low) + " to " + fmt("%.2g", high) + ") " +
         (resists ? "resisting " : "assisting ") + motion + " at knee " + fmt("%.0f", kneeLowDeg) + "-" +
         fmt("%.0f", kneeHighDeg) + " deg while " + (extending ? "extending" : "flexing") + " (" +
         fmt("%.0f", rateLowDegS) + " to " + fmt("%.0f", rateHighDegS) + " deg/s)";
}

MissingMoment calcMissingMoment(const SwingBase& base, const SwingModelParams& params,
                                const std::vector<SwingRecord>& records,
                                const std::vector<SwingPrediction>& references) {
  MissingMoment out;
  const KneeLawSum law = makeSwingKneeLaw(base, params);
  if (law.numStates() > 0) {
    out.note = "not computed: the knee law carries states of its own (" + law.name() + ")";
    return out;
  }
  const LegGeometry g = calcLegGeometry(applyParticipantEffects(base.participant, params.effects), 0.0);
  if (g.socket) {
    out.note =
        "not computed: the leg has a compliant socket (the knee moment a measured motion needs is taken on a "
        "rigid thigh)";
    return out;
  }
  std::map<std::pair<bool, int>, Bin> bins;
  bool pelvis = false;
  std::vector<double> hipNoises, kneeNoises;
  for (std::size_t rec = 0; rec < records.size(); ++rec) {
    const SwingRecord& r = records[rec];
    hipNoises.push_back(0);
    kneeNoises.push_back(0);
    if (r.time.size() < 10) continue;
    pelvis = pelvis || !r.pelvisTilt.empty();
    const SwingPrediction* ref = rec < references.size() ? &references[rec] : nullptr;
    const LocalPolynomialFit hip =
        smoothAround(r.time, r.hipFlexion, ref ? &ref->hipFlexion : nullptr, kHalfWindowS, 3);
    const LocalPolynomialFit knee =
        smoothAround(r.time, r.kneeFlexion, ref ? &ref->kneeFlexion : nullptr, kHalfWindowS, 3);
    const double hipNoise = estimateNoise(r.time, r.hipFlexion).sigma,
                 kneeNoise = estimateNoise(r.time, r.kneeFlexion).sigma;
    hipNoises.back() = hipNoise;
    kneeNoises.back() = kneeNoise;
    for (std::size_t i = 0; i < r.time.size(); ++i) {
      if (!std::isfinite(knee.acceleration[i]) || !std::isfinite(hip.acceleration[i])) continue;
      // The smoother's own window: left out if any of its samples is near the stop.
      const auto from = r.kneeFlexion.begin() + static_cast<std::ptrdiff_t>(knee.windowStart[i]);
      const auto to = from + static_cast<std::ptrdiff_t>(knee.accelerationWeights[i].size());
      if (std::any_of(from, to, [](double q) { return q < kStopMarginRad; })) continue;
      const KneeMomentNeeded need =
          calcKneeMomentNeeded(g, hip.value[i], hip.rate[i], hip.acceleration[i], knee.value[i], knee.acceleration[i]);
      const double applied =
          law.calcMoment({knee.value[i], knee.rate[i], hip.value[i], hip.rate[i], r.time[i] - r.time.front()}, nullptr);
      const double sd = std::hypot(need.perHipAcceleration * hip.accelerationGain[i] * hipNoise,
                                   need.perKneeAcceleration * knee.accelerationGain[i] * kneeNoise);
      const double kneeDeg = knee.value[i] * kRadToDeg, rateDegS = knee.rate[i] * kRadToDeg;
      out.kneeDeg.push_back(kneeDeg);
      out.kneeRateDegS.push_back(rateDegS);
      out.momentNm.push_back(need.moment - applied);
      out.bandNm.push_back(1.96 * sd);
      Bin& b = bins[{rateDegS < 0, static_cast<int>(std::floor(kneeDeg / kBinDeg))}];
      b.sum += need.moment - applied;
      ++b.n;
      for (std::size_t k = 0; k < knee.accelerationWeights[i].size(); ++k)
        b.kneeWeight[{rec, knee.windowStart[i] + k}] += need.perKneeAcceleration * knee.accelerationWeights[i][k];
      for (std::size_t k = 0; k < hip.accelerationWeights[i].size(); ++k)
        b.hipWeight[{rec, hip.windowStart[i] + k}] += need.perHipAcceleration * hip.accelerationWeights[i][k];
      b.kneeLow = std::min(b.kneeLow, kneeDeg);
      b.kneeHigh = std::max(b.kneeHigh, kneeDeg);
      b.rateLow = std::min(b.rateLow, rateDegS);
      b.rateHigh = std::max(b.rateHigh, rateDegS);
    }
  }
  out.regions = findRegions(bins, kneeNoises, hipNoises);
  if (pelvis && base.drive == SwingDrive::kThighKinematics && base.movingHip)
    out.note = "the hip is taken as fixed (the measured pelvis's accelerations are left out)";
  return out;
}

std::string describeMissingMoment(const MissingMoment& missing) {
  if (!missing.note.empty() && missing.kneeDeg.empty()) return "missing moment " + missing.note;
  if (missing.regions.empty())
    return "missing moment: none departs from zero beyond its noise band (" + std::to_string(missing.kneeDeg.size()) +
           " samples)";
  std::string out;
  for (const auto& r : missing.regions) out += (out.empty() ? "" : "; ") + r.describe();
  return out;
}

}  // namespace swingsim
