#pragma once
// Every JSON file swingsim writes goes through here (nlohmann-json): keys in the order the
// writer put them, 2-space indent, non-finite numbers as null, and always valid UTF-8 (a
// name in Latin-1 has its invalid bytes replaced by U+FFFD instead of breaking the file).
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace swingsim {

using Json = nlohmann::ordered_json;

/// `value` times `scale` (a unit conversion), or null if it is absent: a quantity that does
/// not exist is null, never a marker number.
inline Json jsonOrNull(const std::optional<double>& value, double scale = 1) {
  return value ? Json(*value * scale) : Json(nullptr);
}

/// The text of `document`, ending in a newline.
std::string formatJson(const Json& document);
/// Writes `document` to `path` atomically (core/output_files.h). Throws RunError.
void writeJsonFile(const std::string& path, const Json& document);

}  // namespace swingsim
