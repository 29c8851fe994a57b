#pragma once
// printf-style formatting of a few values into a std::string, for reports and messages
// ("%.3f", "%+.0f ms"); at most 511 characters (longer output is cut).
#include <cstdio>
#include <string>

namespace swingsim {

template <class... Args>
std::string fmt(const char* format, Args... args) {
  char buf[512];
  std::snprintf(buf, sizeof buf, format, args...);
  return buf;
}

}  // namespace swingsim
