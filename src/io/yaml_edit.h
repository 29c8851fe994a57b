#pragma once
// Minimal in-place YAML edits that keep the user's comments and layout (yaml-cpp's
// emitter would drop them): used to store calibration results in participant files.
#include <string>

namespace swingsim {

/// Sets `block.key: value` in YAML text where `block:` is a top-level mapping key and
/// `key` one of its indented children; keeps any trailing comment. Inserts the key as
/// the block's first child if absent. Throws InputError if `block:` is not found.
std::string setNestedScalar(const std::string& text, const std::string& path, const std::string& block,
                            const std::string& key, const std::string& value);

}  // namespace swingsim
