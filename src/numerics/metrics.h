#pragma once
// Agreement between measured and predicted series, as in Chien 2014 Table 2: maximum
// absolute error (ME), root-mean-square error (RMSE) and coefficient of determination R^2.
#include <cstddef>
#include <vector>

namespace swingsim {

struct ErrorMetrics {
  double maxError = 0;  ///< ME: max |measured - predicted|, units of the data
  double rmse = 0;      ///< sqrt(mean((measured - predicted)^2)), units of the data
  /// 1 - SS_res / SS_tot (a fraction; Table 2 prints it in %). NaN if the measured series
  /// is constant (SS_tot = 0). Negative when the prediction is worse than the mean.
  double r2 = 0;
  double bias = 0;  ///< mean(measured - predicted)
  std::size_t count = 0;
  std::size_t maxErrorIndex = 0;  ///< sample where ME occurs
};

/// Metrics over all samples. Throws std::invalid_argument if the series differ in length
/// or are empty.
ErrorMetrics calcErrorMetrics(const std::vector<double>& measured, const std::vector<double>& predicted);

/// Metrics over the samples where `mask` is true (per-phase metrics). Count 0 and NaN
/// values if no sample is selected.
ErrorMetrics calcErrorMetrics(const std::vector<double>& measured, const std::vector<double>& predicted,
                              const std::vector<bool>& mask);

/// The median of a series (the upper of the two middle values for an even count); NaN if it
/// is empty.
double calcMedian(std::vector<double> values);

/// Root mean square of a series of errors (residuals); NaN if it is empty.
double calcRms(const std::vector<double>& errors);

/// Pearson's correlation coefficient of two series over their common length; NaN if fewer
/// than 2 samples or either is constant.
double calcCorrelation(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace swingsim
