#include "numerics/step_error.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace swingsim {

void checkStepTolerances(const char* method, double relTol, double absTol) {
  if (!(relTol > 0) || !(absTol > 0) || !std::isfinite(relTol) || !std::isfinite(absTol))
    throw std::invalid_argument(std::string(method) + ": tolerances must be positive and finite");
}

double calcStepErrorNorm(const std::vector<double>& y0, const std::vector<double>& y1, const std::vector<double>& err,
                         double relTol, double absTol) {
  const int n = static_cast<int>(err.size());
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double sk = absTol + relTol * std::max(std::abs(y0[i]), std::abs(y1[i]));
    sum += (err[i] / sk) * (err[i] / sk);
  }
  return std::sqrt(sum / n);
}

}  // namespace swingsim
