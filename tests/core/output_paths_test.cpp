// Where a command will write (core/output_paths.h), checked before any work: a directory
// given as a file, a folder below a file, names and paths too long for the file system,
// and the same file given twice (by another spelling or a link) are named; a writable place
// and a folder that can be made are fine. (Permission checks are not tested: the tests may
// run as root, who may write anywhere.)
#include "core/output_paths.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <limits.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/input_error.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

fs::path scratch() {
  const fs::path dir = fs::temp_directory_path() / "swingsim_output_paths_test";
  fs::create_directories(dir);
  return dir;
}

fs::path writeFile(const std::string& name) {
  const fs::path path = scratch() / name;
  std::ofstream(path) << "x";
  return path;
}

TEST(OutputPaths, AWritablePlaceOrAFolderThatCanBeMadeIsFine) {
  EXPECT_EQ(findOutputFileProblem((scratch() / "report.md").string()), "");
  EXPECT_EQ(findOutputFileProblem((scratch() / "new" / "deeper" / "report.md").string()), "");
  EXPECT_EQ(findOutputFolderProblem((scratch() / "out" / "study").string()), "");
  EXPECT_EQ(findOutputFileProblem("/dev/null"), "") << "written through";
  EXPECT_NO_THROW(checkOutputFolder(scratch().string(), "--out"));
}

TEST(OutputPaths, ADirectoryAsAFileOrAFileAsAFolderIsNamed) {
  const std::string dir = scratch().string();
  EXPECT_EQ(findOutputFileProblem(dir),
            "expected a file to write, got the directory '" + dir + "' (give a file name inside it)");
  const std::string file = writeFile("plain.txt").string();
  EXPECT_EQ(findOutputFolderProblem(file), "expected an output folder, got the existing file '" + file + "'");
  EXPECT_EQ(findOutputFileProblem(file + "/below.csv"), "cannot write '" + file + "/below.csv': '" + file +
                                                            "' is not a folder, so nothing can be written below it");
  try {
    checkOutputFolder(file, "study.yaml: output_dir");
    ADD_FAILURE() << "a file taken for a folder";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "study.yaml: output_dir: expected an output folder, got the existing file '" + file + "'");
  }
}

TEST(OutputPaths, NamesAndPathsTooLongForTheFileSystemAreRefused) {
  const std::string longName(NAME_MAX - 5, 'n');  // fits, but not with `.tmp-PID` added
  EXPECT_THAT(findOutputFileProblem((scratch() / longName).string()),
              HasSubstr("has " + std::to_string(NAME_MAX - 5) + " bytes; a file system takes at most " +
                        std::to_string(NAME_MAX - 12) + " here (NAME_MAX " + std::to_string(NAME_MAX) +
                        ", less the temporary suffix)"));
  EXPECT_EQ(findOutputFolderProblem((scratch() / longName).string()), "") << "a folder gets no suffix";
  // Folders of 200-byte names down past PATH_MAX less the room for what is written inside.
  fs::path deep = scratch();
  while (deep.string().size() + kOutputNameReserve <= PATH_MAX) deep /= std::string(200, 'd');
  EXPECT_THAT(findOutputFolderProblem(deep.string()),
              HasSubstr("as an absolute path; at most " + std::to_string(PATH_MAX - kOutputNameReserve) +
                        " leave room for the files written inside it (PATH_MAX " + std::to_string(PATH_MAX) + ")"));
}

TEST(OutputPaths, TheSameFileUnderTwoNamesIsRefusedWithBothArguments) {
  const fs::path a = writeFile("a.yaml");
  const fs::path b = writeFile("b.yaml");
  const fs::path link = scratch() / "link.yaml";
  fs::remove(link);
  fs::create_symlink(a, link);
  EXPECT_NO_THROW(checkDistinctFiles({a.string(), b.string(), (scratch() / "missing.yaml").string()}, "why"));
  const std::string dotted = (scratch() / "." / "a.yaml").string();
  try {
    checkDistinctFiles({b.string(), a.string(), dotted}, "inputs must differ");
    ADD_FAILURE() << "a file given twice";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              dotted + ": the same file as " + a.string() + " (arguments 2 and 3): inputs must differ");
  }
  EXPECT_THROW(checkDistinctFiles({link.string(), a.string()}, "why"), InputError) << "a link to the same file";
}

}  // namespace
}  // namespace swingsim
