#pragma once
// `swingsim generate` for a study of kind swing-kinematics.
#include <optional>
#include <string>

namespace swingsim {
class YamlMap;
}

namespace swingsim::cli {

/// Writes the synthetic swing kinematics CSVs the study describes, into `outDir` if given
/// (--out), else the study's output_dir; returns the exit code.
int generateSwingKinematics(YamlMap& yaml, const std::optional<std::string>& outDir);

}  // namespace swingsim::cli
