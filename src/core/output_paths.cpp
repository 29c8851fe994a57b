#include "core/output_paths.h"

#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <map>
#include <utility>

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/special_files.h"

namespace swingsim {

namespace {

namespace fs = std::filesystem;

// Room for the `.tmp-PID` suffix of a file written atomically (a pid has at most 7 digits).
constexpr std::size_t kTemporarySuffix = 12;

// "" if `folder`, or the nearest folder above it that exists, is a folder we may write in.
std::string checkFolderWritable(const fs::path& folder) {
  std::error_code ec;
  fs::path p = fs::absolute(folder.empty() ? fs::path(".") : folder, ec);
  while (!fs::exists(p, ec) && p.has_relative_path()) p = p.parent_path();
  if (!fs::is_directory(p, ec)) return "'" + p.string() + "' is not a folder, so nothing can be written below it";
  if (::access(p.c_str(), W_OK | X_OK) != 0) return "cannot write in the folder '" + p.string() + "' (permissions)";
  return "";
}

// "" if no component of `path` is longer than NAME_MAX - `lastExtra` (the last) and the
// absolute path leaves `reserve` bytes below PATH_MAX.
std::string checkLengths(const std::string& path, std::size_t lastExtra, std::size_t reserve) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec).lexically_normal();
  for (const auto& part : fs::path(path)) {
    const std::size_t extra = part == fs::path(path).filename() ? lastExtra : 0;
    if (part.string().size() + extra > NAME_MAX)
      return "the name '" + part.string().substr(0, 40) + "...' has " + std::to_string(part.string().size()) +
             " bytes; a file system takes at most " + std::to_string(NAME_MAX - extra) + " here (NAME_MAX " +
             std::to_string(NAME_MAX) + (extra ? ", less the temporary suffix" : "") + ")";
  }
  if (absolute.string().size() + reserve > PATH_MAX)
    return "the path has " + std::to_string(absolute.string().size()) + " bytes as an absolute path; at most " +
           std::to_string(PATH_MAX - reserve) + " leave room for the files written " +
           (reserve > kTemporarySuffix ? "inside it" : "beside it") + " (PATH_MAX " + std::to_string(PATH_MAX) + ")";
  return "";
}

// Paths up to this many bytes are quoted whole in a message; a longer one (5,000 characters)
// would bury the reason, so the message starts with it and quotes the path's two ends.
constexpr std::size_t kWholePathInMessage = 512;

// "cannot write 'PATH': DETAIL" for a path too long, as above.
std::string describeLengthProblem(const std::string& verb, const std::string& path, std::size_t reserve,
                                  const std::string& detail) {
  if (path.size() <= kWholePathInMessage) return verb + " '" + path + "': " + detail;
  return "path too long (" + std::to_string(path.size()) + " characters; this system allows " +
         std::to_string(PATH_MAX - reserve) + " per path here / " + std::to_string(NAME_MAX) + " per name): " + verb +
         " '" + path.substr(0, 60) + "...' (ending '..." + path.substr(path.size() - 30) + "'): " + detail;
}

}  // namespace

std::string findOutputFileProblem(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec))
    return "expected a file to write, got the directory '" + path + "' (give a file name inside it)";
  if (isWriteThroughTarget(path))
    return ::access(path.c_str(), W_OK) == 0 ? "" : "cannot write '" + path + "' (permissions)";
  if (const std::string length = checkLengths(path, kTemporarySuffix, kTemporarySuffix); !length.empty())
    return describeLengthProblem("cannot write", path, kTemporarySuffix, length);
  const std::string folder = checkFolderWritable(fs::path(path).parent_path());
  return folder.empty() ? "" : "cannot write '" + path + "': " + folder;
}

std::string findOutputFolderProblem(const std::string& path) {
  std::error_code ec;
  if (fs::exists(path, ec) && !fs::is_directory(path, ec))
    return "expected an output folder, got the existing file '" + path + "'";
  if (const std::string length = checkLengths(path, 0, kOutputNameReserve); !length.empty())
    return describeLengthProblem("cannot write into", path, kOutputNameReserve, length);
  const std::string folder = checkFolderWritable(path);
  return folder.empty() ? "" : "cannot write into '" + path + "': " + folder;
}

void checkOutputFolder(const std::string& path, const std::string& where) {
  const std::string problem = findOutputFolderProblem(path);
  if (!problem.empty()) throw InputError(where + ": " + problem);
}

void checkDistinctFiles(const std::vector<std::string>& paths, const std::string& why) {
  std::map<std::pair<dev_t, ino_t>, std::size_t> seen;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    struct stat st {};
    if (::stat(paths[i].c_str(), &st) != 0) continue;
    const auto [it, added] = seen.emplace(std::make_pair(st.st_dev, st.st_ino), i);
    if (!added)
      throw InputError(paths[i] + ": the same file as " + paths[it->second] + " (arguments " +
                       std::to_string(it->second + 1) + " and " + std::to_string(i + 1) + "): " + why);
  }
}

std::vector<CommandFile> listFolderFiles(const std::string& source, const std::string& folder,
                                         const std::vector<std::string>& names) {
  std::vector<CommandFile> files;
  for (const auto& name : names) files.push_back({source, (fs::path(folder) / name).string()});
  return files;
}

namespace {

// True if `a` and `b` name one file: the same device and inode, or (for a path that does not
// exist yet) the same weakly canonical path.
bool isSameFile(const std::string& a, const std::string& b) {
  struct stat sa {
  }, sb{};
  if (::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0)
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  std::error_code ea, eb;
  const fs::path ca = fs::weakly_canonical(a, ea), cb = fs::weakly_canonical(b, eb);
  return !ea && !eb && ca == cb;
}

}  // namespace

void checkOutputsAreNotInputs(const std::vector<CommandFile>& inputs, const std::vector<CommandFile>& outputs) {
  for (const auto& out : outputs) {
    if (out.path.empty() || isWriteThroughTarget(out.path)) continue;
    for (const auto& in : inputs)
      if (!in.path.empty() && isSameFile(out.path, in.path))
        throw InputError(out.source + " '" + out.path + "': would write over the input " + in.source + " '" + in.path +
                         "'; a command never replaces one of its own inputs (write it elsewhere)");
  }
}

std::string chooseStudyOutputFolder(const std::optional<std::string>& out, const std::string& studyName,
                                    const std::string& studyPath) {
  if (out) return *out;
  const std::string folder = "out/" + makeSafeFileStem(studyName);
  checkOutputFolder(folder, "the default output folder of " + studyPath + " (no --out)");
  return folder;
}

}  // namespace swingsim
