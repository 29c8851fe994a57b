#include "core/staged_writer.h"

#include <algorithm>
#include <filesystem>
#include <vector>

#include "core/input_error.h"

namespace swingsim {

void stageFolderWriter(StagedOutput& staged, const std::function<void(const std::string& folder)>& write) {
  namespace fs = std::filesystem;
  const std::string staging = staged.getStagingFolder();
  const std::string folder = fs::path(staging).parent_path().string();
  try {
    write(staging);
  } catch (const RunError& e) {
    std::string what = e.what();
    for (std::size_t at; (at = what.find(staging)) != std::string::npos;) what.replace(at, staging.size(), folder);
    throw RunError("--out " + folder + ": " + what + "; nothing in the folder was changed");
  }
  std::vector<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(staging))
    if (entry.is_regular_file()) names.push_back(entry.path().lexically_relative(staging).string());
  std::sort(names.begin(), names.end());  // the manifest in the same order every run
  for (const auto& name : names) staged.adoptStaged(name);
}

}  // namespace swingsim
