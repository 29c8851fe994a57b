#include "identify/switch_search.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>

#include "identify/projected_residual.h"
#include "identify/switch_grid_costs.h"
#include "numerics/bounded_least_squares.h"

namespace swingsim {

namespace {

// Best multi-start points polished by Ceres: the switch-width surface has flat regions (a
// width far below the data's resolution makes a step) where a polish started there stalls.
constexpr std::size_t kPolishedStarts = 3;

// Geometric points spread over [lo, hi]: lo (hi/lo)^((i + 1/2) / n).
std::vector<double> spreadLog(const double range[2], int n) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(range[0] * std::pow(range[1] / range[0], (i + 0.5) / n));
  return v;
}

// Polishes the best starts by Ceres over the switch constants (linear part projected out),
// each on its own thread; returns the best switch constants found. `done`: starts already
// evaluated, for the progress callback.
MauchSwitchParams polishSwitchStarts(const MauchCylinderParams& model, const TrainingSet& set,
                                     const std::vector<MauchSwitchParams>& sortedStarts,
                                     const CylinderFitOptions& options, int done, CylinderFit& out) {
  const bool latch = options.fitLatchRate;
  BoundedFitSettings settings;
  // A polish near a known fit (no multi-start) needs a few steps; its budget says so.
  settings.maxIterations = options.multiStart ? 50 : 12;
  settings.maxSeconds = 30.0;
  settings.functionTolerance = options.multiStart ? 1e-6 : 1e-5;
  settings.computeCovariance = false;
  // The 2-phase model on 4-phase data has a curved, flat valley: monotone steps crept along
  // it to the iteration budget from one of the three starts.
  settings.nonmonotonicSteps = true;
  auto polish = [&](const MauchSwitchParams& from) {
    ProjectedResidual projected(model, set);
    ResidualJacobianFunction f = [&](const Eigen::VectorXd& x, Eigen::MatrixXd* jacobian) -> Eigen::VectorXd {
      const MauchSwitchParams switches = switchesFrom(model.switches, x.data(), latch);
      return jacobian ? projected.calc(switches, static_cast<int>(x.size()), *jacobian) : projected.calc(switches);
    };
    return solveBoundedLeastSquares(f, switchParameters(from, options.ranges, latch), settings);
  };
  const std::size_t polished = std::min<std::size_t>(kPolishedStarts + options.extraStarts.size(), sortedStarts.size());
  std::vector<std::future<BoundedFitResult>> runs;
  for (std::size_t s = 1; s < polished; ++s)
    runs.push_back(std::async(kAsyncOrHere, polish, sortedStarts[s]));  // see kAsyncOrHere
  std::vector<BoundedFitResult> results;
  results.push_back(polish(sortedStarts[0]));
  for (auto& r : runs) results.push_back(r.get());
  double bestCost = std::numeric_limits<double>::infinity();
  MauchSwitchParams bestSwitches = model.switches;
  for (std::size_t s = 0; s < results.size(); ++s) {
    const BoundedFitResult& r = results[s];
    if (options.multiStart && !r.converged && r.iterations >= settings.maxIterations)
      out.warnings.push_back("the switch-constant fit stopped at its budget of " +
                             std::to_string(settings.maxIterations) + " iterations without converging");
    if (r.cost < bestCost) {
      bestCost = r.cost;
      bestSwitches = switchesFrom(model.switches, r.x.data(), latch);
    }
    if (options.progress) options.progress(done + static_cast<int>(s) + 1, done + static_cast<int>(polished));
  }
  return bestSwitches;
}

}  // namespace

std::vector<MauchSwitchParams> makeSwitchStarts(const MauchCylinderParams& model, const std::vector<BenchData>& train,
                                                const CylinderFitOptions& options) {
  std::vector<double> positions;
  for (const auto& d : train) positions.insert(positions.end(), d.position.begin(), d.position.end());
  std::sort(positions.begin(), positions.end());
  const SwitchConstantRanges& R = options.ranges;
  std::vector<double> xhyStarts;
  for (double q : {0.02, 0.05, 0.1, 0.2, 0.3}) {
    const double v = positions[static_cast<std::size_t>(q * static_cast<double>(positions.size() - 1))];
    xhyStarts.push_back(std::clamp(v, R.hyperextension[0], R.hyperextension[1]));
  }
  std::vector<double> vws = spreadLog(R.velocityWidth, 3), pws = spreadLog(R.positionWidth, 4);
  std::vector<double> ks =
      options.fitLatchRate ? spreadLog(R.latchRate, 2) : std::vector<double>{model.switches.latchRate};
  if (!options.multiStart) {
    vws.assign(1, model.switches.velocityWidth);
    pws.assign(1, model.switches.positionWidth);
    xhyStarts.assign(1, model.switches.hyperextensionPosition);
    ks.assign(1, model.switches.latchRate);
  }
  std::vector<MauchSwitchParams> grid;
  for (double vw : vws)
    for (double pw : pws)
      for (double xh : xhyStarts)
        for (double k : ks) grid.push_back({vw, pw, xh, k});
  return grid;
}

MauchSwitchParams fitSwitchConstants(const MauchCylinderParams& model, const std::vector<BenchData>& train,
                                     const CylinderFitOptions& options, CylinderFit& out) {
  struct Start {
    double cost;
    MauchSwitchParams switches;
  };
  const std::vector<MauchSwitchParams> grid = makeSwitchStarts(model, train, options);
  const int total = static_cast<int>(grid.size());
  const TrainingSet set(model, train);
  const std::vector<double> costs = calcGridCosts(model, set, grid, grid.size() > 1 ? 2 : 1);
  std::vector<Start> starts;
  for (std::size_t i = 0; i < grid.size(); ++i) starts.push_back({costs[i], grid[i]});
  if (options.progress) options.progress(total, total + static_cast<int>(kPolishedStarts));
  std::stable_sort(starts.begin(), starts.end(), [](const Start& a, const Start& b) { return a.cost < b.cost; });
  out.switchStarts = static_cast<int>(starts.size());
  // The extra starts first: each is polished, then the grid's best.
  std::vector<MauchSwitchParams> sorted = options.multiStart ? options.extraStarts : std::vector<MauchSwitchParams>{};
  for (const auto& s : starts) sorted.push_back(s.switches);
  return polishSwitchStarts(model, set, sorted, options, total, out);
}

}  // namespace swingsim
