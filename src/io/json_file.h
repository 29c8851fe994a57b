#pragma once
// Every JSON file swingsim writes goes through here (nlohmann-json): keys in the order the
// writer put them, 2-space indent, non-finite numbers as null, and always valid UTF-8 (a
// name in Latin-1 has its invalid bytes replaced by U+FFFD instead of breaking the file).
#include <nlohmann/json.hpp>
#include <string>

namespace swingsim {

using Json = nlohmann::ordered_json;

/// The text of `document`, ending in a newline.
std::string formatJson(const Json& document);
/// Writes `document` to `path` atomically (core/output_files.h). Throws RunError.
void writeJsonFile(const std::string& path, const Json& document);

}  // namespace swingsim
