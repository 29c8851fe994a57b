#pragma once
// Atomic output: each file is written to `name.tmp-PID` and renamed into place, so an
// interrupted run never leaves a half-written result that looks complete.
#include <string>

namespace swingsim {

/// Writes `contents` to `path` atomically, creating parent directories. Throws
/// RunError if the file cannot be written.
void writeFileAtomic(const std::string& path, const std::string& contents);

/// Creates a directory and its parents (like `mkdir -p`).
void makeDirectories(const std::string& path);

/// Reads a whole file; throws InputError if it cannot be opened.
std::string readFile(const std::string& path);

/// The file name without directory and extension ("data/slow.csv" -> "slow").
std::string fileStem(const std::string& path);

}  // namespace swingsim
