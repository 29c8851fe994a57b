#pragma once
// The cost of every start of the switch fit's multi-start grid (calcSwitchGridCosts in
// identify/cylinder_fit.h), with the switch values grid points share computed once.
#include <future>
#include <vector>

#include "identify/cylinder_regression.h"

namespace swingsim {

/// A thread where one can start, else the work runs in the caller at get() (libstdc++ falls
/// back to deferred when std::thread throws resource_unavailable_try_again).
constexpr std::launch kAsyncOrHere = std::launch::async | std::launch::deferred;

/// The squared norm of the projected residual (N^2) at each grid point, in grid order, on
/// `threads` (1 or 2) threads.
std::vector<double> calcGridCosts(const MauchCylinderParams& model, const TrainingSet& set,
                                  const std::vector<MauchSwitchParams>& grid, int threads);

}  // namespace swingsim
