#include "serve/shipped_files.h"

#include <algorithm>
#include <filesystem>

#include "core/input_error.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;

// The stems of the regular *.yaml files directly in `dir`, sorted.
std::vector<std::string> listYamlStems(const std::string& dir) {
  std::error_code error;
  if (!fs::is_directory(dir, error))
    throw InputError(dir + ": expected a folder of shipped files (run from the repository root or give --data DIR)");
  std::vector<std::string> stems;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".yaml") stems.push_back(entry.path().stem().string());
  }
  if (stems.empty()) throw InputError(dir + ": expected at least one .yaml file");
  std::sort(stems.begin(), stems.end());
  return stems;
}

std::string findIn(const std::vector<std::string>& names, const std::string& dir, const std::string& name,
                   const std::string& key, const char* what) {
  if (std::find(names.begin(), names.end(), name) != names.end()) return dir + "/" + name + ".yaml";
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  throw InputError(key + ": expected " + what + " by name, one of " + list + " (got '" + name + "')");
}

}  // namespace

ShippedFiles::ShippedFiles(const std::string& dataDir)
    : participantsDir_(dataDir + "/participants"),
      modelsDir_(dataDir + "/models"),
      participantNames_(listYamlStems(participantsDir_)),
      kneeNames_(listYamlStems(modelsDir_)) {}

std::vector<std::string> ShippedFiles::getDataDirSpellings() const {
  const fs::path given = fs::path(participantsDir_).parent_path();
  std::vector<std::string> spellings;
  std::string absolute = fs::absolute(given).lexically_normal().string();
  if (absolute.size() > 1 && absolute.back() == '/') absolute.pop_back();
  spellings.push_back(absolute);
  std::error_code error;
  const fs::path canonical = fs::canonical(given, error);
  if (!error) spellings.push_back(canonical.string());
  if (given.is_absolute()) spellings.push_back(given.string());
  // Longest first, so a longer spelling goes before a shorter one inside it; never "/" itself.
  std::sort(spellings.begin(), spellings.end(),
            [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
  spellings.erase(
      std::remove_if(spellings.begin(), spellings.end(), [](const std::string& d) { return d.size() <= 1; }),
      spellings.end());
  return spellings;
}

std::string ShippedFiles::findParticipantPath(const std::string& name, const std::string& key) const {
  return findIn(participantNames_, participantsDir_, name, key, "a shipped participant");
}

std::string ShippedFiles::findKneePath(const std::string& name, const std::string& key) const {
  return findIn(kneeNames_, modelsDir_, name, key, "a shipped knee model");
}

}  // namespace swingsim
