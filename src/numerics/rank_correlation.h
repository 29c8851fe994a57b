#pragma once
// Spearman's rank correlation with a confidence interval: which property of a cohort's
// participants predicts an outcome (docs/cohort.md). Ties take their average rank; the
// interval is Fisher's z transform with the standard error 1.06 / sqrt(n - 3) that Fieller,
// Hartley & Pearson (1957, Biometrika 44:470) give for Spearman's rho (valid for |rho| < 0.8
// and n >= 10; the report says how many values it rests on).
#include <vector>

namespace swingsim {

/// Ranks 1..n of `values`, ties sharing their average rank.
std::vector<double> calcAverageRanks(const std::vector<double>& values);

struct RankCorrelation {
  double rho = 0;            ///< Spearman's rho in [-1, 1]; NaN if undefined (a constant variable, n < 3)
  double low = 0, high = 0;  ///< the interval at the confidence asked; NaN where rho is NaN or n < 4
  int count = 0;             ///< pairs with both values finite
};

/// Spearman's rho of the pairs (x[i], y[i]) where both are finite, with a Fisher-z interval
/// at `confidence` (0 < confidence < 1, e.g. 0.95). Throws std::invalid_argument if the
/// sizes differ or `confidence` is outside (0, 1).
RankCorrelation calcSpearman(const std::vector<double>& x, const std::vector<double>& y, double confidence = 0.95);

}  // namespace swingsim
