// The budgets of one swing (swing/run_budget.h) as a unit; their messages through a whole
// swing are in tests/swing/failing_runs_test.cpp.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "swing/run_budget.h"

namespace swingsim {
namespace {

TEST(RunBudget, RealizationsPastTheBudgetAreSpentAtTheBudgetNot) {
  SwingOptions options;
  options.maxRealizations = 100;
  const RunBudget budget(options);
  EXPECT_EQ(budget.calcSpent(100), RunBudget::Spent::kNone);
  EXPECT_EQ(budget.calcSpent(101), RunBudget::Spent::kRealizations);
}

TEST(RunBudget, WallClockCountsFromConstructionAndRealizationsAreNamedFirst) {
  SwingOptions options;
  options.maxRealizations = 100;
  options.maxWallSeconds = 0.001;
  const RunBudget budget(options);
  std::this_thread::sleep_for(std::chrono::milliseconds(5));  // past the 1 ms budget
  EXPECT_EQ(budget.calcSpent(0), RunBudget::Spent::kWallClock);
  EXPECT_EQ(budget.calcSpent(101), RunBudget::Spent::kRealizations);
  SwingOptions generous;
  EXPECT_EQ(RunBudget(generous).calcSpent(0), RunBudget::Spent::kNone);
}

}  // namespace
}  // namespace swingsim
