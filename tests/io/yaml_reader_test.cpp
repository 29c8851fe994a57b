#include "io/yaml_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace swingsim {
namespace {

using ::testing::HasSubstr;

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(YamlReader, ReadsNumbersAndRejectsUnknownKeys) {
  YamlMap m = YamlMap::loadString("a_m: 1.5\nb: 2\n", "t.yaml");
  EXPECT_DOUBLE_EQ(m.getDouble("a_m"), 1.5);
  EXPECT_THAT(errorOf([&] { m.finish(); }), HasSubstr("t.yaml:2: b: unknown key"));
}

TEST(YamlReader, MissingKeyNamesFileLineAndKey) {
  YamlMap m = YamlMap::loadString("x:\n  a: 1\n", "t.yaml");
  YamlMap x = m.getMap("x");
  EXPECT_THAT(errorOf([&] { x.getDouble("b"); }), HasSubstr("x.b: required key is missing"));
}

TEST(YamlReader, RejectsNonFiniteCommaDecimalAndWrongType) {
  YamlMap m = YamlMap::loadString("a: .nan\nb: 0,41\nc: [1]\nd: -2\n", "t.yaml");
  EXPECT_THAT(errorOf([&] { m.getDouble("a"); }), HasSubstr("t.yaml:1: a: expected a finite number"));
  EXPECT_THAT(errorOf([&] { m.getDouble("b"); }), HasSubstr("t.yaml:2: b: expected a number with a decimal point"));
  EXPECT_THAT(errorOf([&] { m.getDouble("c"); }), HasSubstr("t.yaml:3: c: expected a number (got a list)"));
  EXPECT_THAT(errorOf([&] { m.getDouble("d", mustBePositive); }), HasSubstr("t.yaml:4: d: must be positive (got -2)"));
}

TEST(YamlReader, RejectsDuplicateKeysAndSyntaxErrors) {
  EXPECT_THAT(errorOf([] { YamlMap::loadString("a: 1\nb: 2\na: 3\n", "t.yaml"); }),
              HasSubstr("t.yaml:3: a: key appears twice"));
  EXPECT_THAT(errorOf([] { YamlMap::loadString("a: [1, 2\n", "t.yaml"); }), HasSubstr("YAML syntax error"));
  EXPECT_THAT(errorOf([] { YamlMap::loadString("", "t.yaml"); }), HasSubstr("expected a YAML mapping"));
}

TEST(YamlReader, AcceptsByteOrderMarkAndCrlf) {
  YamlMap m = YamlMap::loadString(
      "\xEF\xBB\xBF"
      "a: 1\r\nb: 2\r\n",
      "t.yaml");
  EXPECT_DOUBLE_EQ(m.getDouble("b"), 2.0);
}

}  // namespace
}  // namespace swingsim
