#include "cli/command_registry.h"

#include <cmath>
#include <cstdlib>

namespace swingsim::cli {

std::map<std::string, Command>& commandRegistry() {
  static std::map<std::string, Command> registry;
  return registry;
}

std::string Arguments::get(const std::string& flag, const std::string& defaultValue) const {
  auto it = values_.find(flag);
  return it == values_.end() ? defaultValue : it->second;
}

double Arguments::getDouble(const std::string& flag, double defaultValue) const {
  if (!has(flag)) return defaultValue;
  const std::string s = get(flag);
  char* end = nullptr;
  double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v))
    throw UsageError(flag + ": expected a number (got '" + s + "')");
  return v;
}

int Arguments::getInt(const std::string& flag, int defaultValue) const {
  double v = getDouble(flag, defaultValue);
  if (v != std::floor(v) || std::fabs(v) > 1e9) throw UsageError(flag + ": expected a whole number (got '" + get(flag) + "')");
  return static_cast<int>(v);
}

std::string Arguments::commandLine(const std::string& name) const {
  std::string out = "swingsim " + name;
  for (const auto& p : positional_) out += " " + p;
  for (const auto& [flag, value] : values_) out += " " + flag + (value.empty() ? "" : " " + value);
  return out;
}

}  // namespace swingsim::cli
