#include "io/json_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace swingsim {
namespace {

TEST(JsonFile, KeepsKeyOrderWritesNullForNonFiniteAndParsesBack) {
  const Json doc = {{"zeta", 1.0 / 3.0}, {"alpha", std::numeric_limits<double>::quiet_NaN()},
                    {"list", {1.5, std::numeric_limits<double>::infinity()}}};
  const std::string text = formatJson(doc);
  EXPECT_LT(text.find("zeta"), text.find("alpha"));  // insertion order, not sorted
  const Json back = Json::parse(text);
  EXPECT_EQ(back["zeta"].get<double>(), 1.0 / 3.0);  // full precision: the number round-trips
  EXPECT_TRUE(back["alpha"].is_null());
  EXPECT_TRUE(back["list"][1].is_null());
  EXPECT_EQ(text.back(), '\n');
}

// A participant name typed in Latin-1 ("Jos\xe9") is not valid UTF-8: the file stays valid,
// the bad byte becomes U+FFFD.
TEST(JsonFile, InvalidUtf8InAStringIsReplacedSoTheFileStaysValid) {
  const Json doc = {{"name", std::string("Jos\xe9")}};
  const std::string text = formatJson(doc);
  const Json back = Json::parse(text);  // throws on invalid UTF-8
  EXPECT_EQ(back["name"].get<std::string>(), "Jos\xEF\xBF\xBD");
}

}  // namespace
}  // namespace swingsim
