#include "cli/command_registry.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace swingsim::cli {

std::map<std::string, Command>& commandRegistry() {
  static std::map<std::string, Command> registry;
  return registry;
}

Arguments::Arguments(const std::vector<std::string>& args,
                     const std::vector<std::string>& valueFlags,
                     const std::vector<std::string>& switchFlags) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.size() > 2 && a.compare(0, 2, "--") == 0) {
      std::string flag = a, value;
      auto eq = a.find('=');
      bool inlineValue = eq != std::string::npos;
      if (inlineValue) {
        flag = a.substr(0, eq);
        value = a.substr(eq + 1);
      }
      if (std::find(valueFlags.begin(), valueFlags.end(), flag) != valueFlags.end()) {
        if (!inlineValue) {
          if (i + 1 >= args.size()) throw UsageError(flag + " needs a value");
          value = args[++i];
        }
        values_[flag] = value;
      } else if (std::find(switchFlags.begin(), switchFlags.end(), flag) != switchFlags.end()) {
        values_[flag] = "1";
      } else {
        throw UsageError("unknown option " + flag);
      }
    } else {
      positional_.push_back(a);
    }
  }
}

bool Arguments::has(const std::string& flag) const { return values_.count(flag) > 0; }

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
  if (v != std::floor(v)) throw UsageError(flag + ": expected a whole number (got '" + get(flag) + "')");
  return static_cast<int>(v);
}

}  // namespace swingsim::cli
