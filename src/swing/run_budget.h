#pragma once
// The budgets of one swing (SwingOptions::maxRealizations, maxWallSeconds): a knee law far
// too stiff for an explicit integrator at the asked accuracy would otherwise run for hours.
#include <chrono>

#include "swing/swing_simulation.h"

namespace swingsim {

class RunBudget {
 public:
  enum class Spent { kNone, kRealizations, kWallClock };
  /// Starts the wall clock.
  explicit RunBudget(const SwingOptions& options);
  /// Which budget `realizations` (so far) and the wall-clock time since construction have
  /// spent, the realizations first; kNone while within both.
  Spent calcSpent(long realizations) const;
  long getMaxRealizations() const { return maxRealizations_; }
  double getMaxWallSeconds() const { return maxWallSeconds_; }

 private:
  long maxRealizations_;
  double maxWallSeconds_;  // s
  std::chrono::steady_clock::time_point start_;
};

}  // namespace swingsim
