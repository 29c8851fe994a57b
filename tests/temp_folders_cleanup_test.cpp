// Removes, when a test process ends with every test passed, the temporary folders this
// process made: ctest runs each test in its own process, and the tests name their folders
// `<temp>/<suite>-<pid>` (tests/cli/run_swingsim.h suiteTempDir and the identify tests), so
// without this every test run leaves hundreds of folders in /tmp. A failed test's folders are
// kept for inspection. Only folders whose name ends in this process's pid and that were
// modified after the process started are removed.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <system_error>

namespace {

namespace fs = std::filesystem;

class TempFoldersCleanup final : public ::testing::Environment {
 public:
  void TearDown() override {
    if (::testing::UnitTest::GetInstance()->Failed()) return;
    const std::string suffix = "-" + std::to_string(::getpid());
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(fs::temp_directory_path(), ec)) {
      const std::string name = entry.path().filename().string();
      if (name.size() <= suffix.size() || name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
        continue;
      std::error_code entryError;
      if (!entry.is_directory(entryError) || entry.is_symlink(entryError)) continue;
      if (fs::last_write_time(entry.path(), entryError) < started_ || entryError) continue;
      fs::remove_all(entry.path(), entryError);  // best effort: a folder in use stays
    }
  }

 private:
  fs::file_time_type started_ = fs::file_time_type::clock::now() - std::chrono::seconds(1);
};

// Registered at static initialisation, before gtest_main runs the tests.
[[maybe_unused]] const auto* const kCleanup = ::testing::AddGlobalTestEnvironment(new TempFoldersCleanup);

}  // namespace
