#pragma once
// Shared by the libFuzzer targets: a loader may throw InputError (a clear message about
// bad input) and nothing else. Any other exception escapes LLVMFuzzerTestOneInput,
// aborts the process and is reported by libFuzzer as a crash.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/input_error.h"

namespace swingsim::fuzz {

inline std::string asText(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

/// Runs `load` and swallows InputError only.
template <class Load>
void expectOnlyInputErrors(Load&& load) {
  try {
    load();
  } catch (const InputError&) {
  }
}

/// A path inside the source tree, so relative paths in fuzzed files (../participants/...)
/// resolve to the real files, as they would for a study in studies/.
inline std::string sourcePath(const std::string& relative) { return std::string(SWINGSIM_SOURCE_DIR) + "/" + relative; }

}  // namespace swingsim::fuzz
