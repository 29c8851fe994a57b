// The JSON archive: one list of keys per record, written and read back exactly; each kind
// of bad value refused with the file, the key (with the path of the object it is in), what
// was expected and what was found.
#include "io/json_archive.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "core/input_error.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

// A small format with one key of each kind the archives know, described once.
struct Part {
  std::vector<double> lengths;  // m; its name is its place in the list
};

struct Shape {
  int index = 0, count = 1;
};

struct Record {
  std::string name;
  bool flag = false;
  int count = 0;
  std::uint64_t seed = 0;
  double scale = 0;            // NaN: none, written null
  std::vector<double> masses;  // kg, NaN written null
  bool hasShape = false;
  Shape shape;
  std::vector<Part> parts;
  std::vector<double> times;  // s, written as text
  std::vector<std::uint64_t> skipped;
};

const JsonFileKind kKind{"a record file", "the test", "this is not a whole record file"};

template <class A>
void serialize(A& a, Shape& s) {
  a.whole("index", s.index, 99);
  a.whole("count", s.count, 100, [](const std::uint64_t& n) { return n >= 1 ? std::string() : "at least 1"; });
  a.require(s.index < s.count, "index", "less than count (" + std::to_string(s.count) + ")",
            [&] { return std::to_string(s.index); });
}

template <class A>
void serialize(A& a, Part& p, std::size_t k) {
  std::string name = "part " + std::to_string(k);
  a.text("name", name, mustBeText(name));
  a.numberLines("lengths_m", p.lengths);
}

template <class A>
void serialize(A& a, Record& r) {
  std::string format = "record";
  a.text("format", format, mustBeText("record"));
  a.text("name", r.name);
  a.flag("flag", r.flag);
  a.whole("count", r.count, 10);
  a.whole("seed", r.seed, std::numeric_limits<std::uint64_t>::max());
  a.number("scale", r.scale);
  a.numbers("masses_kg", r.masses, [](const double& m) { return m > 0 ? std::string() : "a mass above 0 kg"; });
  a.nullOrObject("shape", r.shape, r.hasShape, "{\"index\": K, \"count\": N}");
  a.objectList("parts", r.parts);
  a.numberLines("times_s", r.times);
  a.wholeLines("skipped", r.skipped,
               [](const std::uint64_t& s) { return s < 10 ? std::string() : "an index below 10"; });
  a.require(r.count <= static_cast<int>(r.parts.size()) + 1, "count", "at most the parts + 1",
            [&] { return std::to_string(r.count); });
}

Record makeRecord() {
  Record r;
  r.name = "left";
  r.flag = true;
  r.count = 2;
  r.seed = std::numeric_limits<std::uint64_t>::max();
  r.scale = 1.0 / 3.0;
  r.masses = {0.1, std::numeric_limits<double>::quiet_NaN()};
  r.hasShape = true;
  r.shape = {1, 3};
  r.parts.resize(2);
  r.parts[0].lengths = {0.25, 1.0 / 7.0};
  r.times = {0.1, std::numeric_limits<double>::quiet_NaN()};
  r.skipped = {4};
  return r;
}

std::string scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("swingsim-json-archive-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

Record readText(const std::string& name, const std::string& text) {
  const std::string path = scratch(name);
  std::ofstream(path) << text;
  Record r;
  readJsonDocument(path, kMaxInputFileBytes, kKind, r);
  return r;
}

std::string refusal(const std::string& name, const std::string& text) {
  try {
    readText(name, text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

// Keys in the list's order; the Json tree's numbers in their shortest form, the text lists
// with 17 digits, each list indented to its depth.
TEST(JsonArchive, WritesKeysInTheListsOrderAndTextListsAtTheirDepth) {
  EXPECT_EQ(formatJsonDocument(makeRecord()), R"({
  "format": "record",
  "name": "left",
  "flag": true,
  "count": 2,
  "seed": 18446744073709551615,
  "scale": 0.3333333333333333,
  "masses_kg": [
    0.1,
    null
  ],
  "shape": {
    "index": 1,
    "count": 3
  },
  "parts": [
    {
      "name": "part 0",
      "lengths_m": [
        0.25,
        0.14285714285714285
      ]
    },
    {
      "name": "part 1",
      "lengths_m": []
    }
  ],
  "times_s": [
    0.10000000000000001,
    null
  ],
  "skipped": [
    4
  ]
}
)");
  Record none = makeRecord();
  none.hasShape = false;
  none.scale = std::numeric_limits<double>::infinity();
  none.skipped.clear();
  const std::string text = formatJsonDocument(none);
  EXPECT_THAT(text, HasSubstr("\"shape\": null,\n"));
  EXPECT_THAT(text, HasSubstr("\"scale\": null,\n"));
  EXPECT_THAT(text, HasSubstr("\"skipped\": []\n}\n"));
}

TEST(JsonArchive, ReadsBackWhatItWrote) {
  const Record r = makeRecord();
  const Record back = readText("round-trip.json", formatJsonDocument(r));
  EXPECT_EQ(back.name, r.name);
  EXPECT_EQ(back.flag, r.flag);
  EXPECT_EQ(back.count, r.count);
  EXPECT_EQ(back.seed, r.seed);
  EXPECT_EQ(back.scale, r.scale);  // exact, not near
  ASSERT_EQ(back.masses.size(), 2u);
  EXPECT_EQ(back.masses[0], 0.1);
  EXPECT_TRUE(std::isnan(back.masses[1]));
  EXPECT_TRUE(back.hasShape);
  EXPECT_EQ(back.shape.index, 1);
  EXPECT_EQ(back.shape.count, 3);
  ASSERT_EQ(back.parts.size(), 2u);
  EXPECT_EQ(back.parts[0].lengths, r.parts[0].lengths);
  EXPECT_TRUE(back.parts[1].lengths.empty());
  ASSERT_EQ(back.times.size(), 2u);
  EXPECT_EQ(back.times[0], 0.1);
  EXPECT_TRUE(std::isnan(back.times[1]));
  EXPECT_EQ(back.skipped, r.skipped);

  Record none = makeRecord();
  none.hasShape = false;
  none.shape = {};
  const Record noneBack = readText("no-shape.json", formatJsonDocument(none));
  EXPECT_FALSE(noneBack.hasShape);
}

// A key of the list that is missing is named; a key the list does not name is ignored.
TEST(JsonArchive, NamesAMissingKeyAndIgnoresAnUnknownOne) {
  const std::string text = formatJsonDocument(makeRecord());
  const std::string p = scratch("");
  std::string noSeed = text;
  noSeed.erase(noSeed.find("  \"seed\""), std::string("  \"seed\": 18446744073709551615,\n").size());
  EXPECT_EQ(refusal("a.json", noSeed),
            p + "a.json: seed: expected the key (this is not a whole record file), found it missing");
  std::string extra = text;
  extra.insert(extra.find("  \"name\""), "  \"comment\": [1, 2],\n");
  EXPECT_EQ(refusal("b.json", extra), "accepted");
  std::string noCount = text;
  noCount.erase(noCount.find("    \"count\": 3"), std::string("    \"count\": 3").size());
  noCount.replace(noCount.find("\"index\": 1,"), std::string("\"index\": 1,").size(), "\"index\": 1");
  EXPECT_EQ(refusal("c.json", noCount),
            p + "c.json: shape.count: expected the key (this is not a whole record file), found it missing");
}

TEST(JsonArchive, RefusesEachKindOfBadValueNamingFileAndKey) {
  const std::string text = formatJsonDocument(makeRecord());
  auto edit = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    const auto at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? t : t.replace(at, from.size(), to);
  };
  const std::string p = scratch("");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {edit("\"format\": \"record\"", "\"format\": \"other\""), "format: expected \"record\", found \"other\""},
      {edit("\"name\": \"left\"", "\"name\": 3"), "name: expected a string, found 3"},
      {edit("\"flag\": true", "\"flag\": 1"), "flag: expected true or false, found 1"},
      {edit("\"count\": 2", "\"count\": 11"), "count: expected a whole number from 0 to 10, found 11"},
      {edit("\"count\": 2", "\"count\": -1"), "count: expected a whole number from 0 to 10, found -1"},
      {edit("\"count\": 2", "\"count\": 2.5"), "count: expected a whole number from 0 to 10, found 2.5"},
      {edit("\"count\": 2", "\"count\": 4"), "count: expected at most the parts + 1, found 4"},
      {edit("\"scale\": 0.3333333333333333", "\"scale\": \"x\""), "scale: expected a number or null, found \"x\""},
      {edit("\"masses_kg\": [", "\"masses_kg\": 5, \"x\": ["), "masses_kg: expected a list of numbers, found 5"},
      {edit("    0.1,\n    null\n  ],\n  \"shape\"", "    0.1,\n    true\n  ],\n  \"shape\""),
       "masses_kg[1]: expected a number or null, found true"},
      {edit("    0.1,\n    null\n  ],\n  \"shape\"", "    -0.1,\n    null\n  ],\n  \"shape\""),
       "masses_kg[0]: expected a mass above 0 kg, found -0.1"},
      {edit("\"shape\": {", "\"shape\": 7, \"x\": {"), "shape: expected null or {\"index\": K, \"count\": N}, found 7"},
      {edit("\"index\": 1", "\"index\": 3"), "shape.index: expected less than count (3), found 3"},
      {edit("\"count\": 3", "\"count\": 0"), "shape.count: expected at least 1, found 0"},
      {edit("\"parts\": [", "\"parts\": {\"a\": 1}, \"x\": ["), "parts: expected a list of objects, found {\"a\":1}"},
      {edit("\"name\": \"part 1\"", "\"name\": \"part 2\""), "parts[1].name: expected \"part 1\", found \"part 2\""},
      {edit("        0.25,", "        \"a\","), "parts[0].lengths_m[0]: expected a number or null, found \"a\""},
      {edit("    0.10000000000000001,", "    [],"), "times_s[0]: expected a number or null, found []"},
      {edit("    4\n", "    -4\n"), "skipped[0]: expected a whole number, found -4"},
      {edit("    4\n", "    12\n"), "skipped[0]: expected an index below 10, found 12"},
      {edit("\"skipped\": [", "\"skipped\": \"4\", \"x\": ["),
       "skipped: expected a list of whole numbers, found \"4\""},
  };
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const std::string name = "bad-" + std::to_string(k) + ".json";
    EXPECT_EQ(refusal(name, cases[k].first), p + name + ": " + cases[k].second);
  }
}

TEST(JsonArchive, RefusesAFileThatIsNotAJsonObject) {
  const std::string p = scratch("");
  EXPECT_THAT(refusal("d.json", "{\"format\": "),
              HasSubstr(p + "d.json: expected the JSON of a record file (the test), found text that is not JSON ("));
  EXPECT_EQ(refusal("e.json", "[1, 2]"), p + "e.json: expected a JSON object (a record file), found [1,2]");
  EXPECT_EQ(describeJsonValue(Json(std::string(100, 'x'))), "\"" + std::string(56, 'x') + "...");
}

}  // namespace
}  // namespace swingsim
