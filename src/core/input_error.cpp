#include "core/input_error.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace swingsim {

std::string formatNumber(double value) {
  char buf[64];
  for (int precision = 6; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, value);
    if (std::strtod(buf, nullptr) == value) break;
  }
  return buf;
}

std::string formatSeconds(double seconds) { return formatNumber(std::round(seconds * 1e4) / 1e4); }

}  // namespace swingsim
