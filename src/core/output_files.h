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

/// A set of output files that appear in their folder together or not at all: each is written
/// into a hidden staging folder inside it (`.staging-PID/`); commit() renames them into
/// place (each rename atomic) and removes the folder; the destructor removes an uncommitted
/// staging folder. Nothing named like a result, and no temporary file, is left by a run that
/// fails or is stopped before commit().
class StagedOutput {
 public:
  /// `folder` is created if missing. Throws RunError if it cannot be.
  explicit StagedOutput(std::string folder);
  ~StagedOutput();
  StagedOutput(const StagedOutput&) = delete;
  StagedOutput& operator=(const StagedOutput&) = delete;

  /// Writes `name` (relative to the folder; may contain subfolders) into the staging folder.
  void add(const std::string& name, const std::string& contents);
  /// Stages a file outside the folder (a `--json` path) beside its target, as
  /// `path.tmp-PID` (parent folders created); commit() moves it into place with the others.
  /// A FIFO or a device (`--json /dev/stdout`) is kept in memory and written through at
  /// commit(), after the files.
  void addBeside(const std::string& path, const std::string& contents);
  /// Moves every added file into the folder, replacing older ones, and removes the staging
  /// folder; `stale` files (relative names) are removed from the folder afterwards.
  void commit(const std::vector<std::string>& stale = {});
  /// Removes the staging folder, the files staged beside their targets and what was added
  /// (also done by the destructor).
  void discard();
  const std::string& getStagingFolder() const { return staging_; }

 private:
  std::string folder_, staging_;
  std::vector<std::string> names_;
  std::vector<std::pair<std::string, std::string>> beside_;  ///< (temporary, target)
  std::vector<std::pair<std::string, std::string>> streams_;  ///< (FIFO or device, contents)
};

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
