// YAML as a plain tree (io/yaml_tree.h): reading by dotted key, editing in place, the
// messages of text that is not YAML, and writing from nested calls.
#include "io/yaml_tree.h"

#include <gtest/gtest.h>

#include <string>

#include "core/input_error.h"

namespace swingsim {
namespace {

const char* kText = R"(name: P1
segments:
  shank: {mass_kg: 1.5, inertia_kgm2: 0.06}
states:
  - {name: early, stiffness_Nm_per_rad: 12}
  - {name: late}
quoted: "12"
)";

TEST(YamlTree, ReadsByDottedKeyWithKindsAndNumbers) {
  const YamlTree root = YamlTree::parse(kText, "participant_yaml", "a participant file");
  EXPECT_TRUE(root.isMap());
  EXPECT_EQ(root.get("name").scalar(), "P1");
  EXPECT_FALSE(root.get("name").number());
  EXPECT_EQ(root.find("segments.shank.mass_kg").number(), 1.5);
  EXPECT_TRUE(root.find("segments.thigh.mass_kg").isNull()) << "an absent part";
  EXPECT_TRUE(root.find("name.first").isNull()) << "a scalar on the path";
  const auto states = root.get("states").items();
  ASSERT_EQ(states.size(), 2u);
  EXPECT_EQ(states[0].get("stiffness_Nm_per_rad").number(), 12.0);
  EXPECT_TRUE(states[1].get("stiffness_Nm_per_rad").isNull());
  EXPECT_TRUE(root.get("quoted").isQuoted());
  EXPECT_FALSE(root.get("name").isQuoted());
  const auto entries = root.entries();
  ASSERT_EQ(entries.size(), 4u);
  EXPECT_EQ(entries[1].first, "segments") << "file order";
  EXPECT_TRUE(root.get("name").entries().empty());
}

TEST(YamlTree, EditsInPlaceAndWritesTheEdit) {
  YamlTree root = YamlTree::parse(kText, "participant_yaml", "a participant file");
  root.set("segments.shank.mass_kg", "1.2", "the participant");
  root.set("segments.shank.com_from_distal_m", "0.25", "the participant");  // a new last key
  const YamlTree back = YamlTree::parse(root.emit(), "text", "a participant file");
  EXPECT_EQ(back.find("segments.shank.mass_kg").number(), 1.2);
  EXPECT_EQ(back.find("segments.shank.com_from_distal_m").number(), 0.25);
  EXPECT_EQ(back.find("segments.shank.inertia_kgm2").number(), 0.06) << "the rest kept";
  // A node found shares the document: it reads the edit.
  YamlTree shank = root.find("segments.shank");
  EXPECT_EQ(shank.get("mass_kg").number(), 1.2);
  try {
    root.set("name.first", "x", "the participant");
    FAIL() << "an edit below a scalar was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "name.first: expected a map above 'first' in the participant");
  }
}

TEST(YamlTree, TextThatIsNotYamlIsNamedByItsKey) {
  try {
    YamlTree::parse("a: [1, 2", "knee_yaml", "a knee model file");
    FAIL() << "broken YAML was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("knee_yaml: expected a knee model file in YAML (got a YAML error: ", 0), 0u)
        << e.what();
  }
}

TEST(YamlWriter, WritesMapsBlockListsFlowAndQuotesText) {
  YamlWriter out;
  out.beginMap();
  out.key("name");
  out.quoted("12");
  out.key("values");
  out.beginList();
  out.plain("1.5");
  out.plain("true");
  out.null();
  out.endList();
  out.endMap();
  const YamlTree back = YamlTree::parse(out.text(), "text", "YAML");
  EXPECT_TRUE(back.get("name").isQuoted());
  EXPECT_EQ(back.get("name").scalar(), "12");
  const auto values = back.get("values").items();
  ASSERT_EQ(values.size(), 3u);
  EXPECT_EQ(values[0].number(), 1.5);
  EXPECT_EQ(values[1].scalar(), "true");
  EXPECT_TRUE(values[2].isNull());
  EXPECT_NE(out.text().find("values: [1.5, true, ~]"), std::string::npos) << out.text();
}

}  // namespace
}  // namespace swingsim
