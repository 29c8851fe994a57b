#include "core/output_files.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/input_error.h"

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
  std::filesystem::path p(path);
  if (p.has_parent_path()) makeDirectories(p.parent_path().string());
  const std::string tmp = writeTemporaryBeside(path, contents);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw RunError(path + ": cannot rename temporary file into place");
  }
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open file");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string fileStem(const std::string& path) {
  return std::filesystem::path(path).stem().string();
}

std::string makeSafeFileStem(const std::string& name) {
  constexpr std::size_t kMaxStem = 64;
  std::string stem;
  for (char c : name) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '-' ||
                      c == '_';
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
