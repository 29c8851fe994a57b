// The catalogue's table names every part with its mass, says where a value is assumed, and
// lists only the category asked for.
#include "report/parts_table.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace swingsim {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

PartsCatalogue twoParts() {
  PartsCatalogue c;
  c.path = "parts.yaml";
  ProsthesisPart knee;
  knee.id = "knee-a";
  knee.name = "Knee A";
  knee.maker = "Maker";
  knee.source = "IFU p. 3";
  knee.mass = 0.49;
  knee.length = 0.075;
  ProsthesisPart foot = knee;
  foot.id = "foot-b";
  foot.category = PartCategory::kFoot;
  foot.mass = 0.824;
  foot.length = 0.26;
  foot.com = 0.06;
  foot.inertia = 0.0014;
  c.parts = {knee, foot};
  return c;
}

TEST(PartsTable, EveryPartWithItsMassSourceAndAssumptions) {
  const std::string t = formatPartsTable(twoParts());
  EXPECT_THAT(t, HasSubstr("knee-a"));
  EXPECT_THAT(t, HasSubstr("0.49"));
  EXPECT_THAT(t, HasSubstr("assumed at half its height"));
  EXPECT_THAT(t, HasSubstr("assumed uniform rod"));
  EXPECT_THAT(t, HasSubstr("source: IFU p. 3"));
  EXPECT_THAT(t, HasSubstr("60 mm forward of the ankle"));
  EXPECT_THAT(t, HasSubstr("14.0 kg cm^2"));
}

TEST(PartsTable, OneCategory) {
  const std::string t = formatPartsTable(twoParts(), PartCategory::kFoot);
  EXPECT_THAT(t, HasSubstr("foot-b"));
  EXPECT_THAT(t, Not(HasSubstr("knee-a")));
}

}  // namespace
}  // namespace swingsim
