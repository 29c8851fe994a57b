#pragma once
// A swing record's moments held to what a leg can produce: the CSV and motion readers hold
// every moment to 2000 N m (kJointMomentRange), so a swing's knee moment of some 10 N m
// written in N mm (10,000) is refused, but one of 1 N m (1000 N mm) passed as 1000 N m.
#include <string>

#include "model/swing_record.h"

namespace swingsim {

/// Largest |joint moment| per kg of body mass a record may hold, N m/kg: above the peak knee
/// and hip moments of running (about 2-3 N m/kg in stance; a swing's stay below 0.5 N m/kg,
/// Winter 2009 Biomechanics and Motor Control of Human Movement, ch. 5).
constexpr double kMaxJointMomentPerKg = 4;

/// InputError if the peak |knee moment| (from `kneeMomentPath`) or |hip moment| (from
/// `hipMomentPath`) of `r` is above kMaxJointMomentPerKg x `bodyMass`: "PATH: knee_moment:
/// peak |moment| ... looks like N mm ...". A moment column that is empty is not checked.
void checkMomentUnits(const SwingRecord& r, double bodyMass, const std::string& kneeMomentPath,
                      const std::string& hipMomentPath);

}  // namespace swingsim
