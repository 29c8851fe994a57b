#pragma once
// A measured swing time of one participant at one knee-axis lowering: one row of a
// sweep-measurement CSV (participant,lowering_m,swing_time_s[,sd_s,n]; docs/formats.md),
// the measurement the sweep plant of `swingsim diagnose` compares the sweep with.
#include <cmath>
#include <limits>
#include <string>

namespace swingsim {

struct MeasuredSwingTime {
  std::string participant;  ///< the `name` in a participant file of the study
  double lowering = 0;      ///< m below the standard knee-axis location
  double swingTime = 0;     ///< s, the mean of `trials` swings
  /// s, trial-to-trial standard deviation of one swing; NaN when the file has none.
  double sd = std::numeric_limits<double>::quiet_NaN();
  int trials = 1;  ///< swings averaged into swingTime
  int line = 0;    ///< line in its file, for messages
  /// s, the standard error of the mean: sd / sqrt(trials) (NaN without sd).
  double calcStandardError() const { return sd / std::sqrt(static_cast<double>(trials)); }
};

}  // namespace swingsim
