#include "core/plausible_ranges.h"

#include <cmath>

#include "core/input_error.h"

namespace swingsim {

std::string checkPlausible(double value, const PlausibleRange& range, const std::string& what) {
  if (value >= range.lower && value <= range.upper) return "";
  // Lab software writes 9.9e37 (or similar) where a sample is missing.
  constexpr double kMissingMarker = 1e37;
  const std::string unit = *range.unit ? std::string(" ") + range.unit : std::string();
  return "expected " + what + " in [" + formatNumber(range.lower) + ", " + formatNumber(range.upper) + "]" + unit +
         " (" + range.reason + ")" +
         (std::fabs(value) >= kMissingMarker ? "; a value this large is usually a missing-data marker: remove the row "
                                               "or fill the gap"
                                             : "");
}

}  // namespace swingsim
