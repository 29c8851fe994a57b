#pragma once
// Atomic output: each file is written to `name.tmp-PID` and renamed into place, so an
// interrupted run never leaves a half-written result that looks complete.
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace swingsim {

/// Writes `contents` to `path` atomically, creating parent directories. A FIFO, a device or
/// a link under /dev (`/dev/stdout`) is written through instead, never replaced by a file;
/// a link to a plain file keeps being a link (its target is replaced). Throws RunError if
/// the file cannot be written.
void writeFileAtomic(const std::string& path, const std::string& contents);

/// Writes `contents` to `path.tmp-PID` (the folder must exist) and returns that name; the
/// caller renames it into place. Throws RunError, leaving no temporary file, if it cannot.
std::string writeTemporaryBeside(const std::string& path, const std::string& contents);

/// What a staged set is to its folder.
enum class OutputSetKind {
  kFilesAdded,  ///< files added beside what the folder holds (simulate's trajectory and figure)
  kWholeRun,    ///< the folder's one run (a sweep's report): the files the run before wrote,
                ///< named in the folder's manifest `.swingsim-run`, and not written again are removed
};

/// A set of output files that appear in their folder together or not at all
/// (docs/robustness.md, "One run per output folder"): each is written into a hidden staging
/// folder inside it, `.staging-HOST-PID/`; commit() checks that nothing is in the way of any
/// of them, then renames them into place under a lock on the folder. A staging folder left by
/// a run that was killed is cleaned by the next run into the folder (moved in if it was
/// complete, removed if not) once its owner is provably gone (same host, pid not alive); a
/// sibling still running keeps its own. Errors name the folder as `--out`, never the staging
/// folder. The destructor removes an uncommitted staging folder.
class StagedOutput {
 public:
  /// `folder` is created if missing. Throws RunError naming `--out` if it cannot be, or if a
  /// file is in its place.
  explicit StagedOutput(std::string folder, OutputSetKind kind = OutputSetKind::kFilesAdded);
  ~StagedOutput();
  StagedOutput(const StagedOutput&) = delete;
  StagedOutput& operator=(const StagedOutput&) = delete;

  /// Writes `name` (relative to the folder; may contain subfolders) into the staging folder.
  void add(const std::string& name, const std::string& contents);
  /// Takes `name` (relative to the folder), which a writer has already put into the staging
  /// folder (getStagingFolder()), into the set as add() would, without writing it again.
  void adoptStaged(const std::string& name);
  /// Stages a file outside the folder (a `--json` path) beside its target, as
  /// `path.tmp-PID` (parent folders created); commit() moves it into place with the others.
  /// A FIFO or a device (`--json /dev/stdout`) is kept in memory and written through at
  /// commit(), after the files.
  void addBeside(const std::string& path, const std::string& contents);
  /// Moves every added file into the folder, replacing older ones, and removes the staging
  /// folder; `stale` files (relative names) are removed from the folder afterwards. Throws
  /// RunError, changing nothing in the folder, if a folder is in the way of a file (or a file
  /// in the way of its subfolder) or the folder has gone or been replaced by a file.
  void commit(const std::vector<std::string>& stale = {});
  /// Removes the staging folder, the files staged beside their targets and what was added
  /// (also done by the destructor).
  void discard();
  const std::string& getStagingFolder() const { return staging_; }

 private:
  std::string folder_, staging_;
  OutputSetKind kind_;
  std::vector<std::string> names_;
  std::vector<std::pair<std::string, std::string>> beside_;   ///< (temporary, target)
  std::vector<std::pair<std::string, std::string>> streams_;  ///< (FIFO or device, contents)

  void checkNothingInTheWay() const;
};

/// The manifest of a folder's run (OutputSetKind::kWholeRun), docs/formats.md.
constexpr const char* kOutputManifestName = ".swingsim-run";

/// The name of this process's staging folder: `.staging-HOST-PID` (HOST shortened to a safe
/// stem of at most 24 bytes).
std::string makeStagingFolderName();

/// True if `name` is a staging folder whose run has provably ended: made on this host by a
/// pid that is not alive (or is this process's own, left by a killed run before it). A
/// staging folder of another host, of a live pid, or without a host (`.staging-PID`, older
/// versions) is not.
bool isOrphanedStagingFolder(const std::string& name);

/// Creates a directory and its parents (like `mkdir -p`).
void makeDirectories(const std::string& path);

/// Largest input file any reader takes, bytes (16 MiB): every participant, model and study
/// file is a few kB; a larger one is a mistake (a wrong path, a log, a device).
constexpr std::size_t kMaxInputFileBytes = std::size_t{16} << 20;

/// Reads a whole file, at most `maxBytes`: the reading stops there, so `/dev/zero` or a
/// pipe that never ends is refused without filling memory. Throws InputError naming the
/// file if it cannot be opened, is a directory, or is larger than `maxBytes` (the message
/// gives its size and the limit).
std::string readFile(const std::string& path, std::size_t maxBytes = kMaxInputFileBytes);

/// "16 MiB", "1.5 kB", "312 bytes": a byte count for messages.
std::string formatByteCount(std::uintmax_t bytes);

/// `name` (a participant or study name) as a file stem that stays inside its folder: letters,
/// digits, '.', '-' and '_' kept, anything else (separators, spaces) becomes '_', no leading
/// dot, at most 64 bytes. When the name had to change, 8 hex digits of its hash are appended,
/// so two different names never share a stem.
std::string makeSafeFileStem(const std::string& name);

/// The file name without directory and extension ("data/slow.csv" -> "slow").
std::string fileStem(const std::string& path);

}  // namespace swingsim
