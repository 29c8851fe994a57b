#pragma once
// The cylinder fit's multi-start search for the switch constants (velocity width, position
// width, xhy and, with fitLatchRate, the latch rate): a grid of starts over their physical
// ranges, every start costed, the best ones polished by Ceres with the linear coefficients
// projected out (identify/projected_residual.h).
#include <vector>

#include "identify/cylinder_fit.h"
#include "identify/cylinder_regression.h"

namespace swingsim {

/// The multi-start grid: widths and latch rate spread over their physical ranges, xhy at low
/// quantiles of the training positions (hyperextension is where the piston is lowest); the
/// model's own switch constants alone without options.multiStart.
std::vector<MauchSwitchParams> makeSwitchStarts(const MauchCylinderParams& model, const std::vector<BenchData>& train,
                                                const CylinderFitOptions& options);

/// The switch constants: every start of the grid costed (on two threads, results in grid
/// order, so the fit is the same on any machine), options.extraStarts and the best grid
/// starts polished; the best polish wins. Sets out.switchStarts, adds a warning for a polish
/// stopped at its budget and reports progress through options.progress.
MauchSwitchParams fitSwitchConstants(const MauchCylinderParams& model, const std::vector<BenchData>& train,
                                     const CylinderFitOptions& options, CylinderFit& out);

}  // namespace swingsim
