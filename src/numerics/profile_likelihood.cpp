#include "numerics/profile_likelihood.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <stdexcept>

#include "numerics/residual_analysis.h"

namespace swingsim {

namespace {

// chi^2(1) 95 % quantile: the LR cut of a 95 % interval of one parameter.
const double kChi2One95 = calcChiSquaredQuantile(0.95, 1);

// One side of the interval: direction +1 (upper) or -1 (lower).
double searchSide(const ProfileRssFunction& rssAt, double value, double rssBest, double nEff, double bound, double step,
                  int direction, int bisections, bool& atBound, int& evaluations) {
  const auto inside = [&](double v) {
    ++evaluations;
    try {
      const double rss = rssAt(v);
      return std::isfinite(rss) && nEff * std::log(std::max(rss, 1e-300) / std::max(rssBest, 1e-300)) <= kChi2One95;
    } catch (const std::exception&) {
      return false;
    }
  };
  atBound = false;
  double in = value, d = step;
  for (;;) {
    const double trial = direction > 0 ? std::min(value + d, bound) : std::max(value - d, bound);
    if (trial == in) {  // already at the bound
      atBound = true;
      return in;
    }
    if (!inside(trial)) {
      double out = trial;
      for (int b = 0; b < bisections; ++b) {
        const double mid = 0.5 * (in + out);
        (inside(mid) ? in : out) = mid;
      }
      return 0.5 * (in + out);
    }
    in = trial;
    if (trial == bound) {
      atBound = true;
      return bound;
    }
    d *= 2;
  }
}

}  // namespace

ProfileInterval calcProfileInterval(const ProfileRssFunction& rssAt, double value, double rssBest, double nEff,
                                    double boundLower, double boundUpper, double step, int bisections) {
  if (!(step > 0)) throw std::invalid_argument("calcProfileInterval: step must be > 0");
  if (!(nEff > 0)) throw std::invalid_argument("calcProfileInterval: nEff must be > 0");
  ProfileInterval out;
  const double v = std::clamp(value, boundLower, boundUpper);
  out.lower = searchSide(rssAt, v, rssBest, nEff, boundLower, step, -1, bisections, out.lowerAtBound, out.evaluations);
  out.upper = searchSide(rssAt, v, rssBest, nEff, boundUpper, step, +1, bisections, out.upperAtBound, out.evaluations);
  return out;
}

}  // namespace swingsim
