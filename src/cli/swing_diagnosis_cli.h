#pragma once
// The swing kinds of `compare`, `diagnose` (kind: swing-diagnosis) and `generate` (kind:
// swing-kinematics), called by those commands once the kind is read.
#include <string>
#include <vector>

#include "cli/command_registry.h"

namespace swingsim {
class YamlMap;
}

namespace swingsim::cli {

int runSwingCompare(YamlMap& yaml, const Arguments& args);
int runSwingDiagnose(YamlMap& yaml, const Arguments& args, const std::vector<std::string>& argv);
int generateSwingKinematics(YamlMap& yaml, const Arguments& args);

}  // namespace swingsim::cli
