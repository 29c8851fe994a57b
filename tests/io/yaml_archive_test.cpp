#include "io/yaml_archive.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "core/units.h"
#include "io/yaml_reader.h"

namespace swingsim {
namespace {

// A small format with one field of each kind the archives know, described once.
enum class Side { kLeft, kRight };

struct Item {
  std::string name;
  double mass = 0;  // kg
};

struct Sample {
  std::string name;
  double length = 0;  // m
  double angle = 0;   // rad, degrees in the file
  double rate = 2.5;  // optional, default 2.5
  int count = 0;
  int steps = 7;  // optional, default 7
  bool flag = false;
  Side side = Side::kLeft;
  std::vector<double> angles;  // rad, degrees in the file
  std::vector<Item> items;
  bool hasExtra = false;
  Item extra;
};

template <class A>
void serialize(A& a, Item& i) {
  a.text("name", i.name);
  a.number("mass_kg", i.mass, mustBePositive);
}

template <class A>
void serialize(A& a, Sample& s) {
  a.text("name", s.name);
  a.number("length_m", s.length, mustBePositive);
  a.angle("angle_deg", s.angle);
  a.optionalNumber("rate", s.rate);
  a.integer("count", s.count);
  a.optionalInteger("steps", s.steps);
  a.optionalFlag("flag", s.flag);
  a.choice("side", s.side, {{"left", Side::kLeft}, {"right", Side::kRight}}, true);
  a.angles("angles_deg", s.angles);
  a.mapList("items", s.items);
  a.optionalMap("extra", s.extra, s.hasExtra);
  a.require(s.count <= static_cast<int>(s.items.size()), "count", "must not exceed the number of items",
            [&] { return std::to_string(s.count); });
}

Sample readSample(const std::string& text) {
  YamlMap yaml = YamlMap::loadString(text, "sample.yaml");
  YamlReadArchive a(yaml);
  Sample s;
  serialize(a, s);
  yaml.finish();
  return s;
}

std::string inputErrorOf(const std::string& text) {
  try {
    readSample(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const char* kSample = R"(name: knee
length_m: 0.45
angle_deg: 30
count: 1
side: right
angles_deg: [0, 90, -4]
items:
  - {name: shoe, mass_kg: 0.4}
)";

TEST(YamlArchive, ReadsEveryKindWithDefaultsAndUnits) {
  const Sample s = readSample(kSample);
  EXPECT_EQ(s.name, "knee");
  EXPECT_EQ(s.length, 0.45);
  EXPECT_EQ(s.angle, 30 * kDegToRad);
  EXPECT_EQ(s.rate, 2.5);  // absent: the default
  EXPECT_EQ(s.steps, 7);   // absent: the default
  EXPECT_EQ(s.count, 1);
  EXPECT_FALSE(s.flag);
  EXPECT_EQ(s.side, Side::kRight);
  ASSERT_EQ(s.angles.size(), 3u);
  EXPECT_EQ(s.angles[1], 90 * kDegToRad);
  ASSERT_EQ(s.items.size(), 1u);
  EXPECT_EQ(s.items[0].name, "shoe");
  EXPECT_FALSE(s.hasExtra);
}

TEST(YamlArchive, WriteThenReadGivesTheSameValues) {
  Sample s = readSample(kSample);
  s.rate = 0.1 + 0.2;  // a double without a short exact decimal
  s.angle = 0.3;       // rad: degrees that are not round
  s.steps = 12;
  s.flag = true;
  s.hasExtra = true;
  s.extra = {"weight", 1.0 / 3.0};
  const std::string text = writeYamlDocument(s, "", "a sample\nsecond line");
  EXPECT_EQ(text.rfind("# a sample\n# second line\n", 0), 0u) << text;
  const Sample back = readSample(text);
  EXPECT_EQ(back.rate, s.rate);
  EXPECT_EQ(back.angle, s.angle);
  EXPECT_EQ(back.angles, s.angles);
  EXPECT_EQ(back.steps, 12);
  EXPECT_TRUE(back.flag);
  EXPECT_EQ(back.side, Side::kRight);
  ASSERT_TRUE(back.hasExtra);
  EXPECT_EQ(back.extra.mass, 1.0 / 3.0);
  EXPECT_EQ(back.items.size(), 1u);
}

TEST(YamlArchive, FormatDegreesIsShortAndExact) {
  EXPECT_EQ(formatDegrees(30 * kDegToRad), "30");
  EXPECT_EQ(formatDegrees(-4 * kDegToRad), "-4");
  for (double rad : {0.3, 1e-3, -2.0, 1.0 / 7.0})
    EXPECT_EQ(std::strtod(formatDegrees(rad).c_str(), nullptr) * kDegToRad, rad) << rad;
}

TEST(YamlArchive, BadInputNamesFileLineAndKey) {
  const std::string base = kSample;
  EXPECT_EQ(inputErrorOf(base + "extra: {name: w, mass_kg: -1}\n"),
            "sample.yaml:9: extra.mass_kg: must be positive (got -1)");
  EXPECT_EQ(inputErrorOf(base + "unknown: 1\n"),
            "sample.yaml:9: unknown: unknown key (check the spelling; see docs/formats.md)");
  std::string twice = base;
  twice.replace(twice.find("count: 1"), 8, "count: 2");
  EXPECT_EQ(inputErrorOf(twice), "sample.yaml:4: count: must not exceed the number of items (got 2)");
  std::string side = base;
  side.replace(side.find("side: right"), 11, "side: up");
  EXPECT_EQ(inputErrorOf(side), "sample.yaml:5: side: expected one of: left, right (got 'up')");
}

}  // namespace
}  // namespace swingsim
