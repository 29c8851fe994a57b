#pragma once
// Profile-likelihood interval of one fitted parameter (Venzon & Moolgavkar 1988; Pawitan,
// In All Likelihood, Sec. 3.4): the values v at which the fit with the parameter held at v
// (every other parameter refitted) is not worse than the best fit by more than the chi^2(1)
// 95 % quantile, LR(v) = n_eff ln(RSS(v) / RSS_best) <= 3.84. Unlike the Wald interval
// value +- 1.96 se, it never leaves the parameter's physical bounds: where a bound cuts the
// region the interval is one-sided, ending at the bound.
#include <functional>

namespace swingsim {

/// The RSS of the fit with the parameter held at a value (others refitted). May throw
/// std::exception where the model cannot run; that value then counts as outside.
using ProfileRssFunction = std::function<double(double)>;

struct ProfileInterval {
  double lower = 0, upper = 0;
  bool lowerAtBound = false, upperAtBound = false;  ///< the bound cuts the region there
  int evaluations = 0;                              ///< refits done
};

/// The 95 % profile-likelihood interval around `value` (the best fit, RSS `rssBest`, inside
/// [boundLower, boundUpper]) with `nEff` effective samples. Each side is searched outward in
/// steps of `step`, doubled each time, until LR > 3.84 or the bound, then the crossing is
/// bisected `bisections` times. Throws std::invalid_argument if step <= 0 or nEff <= 0.
ProfileInterval calcProfileInterval(const ProfileRssFunction& rssAt, double value, double rssBest, double nEff,
                                    double boundLower, double boundUpper, double step, int bisections = 30);

}  // namespace swingsim
