#pragma once
// For report writers that take a folder and write their files into it one by one: they write
// into a StagedOutput's staging folder instead, and the files join its set, so the report
// appears whole or not at all (docs/robustness.md, "One run per output folder").
#include <functional>
#include <string>

#include "core/output_files.h"

namespace swingsim {

/// Calls `write` with the staging folder of `staged`, then adds every file it wrote there to
/// the set. A RunError of `write` is rethrown naming `--out` and the file as it would be in
/// the folder, never the staging folder.
void stageFolderWriter(StagedOutput& staged, const std::function<void(const std::string& folder)>& write);

}  // namespace swingsim
