#include "numerics/metrics.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace swingsim {

ErrorMetrics calcErrorMetrics(const std::vector<double>& measured, const std::vector<double>& predicted) {
  return calcErrorMetrics(measured, predicted, std::vector<bool>(measured.size(), true));
}

ErrorMetrics calcErrorMetrics(const std::vector<double>& measured, const std::vector<double>& predicted,
                              const std::vector<bool>& mask) {
  if (measured.size() != predicted.size() || mask.size() != measured.size())
    throw std::invalid_argument("calcErrorMetrics: measured, predicted and mask differ in length");
  if (measured.empty()) throw std::invalid_argument("calcErrorMetrics: no samples");
  ErrorMetrics m;
  double sum = 0, sumRes2 = 0;
  for (std::size_t i = 0; i < measured.size(); ++i) {
    if (!mask[i]) continue;
    const double e = measured[i] - predicted[i];
    ++m.count;
    sum += measured[i];
    sumRes2 += e * e;
    m.bias += e;
    if (std::fabs(e) > m.maxError) {
      m.maxError = std::fabs(e);
      m.maxErrorIndex = i;
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (m.count == 0) return {nan, nan, nan, nan, 0, 0};
  const double n = static_cast<double>(m.count), mean = sum / n;
  double ssTot = 0;
  for (std::size_t i = 0; i < measured.size(); ++i) {
    if (mask[i]) ssTot += (measured[i] - mean) * (measured[i] - mean);
  }
  m.rmse = std::sqrt(sumRes2 / n);
  m.bias /= n;
  m.r2 = ssTot > 0 ? 1.0 - sumRes2 / ssTot : nan;
  return m;
}

double calcRms(const std::vector<double>& errors) {
  if (errors.empty()) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0;
  for (double e : errors) sum += e * e;
  return std::sqrt(sum / static_cast<double>(errors.size()));
}

}  // namespace swingsim
