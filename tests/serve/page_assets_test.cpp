// The page embedded at build time (cmake/embed_page.cmake, serve/page_assets.h): byte for
// byte the files of src/serve/page/, found by name only.
#include "serve/page_assets.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace swingsim {
namespace {

std::string readPageFile(const std::string& name) {
  std::ifstream in(std::string(SWINGSIM_SOURCE_DIR) + "/src/serve/page/" + name, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(PageAssets, EveryPageFileIsEmbeddedByteForByte) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(SWINGSIM_SOURCE_DIR) + "/src/serve/page")) {
    const std::string name = entry.path().filename().string();
    const auto asset = findPageAsset(name);
    ASSERT_TRUE(asset.has_value()) << name;
    EXPECT_EQ(std::string(*asset), readPageFile(name)) << name;
    ++files;
  }
  EXPECT_GE(files, 3);  // index.html, page.js, page.css
}

TEST(PageAssets, OtherNamesAreNotFound) {
  for (const char* name : {"", "../page_assets.h", "/etc/passwd", "page/index.html", "INDEX.HTML"})
    EXPECT_FALSE(findPageAsset(name).has_value()) << name;
}

}  // namespace
}  // namespace swingsim
