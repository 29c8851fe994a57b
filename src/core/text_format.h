#pragma once
// printf-style formatting of a few values into a std::string, for reports and messages
// ("%.3f", "%+.0f ms"); at most 511 characters (longer output is cut). An absent value
// prints as "none".
#include <cstdio>
#include <optional>
#include <string>

namespace swingsim {

template <class... Args>
std::string fmt(const char* format, Args... args) {
  char buf[512];
  std::snprintf(buf, sizeof buf, format, args...);
  return buf;
}

/// `value` times `scale` (a unit conversion) printed with the one-number `format`, or "none"
/// if it is absent: a quantity that does not exist is "none", never a marker number.
inline std::string fmtOrNone(const char* format, const std::optional<double>& value, double scale = 1) {
  return value ? fmt(format, *value * scale) : "none";
}

}  // namespace swingsim
