#pragma once
// `swingsim generate` for a study of kind swing-kinematics.
#include "cli/command_registry.h"

namespace swingsim {
class YamlMap;
}

namespace swingsim::cli {

/// Writes the synthetic swing kinematics CSVs the study describes; returns the exit code.
int generateSwingKinematics(YamlMap& yaml, const Arguments& args);

}  // namespace swingsim::cli
