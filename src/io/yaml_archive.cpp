#include "io/yaml_archive.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace swingsim {

std::string YamlWriteArchive::relative(const std::string& path) const {
  namespace fs = std::filesystem;
  if (baseDir_.empty()) return path;
  std::error_code ec;
  const fs::path rel = fs::relative(fs::absolute(path, ec), fs::absolute(baseDir_, ec), ec);
  return ec || rel.empty() ? fs::absolute(path, ec).string() : rel.generic_string();
}

std::string formatDegrees(double radians) {
  char buf[64];
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, radians * kRadToDeg);
    const double degrees = std::strtod(buf, nullptr);
    if (degrees * kDegToRad == radians) return formatNumber(degrees);
  }
  return formatNumber(radians * kRadToDeg);
}

}  // namespace swingsim
