#pragma once
// Tuned settings a prosthetist can set (docs/tuning.md, "Settings at the knob's resolution").
// The polish ends at a continuous optimum, often on a hard limit's edge: 89.99 deg of peak
// flexion holds only to many decimals, and a knob set to the nearest millimetre or degree can
// break the limit. So the result is moved onto each knob's grid (multiples of its resolution)
// and checked on every neighbour: the corners of the grid cell around it (each knob rounded
// down and up, all combinations) must all meet every hard limit and lie on one continuous
// piece of the swing time (no jump between them: swing_time_jumps.h). Where the cell around
// the optimum fails, the search steps cell by cell (one grid step in any combination of knobs)
// toward the cell closest to holding, then from the first that holds to neighbouring cells
// that hold at a lower cost; the best corner of the last is the result. Where none holds
// within kMaxCellMoves steps, the result says it cannot. Each knob's tolerance band then says how far it
// can move alone, in steps of its resolution, with every hard limit met and the swing time
// within a window.
#include <optional>
#include <string>
#include <vector>

#include "sweep/knee_tuning.h"

namespace swingsim {

/// The resolution a knob key implies by its unit suffix, or nullopt where the unit cannot be
/// told (the study must then state it): _m 1 mm, _deg 1 deg, _Nm_per_rad 1 N m/rad,
/// _Nm_s_per_rad 0.1 N m s/rad, _kg 0.01 kg, _scale and _factor 0.01; any other rate
/// (_per_m, _per_s, _per_rad) and every other unit: none.
std::optional<double> findDefaultKnobResolution(const std::string& key);

/// The most knobs whose neighbouring cells are searched when the cell around the optimum fails
/// (up to 4^n swings a step for n knobs: 4096 at 6).
constexpr int kMaxKnobsForCellSearch = 6;
/// The most steps of the grid the search moves from the cell around the optimum.
constexpr int kMaxCellMoves = 12;
/// The most steps of its resolution a tolerance band walks each way from the result.
constexpr int kMaxBandSteps = 40;

/// `value` on the knob's grid: the nearest multiple of its resolution inside [lower, upper]
/// (unchanged without a resolution).
double roundToKnobGrid(const TuningKnob& knob, double value);

/// Moves `continuous` onto the knobs' grids and checks it (see the file comment). `window` (s)
/// is the swing-time window of the tolerance bands. Runs its swings on `jobs` threads.
ResolutionCheck checkTuningResolution(const std::vector<TuningKnob>& knobs, const std::vector<TuningTarget>& targets,
                                      const TuningEvaluator& evaluate, const TuningPoint& continuous, double window,
                                      int jobs, const volatile bool* stopFlag = nullptr);

}  // namespace swingsim
