// The shipped parts catalogue loads with a source on every part; a bad catalogue is refused
// at its file, line and key.
#include "io/parts_catalogue_loader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <set>

#include "core/input_error.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

const std::string kOnePart = R"(parts:
  knee-a:
    category: knee
    name: Knee A
    maker: Maker
    mass_kg: 0.49
    axis_to_connector_m: 0.075
    source: IFU section 6
)";

std::string errorFor(const std::string& text) {
  try {
    parsePartsCatalogue(text, "parts/bad.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string replaced(const std::string& from, const std::string& to) {
  std::string t = kOnePart;
  const auto at = t.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return t.replace(at, from.size(), to);
}

TEST(PartsCatalogueLoader, ShippedCatalogueHasEveryCategoryAndSources) {
  const PartsCatalogue c = loadPartsCatalogue(defaultPartsCataloguePath());
  std::set<PartCategory> categories;
  for (const ProsthesisPart& p : c.parts) {
    categories.insert(p.category);
    EXPECT_FALSE(p.source.empty()) << p.id;
    EXPECT_GT(p.mass, 0) << p.id;
  }
  EXPECT_EQ(categories.size(), 4u);
  const ProsthesisPart* osl = c.find("osl-knee");
  ASSERT_NE(osl, nullptr);
  EXPECT_DOUBLE_EQ(osl->mass, 2.2455);  // MyoHub/myo_sim osl/assets/myolegs_osl_chain.xml
  EXPECT_EQ(checkCataloguePart(c, "osl-knee", PartCategory::kKnee), "");
  EXPECT_THAT(checkCataloguePart(c, "osl-knee", PartCategory::kFoot), HasSubstr("(it is a knee)"));
  EXPECT_THAT(checkCataloguePart(c, "nope", PartCategory::kFoot), HasSubstr("osl-foot"));
}

TEST(PartsCatalogueLoader, GoodPartAndItsAssumptions) {
  const PartsCatalogue c = parsePartsCatalogue(kOnePart, "parts/one.yaml");
  ASSERT_EQ(c.parts.size(), 1u);
  EXPECT_EQ(c.parts[0].id, "knee-a");
  EXPECT_FALSE(c.parts[0].com.has_value());
  EXPECT_FALSE(c.parts[0].inertia.has_value());
}

TEST(PartsCatalogueLoader, BadInputsNameFileLineAndKey) {
  EXPECT_THAT(errorFor(replaced("mass_kg: 0.49", "mass_kg: 490")),
              AllOf(StartsWith("parts/bad.yaml:6: parts.knee-a.mass_kg"), HasSubstr("is it in grams?")));
  EXPECT_THAT(errorFor(replaced("category: knee", "category: hand")),
              AllOf(StartsWith("parts/bad.yaml:3:"), HasSubstr("hand")));
  EXPECT_THAT(errorFor(replaced("    source: IFU section 6\n", "")), HasSubstr("source"));
  EXPECT_THAT(errorFor(replaced("axis_to_connector_m: 0.075", "axis_to_connector_m: 75")),
              HasSubstr("is it in millimetres?"));
  EXPECT_THAT(errorFor(replaced("axis_to_connector_m: 0.075", "axis_to_connector_m: 0.075\n    com_below_axis_m: 0.1")),
              AllOf(HasSubstr("com_below_axis_m"), HasSubstr("must lie on the knee unit")));
  // A key of another category is not a knee's.
  EXPECT_THAT(errorFor(replaced("axis_to_connector_m: 0.075", "axis_to_connector_m: 0.075\n    length_m: 0.2")),
              HasSubstr("length_m"));
  EXPECT_THAT(errorFor("parts: {}\n"), HasSubstr("expected at least one part"));
}

}  // namespace
}  // namespace swingsim
