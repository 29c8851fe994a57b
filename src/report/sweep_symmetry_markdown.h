#pragma once
// The sweep report's sections on symmetry with the sound limb (sweep/sweep_symmetry.h):
// the symmetry lowering beside the fastest per participant, and Burkett 2004 Table 4's
// best-symmetry lowerings (`*`) beside this model's.
#include <string>
#include <vector>

#include "sweep/burkett_published.h"
#include "sweep/sweep.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim {

/// Index of the Table 4 row of `pub` whose time in `times` (s, one per row, NaN: none) is
/// closest to that row's measured anatomical swing time; -1 if no time is finite. With
/// times = the measured prosthetic column this is Burkett's `*`.
int calcTable4SymmetryRow(const PublishedParticipant& pub, const std::vector<double>& times);

/// "## Symmetry with the sound limb": per participant with a sound-limb swing time, the
/// symmetry lowering beside the fastest (with `uncertainty`, its 5-95 % interval); "" if no
/// participant has one.
std::string formatSymmetrySection(const SweepResults& results, const UncertaintyResults* uncertainty);

/// Table 4's `*` beside this model's symmetry lowering, for Burkett's participants with a
/// sound-limb swing time, and what differs; "" if there are none.
std::string formatTable4SymmetrySection(const SweepResults& results);

}  // namespace swingsim
