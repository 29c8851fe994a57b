#pragma once
// Value, first and second derivative of a noisy sampled signal by a local polynomial
// least-squares fit (Savitzky and Golay 1964, on an uneven time grid), with the gain by which
// white noise on the samples reaches each estimate: a smoother whose noise propagates into a
// band (identify/missing_moment.h uses it for the knee's acceleration).
#include <vector>

namespace swingsim {

/// The smoothed signal and its derivatives at every sample, NaN where the window does not fit
/// inside the record (the first and last `halfWindow` seconds) or holds fewer than degree + 2
/// samples (a sparse record).
struct LocalPolynomialFit {
  std::vector<double> value, rate, acceleration;
  /// Standard deviation of the acceleration per unit standard deviation of white noise on the
  /// samples: sd(acceleration[i]) = noise * accelerationGain[i].
  std::vector<double> accelerationGain;
  /// acceleration[i] = sum over k of accelerationWeights[i][k] * values[windowStart[i] + k]:
  /// the filter itself, so the noise of any linear combination of the estimates (a mean over
  /// many samples, whose windows overlap) can be found exactly.
  std::vector<std::size_t> windowStart;
  std::vector<std::vector<double>> accelerationWeights;
};

/// Fits a polynomial of `degree` (2 or more) to the samples within `halfWindow` s of each
/// sample. Throws std::invalid_argument if time and values differ in length or the degree is
/// below 2.
LocalPolynomialFit fitLocalPolynomial(const std::vector<double>& time, const std::vector<double>& values,
                                      double halfWindow, int degree = 3);

}  // namespace swingsim
