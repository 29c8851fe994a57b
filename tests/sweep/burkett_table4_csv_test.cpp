// The shipped Table 4 measurement (studies/data/burkett2004-table4.csv, the sweep plant's
// input) is the copy compiled into sweep/burkett_published: same participants, lowerings and
// measured prosthetic swing times; sd_s is Table 3's trial-to-trial SD and n = 5 trials.
#include <gtest/gtest.h>

#include "io/sweep_times_csv.h"
#include "sweep/burkett_published.h"

namespace swingsim {
namespace {

TEST(BurkettTable4Csv, EqualsTheCompiledTable) {
  const auto rows = readSweepTimesCsv(std::string(SWINGSIM_SOURCE_DIR) + "/studies/data/burkett2004-table4.csv");
  std::size_t expected = 0;
  for (const auto& p : publishedParticipants()) expected += p.table4.size();
  ASSERT_EQ(rows.size(), expected);
  for (const auto& r : rows) {
    const PublishedParticipant* p = findPublished(r.participant);
    ASSERT_NE(p, nullptr) << r.participant;
    bool found = false;
    for (const auto& t : p->table4) {
      if (std::abs(t.lowering - r.lowering) > 1e-12) continue;
      found = true;
      EXPECT_DOUBLE_EQ(r.swingTime, t.measuredProsthetic) << r.participant << " at " << r.lowering;
    }
    EXPECT_TRUE(found) << r.participant << " at " << r.lowering << " m is not in Table 4";
    EXPECT_DOUBLE_EQ(r.sd, p->table3MeasuredSd) << r.participant;
    EXPECT_EQ(r.trials, 5);
  }
}

}  // namespace
}  // namespace swingsim
