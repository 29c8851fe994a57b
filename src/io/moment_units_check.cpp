#include "io/moment_units_check.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"
#include "core/output_files.h"

namespace swingsim {
namespace {

void checkPeak(const std::vector<double>& moment, double bodyMass, const std::string& path, const std::string& key) {
  if (moment.empty() || !(bodyMass > 0)) return;
  double peak = 0;
  for (double m : moment) peak = std::max(peak, std::fabs(m));
  const double limit = kMaxJointMomentPerKg * bodyMass;
  if (peak <= limit) return;
  throw InputError(path + ": " + key + ": expected a peak |moment| of at most " + formatNumber(kMaxJointMomentPerKg) +
                   " N m/kg x " + formatNumber(bodyMass) + " kg = " + formatNumber(limit) +
                   " N m (ten times a walking swing's peak); it looks like N mm: divide by 1000 (got " +
                   formatNumber(peak) + " N m)");
}

}  // namespace

void checkMomentUnits(const SwingRecord& r, double bodyMass, const std::string& kneeMomentPath,
                      const std::string& hipMomentPath) {
  checkPeak(r.kneeMoment, bodyMass, kneeMomentPath, "knee_moment");
  checkPeak(r.hipMoment, bodyMass, hipMomentPath, "hip_moment");
}

}  // namespace swingsim
