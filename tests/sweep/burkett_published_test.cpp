// Burkett 2004's published numbers (sweep/burkett_published.h) checked against each other, so
// a typing error in one table shows: Table 4's row at the standard location repeats Table 3,
// the lowerings increase, and the paper's predicted optimum is the Table 4 lowering where its
// model's swing time is least.
#include "sweep/burkett_published.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace swingsim {
namespace {

TEST(BurkettPublished, FourParticipantsFoundByName) {
  const auto& all = publishedParticipants();
  ASSERT_EQ(all.size(), 4u);
  for (const std::string name : {"P1", "P2", "P3", "P4"}) {
    const PublishedParticipant* p = findPublished(name);
    ASSERT_NE(p, nullptr) << name;
    EXPECT_EQ(p->name, name);
  }
  EXPECT_EQ(findPublished("P5"), nullptr);
  EXPECT_EQ(findPublished("p1"), nullptr) << "names as in the paper";
  EXPECT_EQ(findPublished(""), nullptr);
}

TEST(BurkettPublished, Table4AtTheStandardLocationRepeatsTable3) {
  for (const auto& p : publishedParticipants()) {
    ASSERT_FALSE(p.table4.empty()) << p.name;
    EXPECT_EQ(p.table4.front().lowering, 0.0) << p.name;
    EXPECT_EQ(p.table4.front().model, p.table3Model) << p.name;
    EXPECT_EQ(p.table4.front().measuredProsthetic, p.table3Measured) << p.name;
    EXPECT_GT(p.table3MeasuredSd, 0.0) << p.name;
    EXPECT_LT(p.table3MeasuredSd, 0.2 * p.table3Measured)
        << p.name << ": a trial SD well below the mean (at most 12 %)";
  }
}

TEST(BurkettPublished, LoweringsIncreaseAndThePredictedOptimumIsTheModelsFastestRow) {
  for (const auto& p : publishedParticipants()) {
    for (std::size_t i = 1; i < p.table4.size(); ++i)
      EXPECT_GT(p.table4[i].lowering, p.table4[i - 1].lowering) << p.name;
    const auto fastest = std::min_element(p.table4.begin(), p.table4.end(),
                                          [](const auto& a, const auto& b) { return a.model < b.model; });
    EXPECT_EQ(fastest->lowering, p.predictedBestLowering) << p.name;
    for (const auto& row : p.table4) {
      EXPECT_GT(row.measuredProsthetic, 0.25) << p.name << " " << row.lowering << ": a swing time in s";
      EXPECT_LT(row.measuredProsthetic, 0.6) << p.name << " " << row.lowering;
      EXPECT_GT(row.measuredAnatomical, 0.25) << p.name << " " << row.lowering;
      EXPECT_LT(row.measuredAnatomical, 0.6) << p.name << " " << row.lowering;
    }
  }
}

}  // namespace
}  // namespace swingsim
