// Files that are not plain files (core/special_files.h), on the quick paths: reading stops
// one byte past the limit (even on an endless device), a FIFO with a writer is read whole,
// which paths are written through and which replaced, links resolved, and writing through
// appends. (The waits of kFifoWaitSeconds for a missing partner:
// tests/scenarios/bad_input_catalogue_files_test.cpp.)
#include "core/special_files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>

#include "core/input_error.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;
using ::testing::StartsWith;

// A fresh folder per test (tests may run in parallel).
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "swingsim_special_files_test" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), {}};
}

template <class F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(SpecialFiles, ReadsAPlainFileWholeAndStopsOneBytePastTheLimit) {
  const fs::path file = scratch("plain") / "a.txt";
  std::ofstream(file) << std::string(100, 'a');
  EXPECT_EQ(readWithoutBlocking(file.string(), 1000), std::string(100, 'a'));
  EXPECT_EQ(readWithoutBlocking(file.string(), 10).size(), 11u) << "one byte more tells the limit was passed";
  EXPECT_EQ(readWithoutBlocking("/dev/zero", 1000).size(), 1001u) << "an endless device is not read for ever";
}

TEST(SpecialFiles, MissingFilesAndDirectoriesAreNamed) {
  const fs::path dir = scratch("missing");
  EXPECT_EQ(errorOf([&] { readWithoutBlocking((dir / "none.yaml").string(), 10); }),
            (dir / "none.yaml").string() + ": cannot open file (No such file or directory)");
  EXPECT_EQ(errorOf([&] { readWithoutBlocking(dir.string(), 10); }),
            dir.string() + ": is a directory (expected a file)");
  EXPECT_THROW(readWithoutBlocking(dir.string(), 10), InputError);
}

TEST(SpecialFiles, AFifoWithAWriterIsReadWhole) {
  const fs::path fifo = scratch("fifo-read") / "in.csv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string text(100000, 'x');  // more than one pipe buffer
  std::thread writer([&] { std::ofstream(fifo) << text; });
  const std::string read = readWithoutBlocking(fifo.string(), 1 << 20);
  writer.join();
  EXPECT_EQ(read, text);
}

TEST(SpecialFiles, DevicesFifosAndDevLinksAreWrittenThroughPlainFilesAndTheirLinksReplaced) {
  const fs::path dir = scratch("targets");
  std::ofstream(dir / "plain.json") << "{}";
  fs::create_symlink("plain.json", dir / "link.json");
  fs::create_symlink("nowhere.json", dir / "dangling.json");
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
  fs::create_symlink("fifo", dir / "fifo-link");
  EXPECT_FALSE(isWriteThroughTarget((dir / "new.json").string()));
  EXPECT_FALSE(isWriteThroughTarget((dir / "plain.json").string()));
  EXPECT_FALSE(isWriteThroughTarget((dir / "link.json").string()));
  EXPECT_FALSE(isWriteThroughTarget((dir / "dangling.json").string()));
  EXPECT_TRUE(isWriteThroughTarget((dir / "fifo").string()));
  EXPECT_TRUE(isWriteThroughTarget((dir / "fifo-link").string()));
  EXPECT_TRUE(isWriteThroughTarget("/dev/null"));
  EXPECT_TRUE(isWriteThroughTarget("/dev/stdout"));
  EXPECT_EQ(resolveReplaceTarget((dir / "plain.json").string()), (dir / "plain.json").string());
  EXPECT_EQ(resolveReplaceTarget((dir / "link.json").string()), fs::canonical(dir / "plain.json").string())
      << "the file a link leads to is replaced, the link kept";
  EXPECT_EQ(resolveReplaceTarget((dir / "new.json").string()), (dir / "new.json").string());
}

TEST(SpecialFiles, WritingThroughAppendsAndReachesAFifosReader) {
  const fs::path dir = scratch("write");
  std::ofstream(dir / "log.txt") << "earlier\n";
  writeThrough((dir / "log.txt").string(), "later\n");
  EXPECT_EQ(slurp(dir / "log.txt"), "earlier\nlater\n") << "appended, as to a shared stdout";
  EXPECT_NO_THROW(writeThrough("/dev/null", "anything"));
  ASSERT_EQ(::mkfifo((dir / "out").c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = slurp(dir / "out"); });
  writeThrough((dir / "out").string(), "{\"ok\": true}\n");
  reader.join();
  EXPECT_EQ(received, "{\"ok\": true}\n");
  EXPECT_THAT(errorOf([&] { writeThrough((dir / "no" / "such").string(), "x"); }),
              StartsWith((dir / "no" / "such").string() + ": cannot write (No such file or directory)"));
}

}  // namespace
}  // namespace swingsim
