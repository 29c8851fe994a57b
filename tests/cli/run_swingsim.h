#pragma once
// Test support: run the real `swingsim` binary and capture what it printed; scratch folders
// and file contents for the tests that check what it wrote.
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include "../test_build.h"

namespace swingsim::testing {

struct CliRun {
  int code;            ///< exit code, -1 if the process did not exit normally
  std::string output;  ///< stdout and stderr together
};

/// Runs `swingsim ARGS` (arguments as one shell string) and waits for it.
inline CliRun runSwingsim(const std::string& args) {
  const std::string cmd = std::string(SWINGSIM_BINARY) + " " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf{};
  while (pipe && std::fgets(buf.data(), buf.size(), pipe)) out += buf.data();
  const int status = pipe ? pclose(pipe) : -1;
  return {status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

/// The whole content of a file ("" if it cannot be read).
inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The folder `<temp>/<suite>-<pid>`, created if missing (kept between tests of a suite).
inline std::filesystem::path suiteTempDir(const std::string& suite) {
  const auto dir = std::filesystem::temp_directory_path() / (suite + "-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

/// Writes `text` byte for byte to `<suiteTempDir(suite)>/<name>`; returns the path.
inline std::string writeSuiteTempFile(const std::string& suite, const std::string& name, const std::string& text) {
  const auto path = suiteTempDir(suite) / name;
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

/// An empty folder `<temp>/<suite>-<pid>/<name>`, created anew (the pid keeps two test runs
/// on one machine out of each other's files).
inline std::filesystem::path freshTempDir(const std::string& suite, const std::string& name) {
  const auto dir = suiteTempDir(suite) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// `dir/tiny.yaml`: a knee-axis sweep of P1 alone at lowerings 0 to `maxLowering` m in
/// 0.05 m steps (no Table 4 extras), plus the YAML lines `extra`; for the sweep's CLI tests.
inline std::filesystem::path writeTinySweepStudy(const std::filesystem::path& dir, double maxLowering,
                                                 const std::string& extra) {
  const auto path = dir / "tiny.yaml";
  std::ofstream(path) << "kind: knee-axis-sweep\nname: tiny\nparticipants: [" << SWINGSIM_SOURCE_DIR
                      << "/participants/p1.yaml]\nlowering: {step_m: 0.05, max_m: " << maxLowering
                      << ", include_published: false}\n"
                      << extra;
  return path;
}

/// Sets an environment variable for the runs of one scope (popen passes it on to the
/// binary) and unsets it at the end of the scope.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) { setenv(name, value.c_str(), 1); }
  ~ScopedEnv() { unsetenv(name_); }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
};

}  // namespace swingsim::testing
