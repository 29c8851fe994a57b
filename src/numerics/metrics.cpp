#include "numerics/metrics.h"

#include <algorithm>
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

double calcCorrelation(const std::vector<double>& a, const std::vector<double>& b) {
  const std::size_t n = std::min(a.size(), b.size());
  if (n < 2) return std::numeric_limits<double>::quiet_NaN();
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < n; ++i) ma += a[i], mb += b[i];
  ma /= static_cast<double>(n);
  mb /= static_cast<double>(n);
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  if (saa <= 0 || sbb <= 0) return std::numeric_limits<double>::quiet_NaN();
  return sab / std::sqrt(saa * sbb);
}

double calcMedian(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

}  // namespace swingsim
