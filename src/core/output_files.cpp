#include "core/output_files.h"

#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/input_error.h"
#include "core/special_files.h"

namespace swingsim {

void makeDirectories(const std::string& path) {
  if (path.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(path, ec);
  if (ec) throw RunError(path + ": cannot create directory: " + ec.message());
}

std::string writeTemporaryBeside(const std::string& path, const std::string& contents) {
  const std::string tmp = path + ".tmp-" + std::to_string(::getpid());
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  if (!out) throw RunError(path + ": cannot write file");
  out << contents;
  out.flush();
  if (!out) {
    out.close();
    std::remove(tmp.c_str());
    throw RunError(path + ": write failed (disk full?)");
  }
  return tmp;
}

void writeFileAtomic(const std::string& path, const std::string& contents) {
  // A FIFO, a device or /dev/stdout is written through: a new file there would replace it.
  if (isWriteThroughTarget(path)) return writeThrough(path, contents);
  const std::string target = resolveReplaceTarget(path);  // a link stays a link
  std::filesystem::path p(target);
  if (p.has_parent_path()) makeDirectories(p.parent_path().string());
  const std::string tmp = writeTemporaryBeside(target, contents);
  if (std::rename(tmp.c_str(), target.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw RunError(path + ": cannot rename temporary file into place");
  }
}

std::string formatByteCount(std::uintmax_t bytes) {
  char buf[64];
  if (bytes < 1024) {
    std::snprintf(buf, sizeof buf, "%ju bytes", bytes);
  } else if (bytes < (std::uintmax_t{1} << 20)) {
    std::snprintf(buf, sizeof buf, "%.4g kB", static_cast<double>(bytes) / 1024);
  } else if (bytes < (std::uintmax_t{1} << 30)) {
    std::snprintf(buf, sizeof buf, "%.4g MiB", static_cast<double>(bytes) / (1 << 20));
  } else {
    std::snprintf(buf, sizeof buf, "%.4g GiB", static_cast<double>(bytes) / (1 << 30));
  }
  return buf;
}

std::string readFile(const std::string& path, std::size_t maxBytes) {
  // Read up to one byte past the limit: a file's stated size can lie (a device, a pipe,
  // /proc) and reading the whole of /dev/zero would never end; a FIFO nobody writes is not
  // waited on for ever (special_files.h).
  const std::string text = readWithoutBlocking(path, maxBytes);
  if (text.size() > maxBytes) {
    std::error_code ec;
    const bool regular = std::filesystem::is_regular_file(path, ec);
    const std::string size =
        regular ? formatByteCount(std::filesystem::file_size(path, ec))
                : "more than " + formatByteCount(maxBytes) + " read and not at its end (a device or a pipe?)";
    throw InputError(path + ": file too large for an input file (" + size + "; the limit is " +
                     formatByteCount(maxBytes) + "): is this the right file?");
  }
  return text;
}

std::string fileStem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

std::string makeSafeFileStem(const std::string& name) {
  constexpr std::size_t kMaxStem = 64;
  std::string stem;
  for (char c : name) {
    const bool keep =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '_';
    stem += keep ? c : '_';
  }
  while (!stem.empty() && stem.front() == '.') stem.front() = '_';
  if (stem.empty()) stem = "_";
  if (stem == name && stem.size() <= kMaxStem) return stem;
  // FNV-1a of the original name: different names keep different stems.
  std::uint32_t hash = 2166136261u;
  for (unsigned char c : name) hash = (hash ^ c) * 16777619u;
  char suffix[16];
  std::snprintf(suffix, sizeof suffix, "-%08x", hash);
  return stem.substr(0, kMaxStem - 9) + suffix;
}

}  // namespace swingsim
