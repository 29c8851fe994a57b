#include "io/json_file.h"

#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <limits>

#include "core/output_files.h"

namespace swingsim {
namespace {

TEST(JsonFile, KeepsKeyOrderWritesNullForNonFiniteAndParsesBack) {
  const Json doc = {{"zeta", 1.0 / 3.0},
                    {"alpha", std::numeric_limits<double>::quiet_NaN()},
                    {"list", {1.5, std::numeric_limits<double>::infinity()}}};
  const std::string text = formatJson(doc);
  EXPECT_LT(text.find("zeta"), text.find("alpha"));  // insertion order, not sorted
  const Json back = Json::parse(text);
  EXPECT_EQ(back["zeta"].get<double>(), 1.0 / 3.0);  // full precision: the number round-trips
  EXPECT_TRUE(back["alpha"].is_null());
  EXPECT_TRUE(back["list"][1].is_null());
  EXPECT_EQ(text.back(), '\n');
}

TEST(JsonFile, AnAbsentValueIsNullAPresentOneIsScaled) {
  EXPECT_TRUE(jsonOrNull(std::nullopt).is_null());
  EXPECT_TRUE(jsonOrNull(std::nullopt, 57.3).is_null());
  EXPECT_EQ(jsonOrNull(2.0, 3.0).get<double>(), 6.0);
  EXPECT_EQ(jsonOrNull(-1.0).get<double>(), -1.0);  // a real value, whatever its sign
}

// A participant name typed in Latin-1 ("Jos\xe9") is not valid UTF-8: the file stays valid,
// the bad byte becomes U+FFFD.
TEST(JsonFile, InvalidUtf8InAStringIsReplacedSoTheFileStaysValid) {
  const Json doc = {{"name", std::string("Jos\xe9")}};
  const std::string text = formatJson(doc);
  const Json back = Json::parse(text);  // throws on invalid UTF-8
  EXPECT_EQ(back["name"].get<std::string>(), "Jos\xEF\xBF\xBD");
}

// writeJsonFile itself: the file on disk (parent folders created, no temporary left beside
// it) parses back to the document that was written, and holds exactly formatJson's text.
TEST(JsonFile, WrittenFileParsesBackToTheSameDocument) {
  const auto dir = std::filesystem::temp_directory_path() / ("swingsim_json_file_test_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  const std::string path = (dir / "nested" / "swing.json").string();
  const Json doc = {{"participant", "P1"},
                    {"swing_time_s", 0.42},
                    {"bounce", false},
                    {"events", Json::array({{{"name", "toe_off"}, {"time_s", 0.0}}})}};
  writeJsonFile(path, doc);
  EXPECT_EQ(Json::parse(readFile(path)), doc);
  EXPECT_EQ(readFile(path), formatJson(doc));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir / "nested"), {}), 1);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace swingsim
