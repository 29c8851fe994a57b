// StagedOutput: a set of output files put in place together (docs/robustness.md, "One run per
// output folder"). The commit protocol, so that a folder holds one complete set at a time:
//  1. every file is written into `.staging-HOST-PID/`, with the list of names in
//     `.staging-HOST-PID/.swingsim-run`;
//  2. before any file moves, nothing may be in the way (a folder where a file goes, a file
//     where a subfolder goes) and the folder must still be a folder;
//  3. under an flock on the folder, the marker `.commit` says the set is complete; the files
//     are renamed in; for a whole run, the files of the run before (its manifest) that this
//     run does not write are removed and the manifest is replaced; the staging folder goes.
// A run killed in 3 leaves a complete staging folder with its marker: the next run into the
// folder finishes moving it in before anything else, so the mix never outlives the kill.
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/special_files.h"

namespace swingsim {

namespace {

namespace fs = std::filesystem;

constexpr const char* kStagingPrefix = ".staging-";
// Inside a staging folder: the set is complete and is being moved in (holds "run" or "add").
constexpr const char* kCommitMarker = ".commit";
constexpr std::size_t kMaxHostBytes = 24;

std::string hostTag() {
  char host[256] = {};
  if (::gethostname(host, sizeof host - 1) != 0 || host[0] == '\0') return "localhost";
  return makeSafeFileStem(host).substr(0, kMaxHostBytes);
}

// Holds an exclusive flock on a folder while it lives: two runs into one folder commit one
// after the other. A folder that cannot be opened is not locked (the rename then fails).
class FolderLock {
 public:
  explicit FolderLock(const std::string& folder) : fd_(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)) {
    while (fd_ >= 0 && ::flock(fd_, LOCK_EX) != 0 && errno == EINTR) {
    }
  }
  ~FolderLock() {
    if (fd_ >= 0) ::close(fd_);
  }
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_;
};

std::string formatManifest(const std::vector<std::string>& names) {
  std::string text =
      "# swingsim: the files of the run in this folder; the next run into it removes those it does "
      "not write again (docs/formats.md)\n";
  for (const auto& name : names) text += name + "\n";
  return text;
}

// The names a manifest lists; only relative names that stay inside the folder, so an edited
// manifest cannot make a run delete anything outside it.
std::vector<std::string> readManifest(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return {};
  std::istringstream in(readFile(path.string()));
  std::vector<std::string> names;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const fs::path name(line);
    const bool inside = name.is_relative() && std::none_of(name.begin(), name.end(), [](const fs::path& part) {
                          return part == ".." || part == ".";
                        });
    if (inside) names.push_back(line);
  }
  return names;
}

// Removes the files the run before wrote (its manifest) that `names` does not hold again;
// only plain files and links, never a folder or a file no run listed.
void removeEarlierRunFiles(const fs::path& folder, const std::vector<std::string>& names) {
  for (const auto& old : readManifest(folder / kOutputManifestName)) {
    if (std::find(names.begin(), names.end(), old) != names.end()) continue;
    std::error_code ec;
    const fs::file_status st = fs::symlink_status(folder / old, ec);
    if (fs::is_regular_file(st) || fs::is_symlink(st)) fs::remove(folder / old, ec);
  }
}

std::string outMessage(const std::string& folder, const std::string& what) { return "--out " + folder + ": " + what; }

// Step 3 of the protocol; repeatable (a file moved before a kill is no longer staged).
void moveSetIntoPlace(const std::string& folder, const std::string& staging, bool wholeRun) {
  const std::vector<std::string> names = readManifest(fs::path(staging) / kOutputManifestName);
  for (const auto& name : names) {
    const fs::path from = fs::path(staging) / name, target = fs::path(folder) / name;
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(from, ec))) continue;
    if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
    if (std::rename(from.c_str(), target.c_str()) != 0)
      throw RunError(outMessage(folder, "cannot move the finished file " + name + " into place"));
  }
  if (wholeRun) {
    removeEarlierRunFiles(folder, names);
    const std::string manifest = staging + "/" + kOutputManifestName;
    if (std::rename(manifest.c_str(), (folder + "/" + kOutputManifestName).c_str()) != 0)
      throw RunError(
          outMessage(folder, std::string("cannot move the manifest ") + kOutputManifestName + " into place"));
  }
  std::error_code ec;
  fs::remove_all(staging, ec);
}

// Cleans the staging folders of runs into `folder` that have provably ended: a complete one
// (with its commit marker) is moved in, as its run would have; an incomplete one is removed.
void cleanOrphanedStaging(const std::string& folder) {
  std::error_code ec;
  std::vector<fs::path> orphans;
  for (const auto& entry : fs::directory_iterator(folder, ec))
    if (isOrphanedStagingFolder(entry.path().filename().string())) orphans.push_back(entry.path());
  for (const auto& staging : orphans) {
    const fs::path marker = staging / kCommitMarker;
    if (!fs::exists(marker, ec)) {
      fs::remove_all(staging, ec);
      continue;
    }
    try {
      moveSetIntoPlace(folder, staging.string(), readFile(marker.string()) == "run\n");
    } catch (const std::exception&) {
      // Something is in the way: left for this run's own commit to report.
    }
  }
}

}  // namespace

std::string makeStagingFolderName() { return kStagingPrefix + hostTag() + "-" + std::to_string(::getpid()); }

bool isOrphanedStagingFolder(const std::string& name) {
  const std::string prefix = kStagingPrefix;
  if (name.rfind(prefix, 0) != 0) return false;
  const std::string rest = name.substr(prefix.size());
  const std::size_t dash = rest.rfind('-');
  if (dash == std::string::npos || rest.substr(0, dash) != hostTag()) return false;
  const std::string digits = rest.substr(dash + 1);
  const auto isDigit = [](char c) { return c >= '0' && c <= '9'; };
  if (digits.empty() || digits.size() > 9 || !std::all_of(digits.begin(), digits.end(), isDigit)) return false;
  const pid_t pid = static_cast<pid_t>(std::strtol(digits.c_str(), nullptr, 10));
  if (pid <= 0) return false;
  if (pid == ::getpid()) return true;  // a killed run of ours whose pid this process now has
  return ::kill(pid, 0) != 0 && errno == ESRCH;
}

StagedOutput::StagedOutput(std::string folder, OutputSetKind kind) : folder_(std::move(folder)), kind_(kind) {
  std::error_code ec;
  if (fs::exists(folder_, ec) && !fs::is_directory(folder_, ec))
    throw RunError(outMessage(folder_, "a file is in the place of the output folder; nothing was written"));
  fs::create_directories(folder_, ec);
  if (ec) throw RunError(outMessage(folder_, "cannot create the output folder: " + ec.message()));
  staging_ = folder_ + "/" + makeStagingFolderName();
  {
    FolderLock lock(folder_);
    cleanOrphanedStaging(folder_);
  }
  fs::remove_all(staging_, ec);
  fs::create_directories(staging_, ec);
  if (ec) throw RunError(outMessage(folder_, "cannot write in the output folder: " + ec.message()));
}

StagedOutput::~StagedOutput() { discard(); }

void StagedOutput::add(const std::string& name, const std::string& contents) {
  try {
    writeFileAtomic(staging_ + "/" + name, contents);
  } catch (const RunError& e) {
    // The message names the file as it would be in the folder, not in the staging folder.
    std::string what = e.what();
    for (std::size_t at; (at = what.find(staging_)) != std::string::npos;) what.replace(at, staging_.size(), folder_);
    throw RunError(outMessage(folder_, what + "; nothing in the folder was changed"));
  }
  names_.push_back(name);
}

void StagedOutput::adoptStaged(const std::string& name) { names_.push_back(name); }

void StagedOutput::addBeside(const std::string& path, const std::string& contents) {
  if (isWriteThroughTarget(path)) {
    streams_.push_back({path, contents});  // written through at commit
    return;
  }
  const std::string target = resolveReplaceTarget(path);
  const fs::path p(target);
  if (p.has_parent_path()) makeDirectories(p.parent_path().string());
  beside_.push_back({writeTemporaryBeside(target, contents), target});
}

void StagedOutput::checkNothingInTheWay() const {
  std::error_code ec;
  const std::string unchanged = "; nothing in the folder was changed";
  if (!fs::is_directory(folder_, ec) || !fs::is_directory(staging_, ec))
    throw RunError(outMessage(folder_, "the output folder was moved, removed or replaced during the run" + unchanged));
  for (const auto& name : names_) {
    fs::path at(folder_);
    const fs::path rel(name);
    for (auto part = rel.begin(); part != rel.end(); ++part) {
      at /= *part;
      const bool last = std::next(part) == rel.end();
      const fs::file_status st = fs::symlink_status(at, ec);
      if (!fs::exists(st)) break;
      if (last && fs::is_directory(st))
        throw RunError(outMessage(folder_, "a folder is in the way of the output file " + name + unchanged));
      if (!last && !fs::is_directory(fs::status(at, ec)))
        throw RunError(outMessage(folder_, "a file is in the way of the folder of " + name + unchanged));
    }
  }
  for (const auto& [tmp, target] : beside_)
    if (fs::is_directory(fs::symlink_status(target, ec)))
      throw RunError(target + ": a folder is in the way of this output file; nothing in --out " + folder_ +
                     " was changed");
}

void StagedOutput::commit(const std::vector<std::string>& stale) {
  checkNothingInTheWay();
  const bool wholeRun = kind_ == OutputSetKind::kWholeRun;
  try {
    writeFileAtomic(staging_ + "/" + kOutputManifestName, formatManifest(names_));
  } catch (const RunError&) {
    throw RunError(outMessage(folder_, "cannot write the manifest (disk full?); nothing in the folder was changed"));
  }
  {
    FolderLock lock(folder_);
    writeFileAtomic(staging_ + "/" + kCommitMarker, wholeRun ? "run\n" : "add\n");
    try {
      moveSetIntoPlace(folder_, staging_, wholeRun);
    } catch (const RunError& e) {
      staging_.clear();  // complete and marked: kept for the next run into the folder to move in
      throw RunError(std::string(e.what()) + "; the next run into this folder moves the rest in");
    }
  }
  for (const auto& [tmp, target] : beside_)
    if (std::rename(tmp.c_str(), target.c_str()) != 0)
      throw RunError(target + ": cannot move the finished file into place");
  for (const auto& [target, contents] : streams_) writeThrough(target, contents);
  names_.clear();
  beside_.clear();
  streams_.clear();
  discard();
  for (const auto& name : stale) {
    std::error_code ec;
    fs::remove(fs::path(folder_) / name, ec);
  }
}

void StagedOutput::discard() {
  if (staging_.empty()) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
  names_.clear();
  for (const auto& [tmp, target] : beside_) std::remove(tmp.c_str());
  beside_.clear();
  streams_.clear();
}

}  // namespace swingsim
