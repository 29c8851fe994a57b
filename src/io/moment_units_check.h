#pragma once
// A swing record's moments held to what a leg can produce: the CSV and motion readers hold
// every moment to 2000 N m (kJointMomentRange), so a swing's knee moment of some 10 N m
// written in N mm (10,000) is refused, but one of 1 N m (1000 N mm) passed as 1000 N m.
#include <string>

#include "model/swing_record.h"

namespace swingsim {

/// Largest |joint moment| per kg of body mass a record may hold, N m/kg. An assumption with
/// a wide margin, not a published limit: Winter's walking swing peaks at about 1 N m/kg
/// (studies/data/winter-natural-cadence.csv: hip 54 N m, knee 38 N m, for the 56.7 kg
/// assumed in docs/winter.md); running and sprinting raise swing moments several-fold, and
/// 10 N m/kg leaves room for them, while a moment written in N mm is 1000x too large.
constexpr double kMaxJointMomentPerKg = 10;

/// InputError if the peak |knee moment| (from `kneeMomentPath`) or |hip moment| (from
/// `hipMomentPath`) of `r` is above kMaxJointMomentPerKg x `bodyMass`: "PATH: knee_moment:
/// peak |moment| ... looks like N mm ...". A moment column that is empty is not checked.
void checkMomentUnits(const SwingRecord& r, double bodyMass, const std::string& kneeMomentPath,
                      const std::string& hipMomentPath);

}  // namespace swingsim
