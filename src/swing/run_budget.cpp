#include "swing/run_budget.h"

namespace swingsim {

RunBudget::RunBudget(const SwingOptions& options)
    : maxRealizations_(options.maxRealizations),
      maxWallSeconds_(options.maxWallSeconds),
      start_(std::chrono::steady_clock::now()) {}

RunBudget::Spent RunBudget::calcSpent(long realizations) const {
  if (realizations > maxRealizations_) return Spent::kRealizations;
  if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count() > maxWallSeconds_)
    return Spent::kWallClock;
  return Spent::kNone;
}

}  // namespace swingsim
