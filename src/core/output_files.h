#pragma once
// Atomic output: each file is written to `name.tmp-PID` and renamed into place, so an
// interrupted run never leaves a half-written result that looks complete.
#include <string>

namespace swingsim {

/// Writes `contents` to `path` atomically, creating parent directories. Throws
/// RunError if the file cannot be written.
void writeFileAtomic(const std::string& path, const std::string& contents);

/// Writes `contents` to `path.tmp-PID` (the folder must exist) and returns that name; the
/// caller renames it into place. Throws RunError, leaving no temporary file, if it cannot.
std::string writeTemporaryBeside(const std::string& path, const std::string& contents);

/// Creates a directory and its parents (like `mkdir -p`).
void makeDirectories(const std::string& path);

/// Reads a whole file; throws InputError if it cannot be opened.
std::string readFile(const std::string& path);

/// `name` (a participant or study name) as a file stem that stays inside its folder: letters,
/// digits, '.', '-' and '_' kept, anything else (separators, spaces) becomes '_', no leading
/// dot, at most 64 bytes. When the name had to change, 8 hex digits of its hash are appended,
/// so two different names never share a stem.
std::string makeSafeFileStem(const std::string& name);

/// The file name without directory and extension ("data/slow.csv" -> "slow").
std::string fileStem(const std::string& path);

}  // namespace swingsim
